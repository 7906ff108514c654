// libFuzzer harness: `--set key=value` (and `--seed N`) applied to a valid shipped scene, then
// the reading and validation of `carom check` (check_like_carom), writing nothing.
//
// Input: the first byte picks the base scene (modulo the number of shipped scenes, in name
// order); the rest is one assignment per line, as given after --set, at most 16. A line
// "--seed TEXT" goes through parse_seed, as `carom run --seed TEXT` does.
// Seeds: make_corpus.py writes one input per key of every shipped scene.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "scenarios/scene/overrides.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

struct BaseScene {
  std::string file;  ///< Path, for messages.
  std::string text;
};

std::vector<BaseScene> load_base_scenes() {
  std::vector<BaseScene> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(CAROM_SCENES_DIR)) {
    const std::filesystem::path& path = entry.path();
    if (path.extension() != ".toml" || path.stem().string().find("sweep") != std::string::npos)
      continue;
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    scenes.push_back({path.string(), text.str()});
  }
  std::sort(scenes.begin(), scenes.end(),
            [](const auto& a, const auto& b) { return a.file < b.file; });
  return scenes;
}

const std::vector<BaseScene>& base_scenes() {
  static const std::vector<BaseScene> scenes = load_base_scenes();
  return scenes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::vector<BaseScene>& scenes = base_scenes();
  if (size == 0 || scenes.empty()) return 0;
  const BaseScene& base = scenes[data[0] % scenes.size()];
  std::vector<std::string> assignments;
  std::optional<std::string> seed_text;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
  for (std::string line; std::getline(lines, line) && assignments.size() < 16;) {
    if (line.rfind("--seed ", 0) == 0)
      seed_text = line.substr(7);
    else
      assignments.push_back(line);
  }
  carom::fuzz::expect_scene_errors_only([&] {
    std::optional<std::uint64_t> seed;
    if (seed_text) seed = carom::parse_seed(*seed_text);
    carom::fuzz::check_like_carom(carom::parse_scene(base.text, base.file, assignments, seed));
  });
  return 0;
}
