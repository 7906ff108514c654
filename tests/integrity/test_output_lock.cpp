// One run per output folder: while a run writes into a folder, a second `carom run`, a
// `carom run --overwrite` and a `carom resume` into it are refused (exit 2, "in use") and delete
// nothing; once the first process is gone (ended by a signal, or killed with SIGKILL, which
// leaves the lock file behind) the lock is stale and the folder is usable at once. A sweep's
// case whose sweep is killed with SIGKILL stops (it is not left running orphaned), and the
// sweep run again at once is not refused.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
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

/// True while process `pid` runs (a zombie counts as gone).
bool running(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
  const std::size_t close = text.rfind(')');
  return close != std::string::npos && close + 2 < text.size() && text[close + 2] != 'Z';
}

TEST_F(OutputLockTest, ACaseOfAKilledSweepStopsAndTheSweepRunsAgain) {
  scene("gas.toml", kGas);
  std::ofstream(dir_ / "long.toml") << "[sweep]\nscene = \"gas.toml\"\nseeds = [1]\n[sweep.set]\ntime.end = 1e6\n"
                                       "collisions.default = { e = 1.0, mu = 0.0, beta0 = -1.0 }\noutput.snapshot_every = 1e5\n"
                                       "output.sample_every = 1e5\noutput.checkpoint_every = 1e5\n";
  const pid_t sweep = start({"sweep", "long.toml", "--out", "swept", "--quiet"});
  // The case's lock file names its process.
  fs::path lock;
  for (int k = 0; k < 300 && lock.empty(); ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::error_code error;
    if (fs::exists(dir_ / "swept"))
      for (const auto& entry : fs::recursive_directory_iterator(dir_ / "swept", error))
        if (entry.path().filename() == ".carom.lock" && fs::file_size(entry.path(), error) > 0) lock = entry.path();
  }
  ASSERT_FALSE(lock.empty()) << read(dir_ / "background.log");
  const pid_t case_pid = std::stoi(read(lock));
  ASSERT_TRUE(running(case_pid));
  kill(sweep, SIGKILL);
  EXPECT_EQ(wait_exit(sweep), 128 + SIGKILL);
  bool stopped = false;
  for (int k = 0; k < 100 && !stopped; ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    stopped = !running(case_pid);
  }
  EXPECT_TRUE(stopped) << "the case of a killed sweep runs on";
  // The sweep again at once: not told that its folder is in use; it runs the case again.
  const pid_t again = start({"sweep", "long.toml", "--out", "swept", "--quiet"});
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  EXPECT_TRUE(running(again)) << read(dir_ / "background.log");
  kill(again, SIGTERM);
  EXPECT_EQ(wait_exit(again), 130) << read(dir_ / "background.log");
  EXPECT_EQ(read(dir_ / "background.log").find("in use"), std::string::npos) << read(dir_ / "background.log");
}

}  // namespace
