// One run per output folder: while a run writes into a folder, a second `carom run`, a
// `carom run --overwrite` and a `carom resume` into it are refused (exit 2, "in use") and delete
// nothing; once the first process is gone (ended by a signal, or killed with SIGKILL, which
// leaves the lock file behind) the lock is stale and the folder is usable at once.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "tests/integrity/integrity_support.hpp"

namespace {

using namespace carom_integrity_test;

class OutputLockTest : public IntegrityCli {
 protected:
  /// Starts `carom ARGS...` in the test directory, in the background; returns its process id.
  pid_t start(const std::vector<std::string>& args) {
    const pid_t pid = fork();
    if (pid == 0) {
      if (chdir(dir_.c_str()) != 0) _exit(127);
      if (!freopen("background.log", "w", stdout) || !freopen("background.log", "a", stderr)) _exit(127);
      std::vector<char*> argv{const_cast<char*>(kCarom.c_str())};
      for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
      argv.push_back(nullptr);
      execv(kCarom.c_str(), argv.data());
      _exit(127);
    }
    return pid;
  }
  /// `carom run` of the gas made elastic, for far longer than the test (it is stopped by a signal).
  static std::vector<std::string> long_run(const std::string& out) {
    return {"run", "gas.toml", "--set", "time.end=1e6", "--set", "collisions.default={ e = 1.0 }", "--set",
            "output.snapshot_every=1e5", "--set", "output.sample_every=1e5", "--set", "output.checkpoint_every=1e5",
            "--out", out, "--quiet"};
  }
  /// Waits (at most 30 s) until `path` exists.
  bool wait_for(const fs::path& path) {
    for (int k = 0; k < 300; ++k) {
      if (fs::exists(path)) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return false;
  }
  /// Waits for process `pid` to end; returns its exit code (128 + signal when killed).
  static int wait_exit(pid_t pid) {
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
};

TEST_F(OutputLockTest, ASecondRunOverwriteOrResumeIntoAFolderInUseIsRefused) {
  scene("gas.toml", kGas);
  const pid_t first = start(long_run("busy"));
  ASSERT_TRUE(wait_for(dir_ / "busy" / "run.h5"));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));

  EXPECT_EQ(carom("run gas.toml --out busy --quiet"), 2) << out_;
  EXPECT_NE(out_.find("in use by another carom process"), std::string::npos) << out_;
  EXPECT_EQ(carom("run gas.toml --out busy --overwrite --quiet"), 2) << out_;
  EXPECT_NE(out_.find("in use by another carom process (process id " + std::to_string(first)), std::string::npos)
      << out_;
  EXPECT_TRUE(fs::exists(dir_ / "busy" / "run.h5")) << "--overwrite deleted the running run's file";
  EXPECT_EQ(carom("resume busy --quiet"), 2) << out_;
  EXPECT_NE(out_.find("in use"), std::string::npos) << out_;

  // SIGTERM: the first run writes its checkpoint and exits 130; the folder is free again.
  kill(first, SIGTERM);
  EXPECT_EQ(wait_exit(first), 130) << read(dir_ / "background.log");
  EXPECT_EQ(carom("run gas.toml --out busy --overwrite --quiet --set time.end=0.2"), 0) << out_;
}

TEST_F(OutputLockTest, ALockLeftByAKilledProcessIsStale) {
  scene("gas.toml", kGas);
  const pid_t first = start(long_run("killed"));
  ASSERT_TRUE(wait_for(dir_ / "killed" / "run.h5"));
  kill(first, SIGKILL);
  EXPECT_EQ(wait_exit(first), 128 + SIGKILL);
  EXPECT_TRUE(fs::exists(dir_ / "killed" / ".carom.lock"));
  EXPECT_EQ(carom("run gas.toml --out killed --overwrite --quiet --set time.end=0.2"), 0) << out_;
  EXPECT_EQ(carom("resume killed --end 0.3 --quiet"), 0) << out_;
}

}  // namespace
