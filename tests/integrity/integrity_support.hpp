#pragma once
// Shared by the integrity tests: small scenes of every method that run in about a second, and
// damage done to a checkpoint the way a flipped bit or a wrong writer would do it.
#include <string>
#include <vector>

#include "core/hdf5.hpp"
#include "scenarios/run/file_checksum.hpp"
#include "tests/cli_support.hpp"

namespace carom_integrity_test {

using namespace carom_cli_test;

/// A small periodic gas of two species (with the elastic constants soft spheres need).
inline const std::string kGas =
    "[domain]\nmin = [0, 0, 0]\nmax = [8.0, 8.0, 8.0]\nperiodic = [\"x\", \"y\", \"z\"]\n"
    "[[species]]\nname = \"a\"\ndiameter = 1.0\ndensity = 1.909859317102744\nfill = { volume_fraction = 0.25 }\n"
    "young_modulus = 1e6\npoisson_ratio = 0.3\n"
    "[[species]]\nname = \"b\"\ndiameter = 0.6\ndensity = 1.909859317102744\nfill = { count = 100 }\n"
    "young_modulus = 1e6\npoisson_ratio = 0.3\n"
    "[collisions]\ndefault = { e = 0.95, mu = 0.2, beta0 = 0.3 }\n"
    "[initial]\ntemperature = 1.0\n"
    "[time]\nend = 1.0\n"
    "[output]\nsnapshot_every = 0.5\nsample_every = 0.1\ncheckpoint_every = 0.5\n";

/// The command-line fixture, whose carom() also takes environment settings ("NAME=value ...").
class IntegrityCli : public carom_cli_test::Cli {
 protected:
  using carom_cli_test::Cli::carom;
  int carom(const std::string& args, const std::string& environment) {
    const std::string log = (dir_ / "log.txt").string();
    const std::string command = "cd '" + dir_.string() + "' && " + environment + " timeout -k 5 60 '" + kCarom + "' " +
                                args + " > '" + log + "' 2>&1";
    const int status = std::system(command.c_str());
    out_ = read(log);
    fs::remove(log);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
};

inline const std::vector<std::string> kMethods = {"event_driven", "soft_sphere", "monte_carlo"};

/// Replaces value `index` (flat, row-major) of dataset `path` of an HDF5 file by `value`, keeping
/// its type T, and, when `reseal`, writes a new checksum: a damage the checksum cannot see,
/// as a writer with a bug would leave it, so that the value checks are tested on their own.
template <class T>
void damage(const std::string& file_path, const std::string& path, std::size_t index, T value, bool reseal = true) {
  const carom::h5::File file = carom::h5::File::open(file_path, true);
  const std::size_t slash = path.find_last_of('/');
  const carom::h5::Group group = file.open_group(path.substr(0, slash));
  const std::string name = path.substr(slash + 1);
  const std::vector<hsize_t> shape = group.open_dataset(name).shape();
  std::vector<T> values = group.read<T>(name);
  values.at(index) = value;
  group.remove(name);
  group.write(name, values, shape);
  if (reseal) carom::seal_file(file);
}

/// The first index of an event list whose kind is `kind` (1: a pair), or -1.
inline long first_of_kind(const std::string& file_path, const std::string& group, int kind) {
  const carom::h5::File file = carom::h5::File::open(file_path, false);
  const std::vector<std::uint8_t> kinds = file.open_group(group).read<std::uint8_t>("kind");
  for (std::size_t i = 0; i < kinds.size(); ++i)
    if (kinds[i] == kind) return static_cast<long>(i);
  return -1;
}

}  // namespace carom_integrity_test
