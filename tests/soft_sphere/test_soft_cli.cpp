// Soft spheres through the `carom` command line: a run stopped at its end time and resumed, and
// one stopped by SIGINT and resumed, end bit for bit in the state of the uninterrupted run.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "core/hdf5.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kCarom = CAROM_BINARY;
const std::string kScenes = CAROM_SCENES_DIR;

int run(const fs::path& dir, const std::string& args) {
  const std::string command = "cd '" + dir.string() + "' && timeout -k 5 120 '" + kCarom + "' " + args +
                              " > log.txt 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The checkpoint's particle arrays and counters, as raw bytes per dataset.
std::string state_bytes(const fs::path& checkpoint) {
  const carom::h5::File f = carom::h5::File::open(checkpoint.string(), false);
  const carom::h5::Group state = f.open_group("state");
  std::ostringstream out;
  for (const char* name : {"position", "velocity", "spin", "contact_force"}) {
    const auto v = state.open_group("particles").read<double>(name);
    out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(double)));
  }
  const auto pairs = state.open_group("statistics").read<std::uint64_t>("pair_collisions");
  out.write(reinterpret_cast<const char*>(pairs.data()), static_cast<std::streamsize>(pairs.size() * 8));
  out << state.attribute<double>("time") << " " << state.attribute<std::uint64_t>("steps");
  return out.str();
}

class SoftCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("carom_soft_cli_" + std::to_string(getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

const std::string kColumn = " --quiet --set species.bead.fill.count=150 --set output.checkpoint_every=0";

TEST_F(SoftCli, ResumeIsBitForBit) {
  const std::string scene = "'" + kScenes + "/soft_column.toml'" + kColumn;
  ASSERT_EQ(run(dir_, "run " + scene + " --out whole --set time.end=0.1"), 0);
  ASSERT_EQ(run(dir_, "run " + scene + " --out split --set time.end=0.05"), 0);
  ASSERT_EQ(run(dir_, "resume split --end 0.1 --quiet"), 0);
  EXPECT_EQ(state_bytes(dir_ / "whole" / "checkpoint.h5"), state_bytes(dir_ / "split" / "checkpoint.h5"));
}

// SIGINT mid-run: exit 130 with a checkpoint; the resumed run ends where the uninterrupted one
// does, bit for bit (the signal stops the loop at a step boundary of its own choosing).
TEST_F(SoftCli, InterruptedRunResumesBitForBit) {
  const std::string scene = "'" + kScenes + "/soft_column.toml'" + kColumn + " --set time.end=0.3";
  ASSERT_EQ(run(dir_, "run " + scene + " --out whole"), 0);
  const std::string command = "cd '" + dir_.string() + "' && exec '" + kCarom + "' run " + scene +
                              " --out cut > cut.txt 2>&1";
  const pid_t child = fork();
  if (child == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  // Signal once the run's loop is going (its run file exists, then half a second more).
  for (int k = 0; k < 600 && !fs::exists(dir_ / "cut" / "run.h5"); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  kill(child, SIGINT);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  if (WEXITSTATUS(status) == 0) GTEST_SKIP() << "the run finished before the signal (a fast machine)";
  ASSERT_EQ(WEXITSTATUS(status), 130);
  ASSERT_TRUE(fs::exists(dir_ / "cut" / "checkpoint.h5"));
  ASSERT_EQ(run(dir_, "resume cut --quiet"), 0);
  EXPECT_EQ(state_bytes(dir_ / "whole" / "checkpoint.h5"), state_bytes(dir_ / "cut" / "checkpoint.h5"));
}

}  // namespace
