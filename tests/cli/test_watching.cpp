// Watching a run: progress lines in a log when stderr is not a terminal (a batch job's log),
// and `carom info` on a run file that the running process holds locked for writing.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "cli_support.hpp"
#include "scenarios/run/progress.hpp"

using namespace carom;
using namespace carom_cli_test;

namespace {

TEST(ProgressLog, WholeLinesAtTheIntervalWhenStderrIsNotATerminal) {
  ASSERT_FALSE(ProgressLine::stderr_is_terminal()) << "run this test with stderr redirected (ctest does)";
  testing::internal::CaptureStderr();
  {
    // An interval of 1 s: wide enough that a busy machine does not reach it between two calls.
    ProgressLine progress(true, 0.0, 2.0, 1.0);
    progress.update(0.1, 100, 50);  // before the first interval: nothing
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));
    progress.update(0.5, 1100, 550);
    progress.update(0.6, 1200, 600);  // within the interval after it: nothing
    progress.finish();
  }
  const std::string log = testing::internal::GetCapturedStderr();
  // One whole line: the time against the end, the share done, rates since the first count.
  EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 1) << log;
  EXPECT_EQ(log.find('\r'), std::string::npos) << log;
  EXPECT_EQ(log.rfind("carom: t = 0.5 / 2 s (25.0%), ", 0), 0u) << log;
  EXPECT_NE(log.find("events/s"), std::string::npos) << log;
  EXPECT_NE(log.find("to go"), std::string::npos) << log;
}

TEST(ProgressLog, QuietWritesNothing) {
  testing::internal::CaptureStderr();
  ProgressLine progress(false, 0.0, 1.0, 0.0);
  progress.update(0.5, 10, 5);
  progress.finish();
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST_F(Cli, InfoReadsARunThatAnotherProcessHoldsLocked) {
  ASSERT_EQ(carom("run " + scene("gas.toml", kSmallGas) + " --out running --quiet"), 0) << out_;
  // As while the run is still going: no summary yet, and HDF5's lock held by the writer.
  fs::remove(dir_ / "running" / "summary.json");
  const int fd = ::open((dir_ / "running" / "run.h5").c_str(), O_RDWR);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  EXPECT_EQ(carom("info running/run.h5"), 0) << out_;
  EXPECT_NE(out_.find("carom run file"), std::string::npos) << out_;
  EXPECT_NE(out_.find("t = 4 s of time.end = 4 s (100 %)"), std::string::npos) << out_;
  EXPECT_EQ(carom("info --tree running/run.h5"), 0) << out_;
  ::close(fd);
}

}  // namespace
