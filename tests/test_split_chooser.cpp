// core/split_chooser.hpp, on a clock the tasks themselves move: every call runs exactly one of
// the two ways; a trial times each way on the same number of calls; the faster way is kept
// until the next trial, which follows a change of the machine's pace; a tie goes to one thread.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>

#include "core/split_chooser.hpp"

namespace carom {
namespace {

/// A clock that only the tasks advance (nanoseconds).
struct TaskClock {
  using duration = std::chrono::nanoseconds;
  using time_point = std::chrono::time_point<TaskClock, duration>;
  static inline std::int64_t now_ns = 0;
  static time_point now() { return time_point(duration(now_ns)); }
};

using Chooser = SplitChooser<TaskClock>;

struct Counts {
  std::uint64_t split = 0, serial = 0;
};

/// Runs `calls` calls in which a split pair takes split_ns and one after the other serial_ns.
Counts run(Chooser& chooser, std::uint32_t calls, std::int64_t split_ns, std::int64_t serial_ns) {
  Counts counts;
  for (std::uint32_t k = 0; k < calls; ++k)
    chooser.run(
        [&] {
          ++counts.split;
          TaskClock::now_ns += split_ns;
        },
        [&] {
          ++counts.serial;
          TaskClock::now_ns += serial_ns;
        });
  return counts;
}

TEST(SplitChooser, TrialTimesBothWaysAlikeThenKeepsTheFaster) {
  Chooser chooser;
  EXPECT_TRUE(chooser.in_trial()) << "a run starts with a trial";
  const Counts trial = run(chooser, Chooser::kTrialCalls, 700, 1000);
  EXPECT_EQ(trial.split, Chooser::kTrialCalls / 2);
  EXPECT_EQ(trial.serial, Chooser::kTrialCalls / 2);
  EXPECT_FALSE(chooser.in_trial());
  EXPECT_TRUE(chooser.splits()) << "splitting was faster";
  const Counts kept = run(chooser, Chooser::kKeptCalls, 700, 1000);
  EXPECT_EQ(kept.split, Chooser::kKeptCalls);
  EXPECT_EQ(kept.serial, 0u);
  EXPECT_TRUE(chooser.in_trial()) << "a new trial after the kept calls";
}

TEST(SplitChooser, FollowsTheMachineWhenItsPaceChanges) {
  Chooser chooser;
  run(chooser, Chooser::kTrialCalls, 700, 1000);
  ASSERT_TRUE(chooser.splits());
  // The hand-over becomes dear (the cores far apart, or the other one busy): the next trial
  // turns to one thread.
  run(chooser, Chooser::kKeptCalls, 2500, 1000);
  const Counts trial = run(chooser, Chooser::kTrialCalls, 2500, 1000);
  EXPECT_EQ(trial.split, trial.serial);
  EXPECT_FALSE(chooser.splits());
  const Counts kept = run(chooser, Chooser::kKeptCalls, 2500, 1000);
  EXPECT_EQ(kept.serial, Chooser::kKeptCalls);
  // And back.
  run(chooser, Chooser::kTrialCalls, 600, 1000);
  EXPECT_TRUE(chooser.splits());
}

TEST(SplitChooser, PaceChangeWithinATrialHitsBothWays) {
  // The blocks alternate, so a machine that slows down by half during a trial (every call
  // after the first half of it) still compares like with like: split at 700 against serial at
  // 1000 is found faster though half of its calls came at 1400.
  Chooser chooser;
  run(chooser, Chooser::kTrialCalls / 2, 700, 1000);
  run(chooser, Chooser::kTrialCalls / 2, 1400, 2000);
  EXPECT_TRUE(chooser.splits());
}

TEST(SplitChooser, ATieGoesToOneThread) {
  Chooser chooser;
  run(chooser, Chooser::kTrialCalls, 1000, 1000);
  EXPECT_FALSE(chooser.splits());
}

}  // namespace
}  // namespace carom
