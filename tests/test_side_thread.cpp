// core/side_thread.hpp: both tasks of run_beside run exactly once and their writes are seen
// when it returns, whichever thread ran the side task; an exception of either reaches the
// caller (the caller's own first) and the thread stays usable; a thread that fell asleep
// wakes for the next task; and the side thread does take tasks while the caller is busy.
// wake() ends its sleep without a task, also when called the moment the thread falls asleep.
// for_chunks hands every index out exactly once, in pieces of at most the chunk, with or
// without a side thread.
#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/side_thread.hpp"

namespace carom {
namespace {

TEST(SideThread, BothTasksRunOnceAndTheirWritesAreSeen) {
  SideThread side;
  // Plain (non-atomic) data: run_beside's hand-over must order the side task's writes before
  // its return (a data race here is what ThreadSanitizer would report).
  std::vector<long> side_values(20000, 0), own_values(20000, 0);
  for (std::size_t k = 0; k < side_values.size(); ++k)
    side.run_beside([&] { side_values[k] += static_cast<long>(k) + 1; },
                    [&] { own_values[k] += 2 * static_cast<long>(k); });
  for (std::size_t k = 0; k < side_values.size(); ++k) {
    ASSERT_EQ(side_values[k], static_cast<long>(k) + 1) << "task " << k;
    ASSERT_EQ(own_values[k], 2 * static_cast<long>(k)) << "task " << k;
  }
}

TEST(SideThread, ExceptionsReachTheCallerAndTheThreadStaysUsable) {
  SideThread side;
  for (int round = 0; round < 50; ++round) {
    int ran = 0;
    EXPECT_THROW(side.run_beside([] { throw std::runtime_error("side"); }, [&] { ++ran; }),
                 std::runtime_error);
    EXPECT_EQ(ran, 1);
    EXPECT_THROW(side.run_beside([&] { ++ran; }, [] { throw std::logic_error("here"); }),
                 std::logic_error);
    EXPECT_EQ(ran, 2) << "the side task finishes before the caller's exception leaves";
    try {  // both throw: the caller's own exception is the one rethrown
      side.run_beside([] { throw std::runtime_error("side"); },
                      [] { throw std::logic_error("here"); });
      ADD_FAILURE() << "no exception";
    } catch (const std::logic_error&) {
    }
    int value = 0;
    side.run_beside([&] { value += 1; }, [&] { value += 0; });
    EXPECT_EQ(value, 1);
  }
}

TEST(SideThread, WakesForATaskAfterFallingAsleep) {
  SideThread side;
  for (int round = 0; round < 5; ++round) {
    // Longer than its patience (200 us): the thread has gone to sleep.
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    int value = 0;
    side.run_beside([&] { value = 7; }, [] {});
    EXPECT_EQ(value, 7);
  }
}

/// Waits up to 10 s for condition(), looking every `poll`; returns whether it came.
template <class Condition>
bool eventually(Condition condition,
                std::chrono::nanoseconds poll = std::chrono::microseconds(50)) {
  const auto limit = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!condition())
    if (std::chrono::steady_clock::now() > limit)
      return false;
    else if (poll.count() > 0)
      std::this_thread::sleep_for(poll);
  return true;
}

TEST(SideThread, WakeEndsItsSleepWithoutATask) {
  SideThread side;
  for (int round = 0; round < 5; ++round) {
    ASSERT_TRUE(eventually([&] { return side.sleeping(); })) << "it sleeps after its patience";
    const unsigned long long before = side.wake_ups(), runs = side.side_runs();
    side.wake();
    EXPECT_TRUE(eventually([&] { return side.wake_ups() > before; })) << "round " << round;
    EXPECT_EQ(side.side_runs(), runs) << "waking runs nothing";
    int value = 0;
    side.run_beside([&] { value = 7; }, [] {});
    EXPECT_EQ(value, 7);
  }
  // Awake, wake() does nothing (and the destructor ends a sleeping or spinning thread alike).
  side.wake();
  side.wake();
}

// wake() called the moment the thread is seen asleep: the race the previous test gives little
// chance (it polls every 50 us). With serve raising sleeping_ before it read wakes_, a wake()
// between the two was lost: 17 of 5000 such rounds under ASan, none in 3000 in a release build.
// Each round waits for the thread's 200 us patience; 2000 rounds take about half a second.
TEST(SideThread, WakeTheMomentItSleepsIsNotLost) {
  SideThread side;
  for (int round = 0; round < 2000; ++round) {
    ASSERT_TRUE(eventually([&] { return side.sleeping(); }, std::chrono::nanoseconds(0)));
    const unsigned long long before = side.wake_ups();
    side.wake();
    ASSERT_TRUE(eventually([&] { return side.wake_ups() > before; }, std::chrono::nanoseconds(0)))
        << "round " << round;
  }
}

TEST(SideThread, TakesTasksWhileTheCallerIsBusy) {
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "one hardware thread";
  SideThread side;
  auto busy = [] {  // about 20 us of the caller's own work
    const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(20);
    while (std::chrono::steady_clock::now() < until) {
    }
  };
  // 0.2 s of tasks: the side thread is scheduled in that time even on a loaded machine.
  for (int k = 0; k < 10000; ++k) side.run_beside([] {}, busy);
  EXPECT_GT(side.side_runs(), 0u);
}

// Plain per-index writes (each index belongs to one piece): every index of [0, n) is visited
// exactly once and no piece is longer than the chunk or empty, for sizes around the chunk and a
// size whose pieces the two threads share (uneven work: odd pieces spin a little).
TEST(SideThread, ChunksHandEachIndexOutOnce) {
  SideThread side;
  for (SideThread* thread : {&side, static_cast<SideThread*>(nullptr)})
    for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{31}, std::size_t{32},
                          std::size_t{33}, std::size_t{10007}}) {
      std::vector<int> visits(n, 0);
      std::vector<int> bad_piece(n + 1, 0);
      for_chunks(thread, n, 32, [&](std::size_t begin, std::size_t end) {
        if (end <= begin || end - begin > 32 || end > n) bad_piece[begin] = 1;
        for (std::size_t i = begin; i < end; ++i) {
          ++visits[i];
          if ((begin / 32) % 2 == 1) {
            const auto until = std::chrono::steady_clock::now() + std::chrono::nanoseconds(200);
            while (std::chrono::steady_clock::now() < until) {
            }
          }
        }
      });
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(visits[i], 1) << "n " << n << " index " << i;
      for (std::size_t i = 0; i <= n; ++i)
        ASSERT_EQ(bad_piece[i], 0) << "n " << n << " piece at " << i;
    }
}

}  // namespace
}  // namespace carom
