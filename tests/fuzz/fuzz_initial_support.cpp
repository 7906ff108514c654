#include "tests/fuzz/fuzz_initial_support.hpp"

#include <hdf5.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "scenarios/run/output_estimate.hpp"
#include "scenarios/run/run.hpp"
#include "scenarios/scene/scene.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace carom::fuzz {

namespace fs = std::filesystem;

std::string make_work_dir(const std::string& prefix) {
  std::string folder = (fs::temp_directory_path() / (prefix + "_XXXXXX")).string();
  if (mkdtemp(folder.data()) == nullptr) {
    std::perror("carom fuzz: mkdtemp");
    std::abort();
  }
  static std::vector<std::string> remove_at_exit;
  if (remove_at_exit.empty())
    std::atexit([] {
      std::error_code error;
      for (const std::string& f : remove_at_exit) fs::remove_all(f, error);
    });
  remove_at_exit.push_back(folder);
  return folder;
}

namespace {

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

herr_t collect_attribute(hid_t, const char* name, const H5A_info_t*, void* data) {
  auto* where = static_cast<std::pair<SeedFile*, std::string>*>(data);
  where->first->attributes.push_back({where->second, name});
  return 0;
}

void collect_attributes(hid_t object, const std::string& path, SeedFile& seed) {
  std::pair<SeedFile*, std::string> where{&seed, path};
  H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_attribute, &where);
}

herr_t collect_object(hid_t group, const char* name, const H5L_info_t*, void* data) {
  auto* seed = static_cast<SeedFile*>(data);
  const hid_t object = H5Oopen(group, name, H5P_DEFAULT);
  if (object < 0) return 0;
  const std::string path = std::string("/") + name;
  if (H5Iget_type(object) == H5I_DATASET) seed->datasets.push_back(path);
  collect_attributes(object, path, *seed);
  H5Oclose(object);
  return 0;
}

InitialFileSeeds make_seeds() {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // damaged files: HDF5's errors are expected
  InitialFileSeeds seeds;
  const std::string folder = make_work_dir("carom_fuzz");
  seeds.work_dir = folder;
  const fs::path scene_path = fs::path(CAROM_FUZZ_DIR) / "tiny_run.toml";
  RunOptions options;
  options.out_dir = (fs::path(folder) / "seed_run").string();
  options.quiet = true;
  if (run_scene(load_scene(scene_path.string()), options) != kExitOk) {
    std::fprintf(stderr, "carom fuzz: the seed run of %s failed\n", scene_path.c_str());
    std::abort();
  }
  seeds.run = load_seed_file((fs::path(options.out_dir) / "run.h5").string());
  seeds.checkpoint = load_seed_file((fs::path(options.out_dir) / "checkpoint.h5").string());
  return seeds;
}

/// tiny_run.toml's box and species, without fills: every particle comes from the file.
const char* const kReaderScene = R"(
[domain]
min = [0.0, 0.0, 0.0]
max = [0.01, 0.01, 0.01]
gravity = [0.0, 0.0, -9.81]

[[species]]
name = "large"
diameter = 2.0e-3
density = 2500.0

[[species]]
name = "small"
diameter = 1.0e-3
density = 2500.0

[collisions]
default = { e = 0.9, mu = 0.2, beta0 = 0.3 }
collapse = { model = "tc", contact_time = 1.0e-5 }

[time]
end = 0.02
)";

}  // namespace

SeedFile load_seed_file(const std::string& path) {
  SeedFile seed;
  const std::string bytes = read_text(fs::path(path));
  seed.bytes.assign(bytes.begin(), bytes.end());
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) {
    std::fprintf(stderr, "carom fuzz: cannot open the seed %s\n", path.c_str());
    std::abort();
  }
  collect_attributes(file, "/", seed);
  H5Lvisit(file, H5_INDEX_NAME, H5_ITER_INC, collect_object, &seed);
  H5Fclose(file);
  return seed;
}

const InitialFileSeeds& initial_file_seeds() {
  static const InitialFileSeeds seeds = make_seeds();
  return seeds;
}

void read_like_carom(const std::string& path, std::int64_t snapshot, bool snapshot_given) {
  static const Scene reader = parse_scene(kReaderScene, "fuzz_reader.toml");
  expect_scene_errors_only([&] {
    Scene scene = reader;
    scene.from_file = InitialFile{path, "input.h5", snapshot, snapshot_given, "fuzz_reader.toml:1"};
    const std::size_t particles = planned_particle_count(scene);
    (void)particles;
    build_initial_state(scene, nullptr);
    try {
      (void)make_method(scene.system, scene.method);
    } catch (const std::invalid_argument&) {
      return;  // main.cpp turns these into SceneError
    }
  });
}

}  // namespace carom::fuzz
