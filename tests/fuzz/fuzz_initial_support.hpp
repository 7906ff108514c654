#pragma once
/// Shared by the initial-file harnesses: the valid files they start from, and the reading of a
/// damaged file the way `carom check` reads `[initial] from_file`.
#include <cstdint>
#include <string>
#include <vector>

namespace carom::fuzz {

/// An attribute of an object in an HDF5 file.
struct AttributeName {
  std::string object;  ///< Object path, "/" for the root.
  std::string name;
};

/// A valid carom file, its bytes and what it holds.
struct SeedFile {
  std::vector<std::uint8_t> bytes;
  std::vector<std::string> datasets;      ///< Every dataset's path.
  std::vector<AttributeName> attributes;  ///< Every attribute (of the root, groups, datasets).
};

/// Reads a valid carom file: its bytes and every dataset and attribute it holds (aborts when it
/// cannot be opened).
SeedFile load_seed_file(const std::string& path);

/// The run file and checkpoint of tests/fuzz/tiny_run.toml, and this process's scratch folder.
struct InitialFileSeeds {
  std::string work_dir;  ///< A fresh folder under the temp dir, removed at exit.
  SeedFile run;          ///< run.h5.
  SeedFile checkpoint;   ///< checkpoint.h5.
};

/// A new scratch folder under the system's temporary folder, named `prefix` and a random
/// suffix, removed when the process exits.
std::string make_work_dir(const std::string& prefix);

/// Runs tiny_run.toml into a scratch folder once (first call) and returns its files.
const InitialFileSeeds& initial_file_seeds();

/// Reads `path` as `[initial] from_file` of a scene with tiny_run.toml's species and no fills,
/// then places, starts the method and describes the scene as `carom check` does. A SceneError
/// is the expected answer to a damaged file; anything else aborts (expect_scene_errors_only).
void read_like_carom(const std::string& path, std::int64_t snapshot, bool snapshot_given);

}  // namespace carom::fuzz
