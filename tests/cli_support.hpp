#pragma once
// The `carom` binary run as a user runs it, for the command-line tests (test_cli.cpp,
// test_cli_inputs.cpp): a fresh directory per test, the exit code and the output of a command.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/hdf5.hpp"

namespace carom_cli_test {

namespace fs = std::filesystem;

inline const std::string kCarom = CAROM_BINARY;
inline const std::string kScenes = CAROM_SCENES_DIR;

/// The whole text of a file ("" when it cannot be read).
inline std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A fresh directory per test, removed afterwards.
class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("carom_cli_" + std::to_string(getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// Runs `carom ARGS` in the test directory; returns the exit code; output in out_.
  int carom(const std::string& args) {
    const std::string log = (dir_ / "log.txt").string();
    // timeout: a hang fails the test (exit 124/137) instead of stalling the suite.
    const std::string command = "cd '" + dir_.string() + "' && timeout -k 5 60 '" + kCarom + "' " + args + " > '" + log + "' 2>&1";
    const int status = std::system(command.c_str());
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    out_ = text.str();
    fs::remove(log);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  /// Writes a scene file into the test directory.
  std::string scene(const std::string& name, const std::string& text) {
    std::ofstream((dir_ / name).string()) << text;
    return name;
  }

  fs::path dir_;
  std::string out_;
};

/// A small elastic gas that runs in well under a second.
inline const std::string kSmallGas =
    "[domain]\nmin = [0, 0, 0]\nmax = [8.0, 8.0, 8.0]\nperiodic = [\"x\", \"y\", \"z\"]\n"
    "[[species]]\nname = \"a\"\ndiameter = 1.0\ndensity = 1.909859317102744\nfill = { volume_fraction = 0.25 }\n"
    "[[species]]\nname = \"b\"\ndiameter = 0.6\ndensity = 1.909859317102744\nfill = { count = 100 }\n"
    "[collisions]\ndefault = { e = 0.95, mu = 0.2, beta0 = 0.3 }\n"
    "[initial]\ntemperature = 1.0\n"
    "[time]\nend = 4.0\n"
    "[output]\nsnapshot_every = 0.5\nsample_every = 0.1\n";

/// The time series `name` of a run file (its group "timeseries").
inline std::vector<double> timeseries(const fs::path& run_file, const std::string& name) {
  const carom::h5::File file = carom::h5::File::open(run_file.string(), false);
  return file.open_group("timeseries").read<double>(name);
}

}  // namespace carom_cli_test
