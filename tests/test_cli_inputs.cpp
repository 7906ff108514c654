// The `carom` command against what a new user and a hostile input try (issue 20): inputs that
// are the wrong kind of file, a negative seed, a signal while the bed settles before t = 0, an
// output that would fill the disk, --overwrite over an earlier run's figures, `carom info` as a
// summary, and report.md saying only what applies to the scene.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "cli_support.hpp"

namespace fs = std::filesystem;
using namespace carom;
using namespace carom_cli_test;

extern char** environ;

// SIGTERM while initial.settle_time runs (before t = 0) used to kill carom with no message
// (exit 143). Now: exit 130, a message that nothing was written, and no output directory.
TEST_F(Cli, SignalWhileSettlingExitsInterruptedAndWritesNothing) {
  // An elastic gas settling "for ever" (1e6 s is hours of wall time).
  const std::string gas = scene("gas.toml", kSmallGas);
  const std::string log = (dir_ / "stderr.txt").string();
  std::vector<std::string> args{kCarom, "run", (dir_ / gas).string(), "--out", (dir_ / "s").string(),
                                "--set", "collisions.default={ e = 1.0 }", "--set", "initial.settle_time=1e6"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, kCarom.c_str(), &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  const std::string message = read(log);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0) << "; "
                                 << message;
  EXPECT_EQ(WEXITSTATUS(status), 130) << message;
  EXPECT_NE(message.find("interrupted while settling ("), std::string::npos) << message;
  EXPECT_NE(message.find("initial.settle_time = 1e+06"), std::string::npos) << message;
  EXPECT_NE(message.find("nothing was written"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(dir_ / "s")) << "an interrupted settling must leave no output directory";
}
