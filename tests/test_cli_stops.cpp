// Stop signals and the output-size check where they used to be missed: a signal
// during a long placement (`carom run`, `carom check`, `carom sweep --dry-run`) was honoured only
// when the placement ended; `carom resume DIR --end T` and `carom sweep --dry-run` did not
// estimate the output.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_support.hpp"

namespace fs = std::filesystem;
using namespace carom_cli_test;

extern char** environ;

namespace {

/// A random fill that takes far longer to place than the tests wait: 107 430 spheres of 1 mm,
/// 0.45 of a 5 cm box. Random insertion jams near 0.38, so the placement runs until it has
/// tried 20 000 times for one sphere, then fails: 292 s of wall time (76 352 placed) for
/// `carom check` of the release build before this fix, on the loaded 2-core machine where it was
/// measured, against the few seconds these tests wait. Below random close packing (0.64), so
/// the capacity check lets it through to the placement.
const std::string kSlowFill =
    "[domain]\nmin = [0, 0, 0]\nmax = [0.05, 0.05, 0.05]\n"
    "[[species]]\nname = \"bead\"\ndiameter = 1.0e-3\ndensity = 2500.0\n"
    "fill = { volume_fraction = 0.45 }\n"
    "[time]\nend = 0.01\n";

/// What one interrupted command did: its exit code, its stderr and stdout, and the seconds from
/// the signal to its exit.
struct Interrupted {
  int exit_code = -1;
  std::string output;
  double seconds_after_signal = 0;
};

/// Starts `carom ARGS` in `dir`, sends SIGTERM after `wait`, and waits for it to exit.
Interrupted interrupt_after(const fs::path& dir, const std::vector<std::string>& args,
                            std::chrono::milliseconds wait) {
  const std::string log = (dir / "output.txt").string();
  std::vector<std::string> words{kCarom};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : words) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  pid_t pid = 0;
  Interrupted result;
  if (posix_spawn(&pid, kCarom.c_str(), &actions, nullptr, argv.data(), environ) != 0) {
    ADD_FAILURE() << "cannot start " << kCarom;
    return result;
  }
  posix_spawn_file_actions_destroy(&actions);
  std::this_thread::sleep_for(wait);
  kill(pid, SIGTERM);
  const auto signalled = std::chrono::steady_clock::now();
  int status = 0;
  waitpid(pid, &status, 0);
  result.seconds_after_signal =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - signalled).count();
  result.exit_code =
      WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  result.output = read(log);
  return result;
}

/// The most seconds a stopped placement may take to exit: the placement looks at the flag every
/// 1024 tries (well under a millisecond); the rest is the process's exit on a loaded machine.
constexpr double kPromptSeconds = 5.0;

}  // namespace

// The placement took its whole course (tens of seconds, until it jammed) before the signal was
// seen; it now stops within kPromptSeconds, with exit 130, a message, and nothing written.
TEST_F(Cli, SignalDuringALongPlacementStopsItPromptly) {
  const std::string slow = scene("slow.toml", kSlowFill);
  const Interrupted run =
      interrupt_after(dir_, {"run", slow, "--out", "r"}, std::chrono::milliseconds(2000));
  EXPECT_EQ(run.exit_code, 130) << run.output;
  EXPECT_LT(run.seconds_after_signal, kPromptSeconds) << run.output;
  EXPECT_NE(run.output.find("interrupted while the particles were placed"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("nothing was written"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir_ / "r")) << "an interrupted placement must leave no output directory";

  const Interrupted check = interrupt_after(dir_, {"check", slow}, std::chrono::milliseconds(2000));
  EXPECT_EQ(check.exit_code, 130) << check.output;
  EXPECT_LT(check.seconds_after_signal, kPromptSeconds) << check.output;
  EXPECT_NE(check.output.find("interrupted while the particles were placed"), std::string::npos)
      << check.output;
}

// `carom sweep --dry-run` places every case's particles; a signal meanwhile was recorded and
// ignored until all were placed. Now it stops the check at once with 130, nothing run.
TEST_F(Cli, SignalDuringASweepDryRunStopsIt) {
  const std::string slow = scene("slow.toml", kSlowFill);
  scene("sweep.toml", "[sweep]\nscene = \"slow.toml\"\nseeds = [1, 2, 3]\n");
  const Interrupted dry =
      interrupt_after(dir_, {"sweep", "sweep.toml", "--dry-run"}, std::chrono::milliseconds(2000));
  EXPECT_EQ(dry.exit_code, 130) << dry.output;
  EXPECT_LT(dry.seconds_after_signal, kPromptSeconds) << dry.output;
  EXPECT_NE(dry.output.find("interrupted while the particles were placed"), std::string::npos)
      << dry.output;
  EXPECT_EQ(dry.output.find("all valid"), std::string::npos) << dry.output;
  EXPECT_FALSE(fs::exists(dir_ / "sweep.out")) << "a dry run wrote outputs";
}

// The sweep's check of its cases (with and without --dry-run) now estimates each case's output
// as `carom run` does: a case that would write terabytes is refused before anything runs.
TEST_F(Cli, SweepRefusesARunawayOutputBeforeRunning) {
  scene("gas.toml", kSmallGas);
  scene("sweep.toml",
        "[sweep]\nscene = \"gas.toml\"\nseeds = [1]\n"
        "[[sweep.vary]]\nkey = \"output.snapshot_every\"\nvalues = [0.5, 1e-9]\n");
  for (const std::string flags : {" --dry-run", ""}) {
    SCOPED_TRACE(flags);
    EXPECT_EQ(carom("sweep sweep.toml" + flags), 2) << out_;
    EXPECT_NE(out_.find("case 1 (output.snapshot_every=1e-09, seed 1)"), std::string::npos) << out_;
    EXPECT_NE(out_.find("more than output.max_bytes = 10 GB (the default)"), std::string::npos)
        << out_;
    EXPECT_EQ(out_.find("case 0 ("), std::string::npos) << "the reasonable case is not an error:\n"
                                                        << out_;
    EXPECT_FALSE(fs::exists(dir_ / "sweep.out" / "case_0000" / "run.h5")) << "a case ran";
  }
}

// `carom resume DIR --end T` with a T that makes the output enormous used to run on (here: 2e12
// snapshots); it is now refused like `carom run`, with the files of the run untouched.
TEST_F(Cli, ResumeToALaterEndChecksTheOutputSize) {
  const std::string gas = scene("gas.toml", kSmallGas);
  ASSERT_EQ(carom("run " + gas + " --out r --quiet"), 0) << out_;
  const std::string checkpoint = read(dir_ / "r" / "checkpoint.h5");
  const auto run_size = fs::file_size(dir_ / "r" / "run.h5");
  EXPECT_EQ(carom("resume r --end 1e12"), 2) << out_;
  EXPECT_NE(out_.find("more than output.max_bytes = 10 GB (the default)"), std::string::npos)
      << out_;
  EXPECT_NE(out_.find("time.end = 1e+12 s"), std::string::npos) << out_;
  EXPECT_EQ(read(dir_ / "r" / "checkpoint.h5"), checkpoint) << "the checkpoint changed";
  EXPECT_EQ(fs::file_size(dir_ / "r" / "run.h5"), run_size) << "run.h5 changed";
  // A later end whose output fits still resumes.
  EXPECT_EQ(carom("resume r --end 5 --quiet"), 0) << out_;
}
