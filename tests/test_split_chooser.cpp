// core/split_chooser.hpp, on a clock that only the test moves: every call runs exactly one of
// the two ways; a trial runs each way on the same number of calls; the way with the shorter
// blocks (the calls and the work between them) is kept until the next trial, which follows a
// change of the machine's pace; an interrupted block is left out; a tie goes to one thread.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>

#include "core/split_chooser.hpp"

namespace carom {
namespace {

/// A clock that only the test advances (nanoseconds).
struct TestClock {
  using duration = std::chrono::nanoseconds;
  using time_point = std::chrono::time_point<TestClock, duration>;
  static inline std::int64_t now_ns = 0;
  static time_point now() { return time_point(duration(now_ns)); }
};

using Chooser = SplitChooser<TestClock>;

struct Counts {
  std::uint64_t split = 0, serial = 0;
};

/// What a call costs each way (ns): in the call, and in the work after it until the next call
/// (where a split's cache misses are paid).
struct Costs {
  std::int64_t split = 0, serial = 0, split_after = 0, serial_after = 0;
};

Counts run(Chooser& chooser, std::uint32_t calls, Costs costs) {
  Counts counts;
  for (std::uint32_t k = 0; k < calls; ++k) {
    bool splitting = false;
    chooser.run(
        [&] {
          ++counts.split;
          splitting = true;
          TestClock::now_ns += costs.split;
        },
        [&] {
          ++counts.serial;
          TestClock::now_ns += costs.serial;
        });
    TestClock::now_ns += splitting ? costs.split_after : costs.serial_after;
  }
  return counts;
}

/// Runs a whole trial and the call after it that books its last block.
Counts trial(Chooser& chooser, Costs costs) {
  EXPECT_TRUE(chooser.in_trial());
  const Counts counts = run(chooser, Chooser::kTrialCalls + 1, costs);
  EXPECT_FALSE(chooser.in_trial());
  return counts;
}

TEST(SplitChooser, TrialRunsBothWaysAlikeThenKeepsTheFaster) {
  Chooser chooser;
  EXPECT_TRUE(chooser.in_trial()) << "a run starts with a trial";
  const Counts counts = trial(chooser, {700, 1000, 0, 0});
  EXPECT_EQ(counts.split, Chooser::kTrialCalls / 2 + 1) << "the call after the trial splits";
  EXPECT_EQ(counts.serial, Chooser::kTrialCalls / 2);
  EXPECT_TRUE(chooser.splits()) << "splitting was faster";
  const Counts kept = run(chooser, Chooser::kKeptCalls - 1, {700, 1000, 0, 0});
  EXPECT_EQ(kept.split, Chooser::kKeptCalls - 1);
  EXPECT_EQ(kept.serial, 0u);
  EXPECT_TRUE(chooser.in_trial()) << "a new trial after the kept calls";
}

TEST(SplitChooser, CountsTheWorkBetweenCalls) {
  // The split call itself is quicker, but what it leaves for the work after it (cache lines in
  // the other core) costs more than it saved: one thread is kept.
  Chooser chooser;
  trial(chooser, {700, 1000, 500, 0});
  EXPECT_FALSE(chooser.splits());
}

TEST(SplitChooser, FollowsTheMachineWhenItsPaceChanges) {
  Chooser chooser;
  trial(chooser, {700, 1000, 0, 0});
  ASSERT_TRUE(chooser.splits());
  // The hand-over becomes dear (the cores far apart, or the other one busy): the next trial
  // turns to one thread.
  run(chooser, Chooser::kKeptCalls - 1, {2500, 1000, 0, 0});
  const Counts counts = trial(chooser, {2500, 1000, 0, 0});
  EXPECT_EQ(counts.split, Chooser::kTrialCalls / 2);
  EXPECT_FALSE(chooser.splits());
  const Counts kept = run(chooser, Chooser::kKeptCalls - 1, {2500, 1000, 0, 0});
  EXPECT_EQ(kept.serial, Chooser::kKeptCalls - 1);
  // And back.
  trial(chooser, {600, 1000, 0, 0});
  EXPECT_TRUE(chooser.splits());
}

TEST(SplitChooser, PaceChangeWithinATrialHitsBothWays) {
  // The blocks alternate, so a machine that slows down by half during a trial (every call
  // after the first half of it) still compares like with like: split at 700 against serial at
  // 1000 is found faster though half of its calls came at 1400.
  Chooser chooser;
  run(chooser, Chooser::kTrialCalls / 2, {700, 1000, 0, 0});
  trial(chooser, {1400, 2000, 0, 0});
  EXPECT_TRUE(chooser.splits());
}

TEST(SplitChooser, InterruptedBlocksAreLeftOut) {
  // A long pause (a fluid step) after the first call of every split block would make splitting
  // look slow; interrupt() leaves those blocks out, and the rest decide.
  Chooser chooser;
  for (std::uint32_t k = 0; k <= Chooser::kTrialCalls; ++k) {
    const bool first_of_split_block = k % (2 * Chooser::kBlock) == 0 && k < Chooser::kTrialCalls;
    run(chooser, 1, {700, 1000, 0, 0});
    if (first_of_split_block && k > 0) {
      TestClock::now_ns += 1'000'000;
      chooser.interrupt();
    }
  }
  EXPECT_FALSE(chooser.in_trial());
  EXPECT_TRUE(chooser.splits()) << "the first split block (never interrupted) decides";
}

TEST(SplitChooser, AWayNeverTimedKeepsTheChoice) {
  Chooser chooser;
  trial(chooser, {700, 1000, 0, 0});
  ASSERT_TRUE(chooser.splits());
  run(chooser, Chooser::kKeptCalls - 1, {700, 1000, 0, 0});
  // Every block of the next trial interrupted: nothing timed, the choice stays.
  for (std::uint32_t k = 0; k <= Chooser::kTrialCalls; ++k) {
    run(chooser, 1, {5000, 1000, 0, 0});
    chooser.interrupt();
  }
  EXPECT_FALSE(chooser.in_trial());
  EXPECT_TRUE(chooser.splits());
}

TEST(SplitChooser, ATieGoesToOneThread) {
  Chooser chooser;
  trial(chooser, {1000, 1000, 0, 0});
  EXPECT_FALSE(chooser.splits());
}

}  // namespace
}  // namespace carom
