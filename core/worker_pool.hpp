#pragma once
/// Threads that share one loop's iterations: the calling thread and `threads - 1` workers that
/// wait (asleep, not spinning) between loops. Each loop is cut into one contiguous chunk per
/// thread, so what each iteration computes, and where it writes, is the same for any number of
/// threads: results do not depend on the thread count (the engine's use keeps them bit for bit).
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace carom {

class WorkerPool {
 public:
  /// `threads` >= 1 in all, the calling thread included.
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  /// Threads in all, the calling thread included.
  int threads() const { return static_cast<int>(workers_.size()) + 1; }

  /// Calls body(begin, end) once per thread on the chunks [k n / T, (k + 1) n / T) of [0, n)
  /// and returns when all are done. An exception from any chunk is rethrown here (the first
  /// one; the other chunks still finish). Not reentrant; one caller at a time.
  void for_chunks(std::size_t n, const std::function<void(std::size_t, std::size_t)>& body);

  /// The thread count a run uses when its scene leaves it to carom: the environment variable
  /// CAROM_THREADS when set (an integer >= 1), else the hardware threads this process may run
  /// on (its CPU affinity: `taskset -c 1 carom ...` or a batch job's share of a node counts
  /// its own cores, not the machine's).
  static int default_threads();

 private:
  void work(int k);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_;
  std::condition_variable done_;
  const std::function<void(std::size_t, std::size_t)>* body_ = nullptr;
  std::size_t n_ = 0;
  unsigned long long generation_ = 0;  ///< Bumped at each loop; workers wait for a new one.
  int pending_ = 0;                    ///< Workers not yet done with this loop.
  bool stop_ = false;
  std::exception_ptr error_;
};

}  // namespace carom
