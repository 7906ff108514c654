// libFuzzer harness: a whole scene text through the reading and validation of `carom check`
// (parse_scene, then check_like_carom), writing nothing. Seeds: scenarios/scenes/*.toml.
#include <cstddef>
#include <cstdint>
#include <string>

#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  carom::fuzz::expect_scene_errors_only(
      [&] { carom::fuzz::check_like_carom(carom::parse_scene(text, "fuzz.toml")); });
  return 0;
}
