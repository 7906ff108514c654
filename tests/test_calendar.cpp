// The event calendar (events/event_driven/calendar.hpp) against a brute-force oracle: a linear scan of all
// slots for the smallest (time, slot).
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "core/rng.hpp"
#include "events/event_driven/calendar.hpp"

namespace carom {
namespace {

std::size_t oracle_top(const std::vector<double>& times) {
  std::size_t best = 0;
  for (std::size_t s = 1; s < times.size(); ++s)
    if (times[s] < times[best]) best = s;  // strict: ties keep the lower slot
  return best;
}

// Random set/top sequences: earlier and later updates, kNever, many exact ties (times drawn
// from a small set), growth with resize. Exact comparison: the calendar must return exactly
// the oracle's slot and time (ties broken by slot number is the documented order).
TEST(Calendar, MatchesLinearScanOracle) {
  Rng rng(7);
  for (int round = 0; round < 20; ++round) {
    // The last rounds with heaps of blocks several levels deep.
    std::size_t slots = round < 17 ? 1 + rng.below(200) : 1000 + rng.below(2000);
    Calendar calendar(slots);
    std::vector<double> times(slots, kNever);
    for (int step = 0; step < 20000; ++step) {
      const double u = rng.uniform();
      if (u < 0.002) {  // grow
        slots += 1 + rng.below(5);
        calendar.resize(slots);
        times.resize(slots, kNever);
      } else {
        const std::size_t slot = rng.below(slots);
        double t;
        const double kind = rng.uniform();
        if (kind < 0.1) t = kNever;
        else if (kind < 0.5) t = double(rng.below(8));  // ties
        else t = rng.uniform(0, 10);
        calendar.set(slot, t);
        times[slot] = t;
      }
      ASSERT_EQ(calendar.size(), times.size());
      const std::size_t expected = oracle_top(times);
      ASSERT_EQ(calendar.top_slot(), expected) << "round " << round << " step " << step;
      ASSERT_EQ(calendar.top_time(), times[expected]);
      const std::size_t probe = rng.below(slots);
      ASSERT_EQ(calendar.time_of(probe), times[probe]);
    }
  }
}

// set_first (all particles scheduled after a fluid step) against set one slot at a time: the
// same top after it, and the same order of events (pop, set later) for long after, on
// calendars whose slots beyond n (the global events) hold times of their own, with ties.
TEST(Calendar, SetFirstIsSetOneByOne) {
  Rng rng(13);
  for (int round = 0; round < 40; ++round) {
    const std::size_t slots = 1 + rng.below(round < 30 ? 300 : 3000);
    const std::size_t n = rng.below(slots + 1);
    auto draw = [&] {
      const double kind = rng.uniform();
      return kind < 0.1 ? kNever : kind < 0.5 ? double(rng.below(8)) : rng.uniform(0, 10);
    };
    Calendar bulk(slots), single(slots);
    std::vector<double> times(slots, kNever);
    for (int step = 0; step < 3 * static_cast<int>(slots); ++step) {  // a history first
      const std::size_t slot = rng.below(slots);
      times[slot] = draw();
      bulk.set(slot, times[slot]);
      single.set(slot, times[slot]);
    }
    std::vector<double> fresh(n);
    for (double& t : fresh) t = draw();
    bulk.set_first(n, [&](std::size_t s) { return fresh[s]; });
    for (std::size_t s = 0; s < n; ++s) single.set(s, fresh[s]);
    for (std::size_t s = 0; s < n; ++s) times[s] = fresh[s];
    for (int step = 0; step < 2000; ++step) {
      ASSERT_EQ(bulk.top_slot(), single.top_slot()) << "round " << round << " step " << step;
      ASSERT_EQ(bulk.top_slot(), oracle_top(times));
      ASSERT_EQ(bulk.top_time(), single.top_time());
      const std::size_t top = bulk.top_slot();
      const double later = std::max(times[top], 0.0) + rng.uniform(0, 1);
      times[top] = later == times[top] ? kNever : later;
      bulk.set(top, times[top]);
      single.set(top, times[top]);
    }
  }
}

// The event-loop pattern: pop the top, re-schedule it later; events come out in time order.
TEST(Calendar, PopAndRescheduleGivesNondecreasingTimes) {
  Rng rng(11);
  const std::size_t slots = 500;
  Calendar calendar(slots);
  for (std::size_t s = 0; s < slots; ++s) calendar.set(s, rng.uniform(0, 1));
  double last = -1;
  for (int step = 0; step < 100000; ++step) {
    const std::size_t s = calendar.top_slot();
    const double t = calendar.top_time();
    ASSERT_GE(t, last);
    last = t;
    calendar.set(s, t + rng.uniform(0, 1));
    // A random other slot is invalidated to a later time, as lazy invalidation does.
    const std::size_t other = rng.below(slots);
    calendar.set(other, std::max(calendar.time_of(other), t) + rng.uniform(0, 0.1));
  }
}


// Calendars large enough that later blocks wait in time buckets, in the event loop's pattern:
// pop the top (set to kNever, look at the next top, set the popped slot later), invalidate a
// neighbour, now and then an earlier time, a tie, kNever, a time far beyond the ring, and a
// change of time scale that makes the buckets' width wrong (it is tuned again). The oracle is an
// ordered set of (time, slot): the calendar's top must be its first element, exactly.
TEST(Calendar, BucketsMatchAnOrderedSet) {
  for (const std::uint64_t seed : {3u, 4u}) {
    Rng rng(seed);
    const std::size_t slots = 100000 + rng.below(1000);
    Calendar calendar(slots);
    std::vector<double> times(slots, kNever);
    std::set<std::pair<double, std::size_t>> oracle;
    auto set = [&](std::size_t slot, double t) {
      if (times[slot] != kNever) oracle.erase({times[slot], slot});
      times[slot] = t;
      if (t != kNever) oracle.insert({t, slot});
      calendar.set(slot, t);
    };
    auto check = [&](int step) {
      const std::size_t expected = oracle.empty() ? 0 : oracle.begin()->second;
      ASSERT_EQ(calendar.top_slot(), expected) << "seed " << seed << " step " << step;
      ASSERT_EQ(calendar.top_time(), times[expected]);
    };
    // Stops the test at the first failure of check (an ASSERT inside a lambda only leaves it).
#define CHECK_TOP(step)       \
  check(step);                \
  if (HasFatalFailure()) return
    // The first schedule slot by slot, as the engine's constructor makes it.
    for (std::size_t s = 0; s + 1 < slots; ++s) set(s, rng.uniform(0, 1));
    set(slots - 1, 1e9);  // the end of the run: far beyond every bucket
    CHECK_TOP(-1);
    EXPECT_TRUE(calendar.bucketed());
    double scale = 1;
    bool was_bucketed = true;
    for (int step = 0; step < 240000; ++step) {
      if (step == 80000) scale = 1e-3;  // events far denser than the width was tuned for
      if (step == 160000) scale = 1;
      const std::size_t top = calendar.top_slot();
      const double now = calendar.top_time();
      set(top, kNever);
      CHECK_TOP(step);
      const double u = rng.uniform();
      set(top, u < 0.001 ? kNever : u < 0.002 ? now : u < 0.003 ? now + 1e6 : now + scale * -std::log(1 - rng.uniform()));
      CHECK_TOP(step);
      const std::size_t other = rng.below(slots - 1);
      const double v = rng.uniform();
      if (v < 0.3) {
        set(other, std::max(times[other], now) + scale * rng.uniform(0, 0.1));  // later
      } else if (v < 0.35 && times[other] != kNever) {
        set(other, now + (times[other] - now) * rng.uniform());  // earlier, not before now
      } else if (v < 0.36) {
        set(other, times[top]);  // a tie with another slot
      }
      CHECK_TOP(step);
      was_bucketed = was_bucketed && calendar.bucketed();
      if (step % 5000 == 0) {
        ASSERT_TRUE(calendar.consistent()) << "seed " << seed << " step " << step;
      }
    }
    EXPECT_TRUE(was_bucketed) << "the test should run the buckets all along";
    EXPECT_GE(calendar.tunings(), 3u) << "the first width, and again after each change of scale";
    // Empty it: every slot to kNever, the top checked as it goes.
    for (int step = 0; !oracle.empty(); ++step) {
      set(oracle.begin()->second, kNever);
      CHECK_TOP(step);
    }
#undef CHECK_TOP
  }
}

}  // namespace
}  // namespace carom
