// core/worker_pool.hpp: every index of a loop is visited exactly once, in the chunks the header
// promises, for any thread count; an exception in any chunk reaches the caller; the pool is
// reusable after one.
#include <gtest/gtest.h>
#ifdef __linux__
#include <sched.h>
#endif

#include <atomic>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "core/worker_pool.hpp"

namespace carom {
namespace {

TEST(WorkerPool, EveryIndexOnceInItsPromisedChunk) {
  for (int threads : {1, 2, 3, 8}) {
    WorkerPool pool(threads);
    EXPECT_EQ(pool.threads(), threads);
    for (std::size_t n : {0u, 1u, 2u, 7u, 1000u}) {
      for (int repeat = 0; repeat < 3; ++repeat) {  // the same pool, loop after loop
        std::vector<std::atomic<int>> visits(n);
        std::vector<std::pair<std::size_t, std::size_t>> chunks(static_cast<std::size_t>(threads));
        std::atomic<int> calls{0};
        pool.for_chunks(n, [&](std::size_t begin, std::size_t end) {
          for (std::size_t i = begin; i < end; ++i) ++visits[i];
          // Chunk k starts at k n / T: find k from the start (chunks may be empty).
          for (int k = 0; k < threads; ++k)
            if (begin == n * k / threads && end == n * (k + 1) / threads) chunks[k] = {begin, end};
          ++calls;
        });
        EXPECT_EQ(calls.load(), threads) << threads << " threads, n = " << n;
        for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(visits[i].load(), 1) << "index " << i;
        for (int k = 0; k < threads; ++k)
          EXPECT_EQ(chunks[k], std::make_pair(n * k / threads, n * (k + 1) / threads));
      }
    }
  }
}

TEST(WorkerPool, AnExceptionInAnyChunkReachesTheCaller) {
  WorkerPool pool(3);
  for (std::size_t bad : {0u, 50u, 99u}) {  // in the caller's chunk and in each worker's
    std::atomic<int> visited{0};
    EXPECT_THROW(pool.for_chunks(100,
                                 [&](std::size_t begin, std::size_t end) {
                                   for (std::size_t i = begin; i < end; ++i) {
                                     if (i == bad) throw std::runtime_error("bad index");
                                     ++visited;
                                   }
                                 }),
                 std::runtime_error);
    EXPECT_LT(visited.load(), 100);
  }
  std::atomic<int> visited{0};  // still usable
  pool.for_chunks(100, [&](std::size_t begin, std::size_t end) { visited += static_cast<int>(end - begin); });
  EXPECT_EQ(visited.load(), 100);
}

TEST(WorkerPool, ThreadCountFromTheEnvironment) {
  const char* saved = std::getenv("CAROM_THREADS");
  const std::string keep = saved ? saved : "";
  setenv("CAROM_THREADS", "3", 1);
  EXPECT_EQ(WorkerPool::default_threads(), 3);
  for (const char* bad : {"0", "-2", "two", "3x", ""}) {
    setenv("CAROM_THREADS", bad, 1);
    EXPECT_THROW(WorkerPool::default_threads(), std::invalid_argument) << "'" << bad << "'";
  }
  unsetenv("CAROM_THREADS");
  EXPECT_GE(WorkerPool::default_threads(), 1);
#ifdef __linux__
  // Without the variable: the CPUs the calling thread may run on (as under `taskset -c 1`),
  // here a thread of this test pinned to one CPU, so the rest of the process keeps its own.
  int pinned = 0;
  std::thread([&] {
    cpu_set_t allowed, one;
    ASSERT_EQ(sched_getaffinity(0, sizeof(allowed), &allowed), 0);
    int first = 0;
    while (!CPU_ISSET(first, &allowed)) ++first;
    CPU_ZERO(&one);
    CPU_SET(first, &one);
    ASSERT_EQ(sched_setaffinity(0, sizeof(one), &one), 0);
    pinned = WorkerPool::default_threads();
  }).join();
  EXPECT_EQ(pinned, 1);
#endif
  if (saved) setenv("CAROM_THREADS", keep.c_str(), 1);
  EXPECT_THROW(WorkerPool(0), std::invalid_argument);
}

}  // namespace
}  // namespace carom
