#pragma once
/// A second thread for work that comes in pairs of small, independent tasks, thousands of
/// times a second (after a collision both partners' next events are predicted; each takes a
/// few microseconds). Waking a sleeping thread costs more than such a task, so the thread
/// spins while tasks keep coming and sleeps after a pause; handing one task over and back costs
/// 0.1 to 0.6 us on this virtual machine's two cores (it varies from hour to hour with where the
/// host puts them): whether that pays for tasks of a few microseconds is measured as the run
/// goes (core/split_chooser.hpp).
///
/// The caller never waits for the thread to begin: run_beside posts one task, runs the other
/// itself, and then takes the first back and runs it too unless the thread has begun it. So a
/// machine whose cores are all busy (or a thread descheduled) costs at most the hand-over, and
/// both tasks run exactly once whichever thread runs them: results do not depend on it.
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <type_traits>

namespace carom {

class SideThread {
 public:
  SideThread();
  ~SideThread();
  SideThread(const SideThread&) = delete;
  SideThread& operator=(const SideThread&) = delete;

  /// Runs side() and here() and returns when both are done: here() on the calling thread, side()
  /// on the side thread at the same time, or after here() on the calling thread if the side
  /// thread had not begun it. The two must not write anything the other reads. An exception
  /// from either is rethrown here (here()'s first), after both have finished. Not reentrant.
  template <class Side, class Here>
  void run_beside(Side&& side, Here&& here) {
    post(&call<std::remove_reference_t<Side>>, &side);
    std::exception_ptr own;
    try {
      here();
    } catch (...) {
      own = std::current_exception();
    }
    // The side task reads the caller's stack: it is finished before anything leaves.
    std::exception_ptr other = reclaim() ? run_here() : wait();
    if (own) std::rethrow_exception(own);
    if (other) std::rethrow_exception(other);
  }

  /// Wakes the thread if it sleeps, so that it is spinning when the next tasks come: call it a
  /// little before a burst of tasks after a pause (waking takes tens of microseconds, which the
  /// caller otherwise waits for at the burst's first task). Does nothing if it is awake.
  void wake();
  /// Whether the thread sleeps now (it wakes for the next task or wake()): for tests.
  bool sleeping() const { return sleeping_.load(std::memory_order_seq_cst); }
  /// Times the thread woke from sleep so far: for tests and diagnostics.
  unsigned long long wake_ups() const { return wake_ups_.load(std::memory_order_relaxed); }

  /// Tasks run on the side thread so far (not taken back): for tests and diagnostics.
  unsigned long long side_runs() const { return side_runs_.load(std::memory_order_relaxed); }

 private:
  /// The task's state: what the caller and the side thread hand each other.
  enum State : int { kIdle, kPosted, kRunning, kDone, kStop };

  template <class F>
  static void call(void* f) {
    (*static_cast<F*>(f))();
  }
  /// Hands task(argument) to the side thread.
  void post(void (*task)(void*), void* argument);
  /// Takes the posted task back if the side thread has not begun it.
  bool reclaim();
  /// Runs the taken-back task on the calling thread; returns its exception, if any.
  std::exception_ptr run_here();
  /// Waits until the side thread has finished the task; returns its exception, if any.
  std::exception_ptr wait();
  /// The side thread: spins for tasks, sleeps when none came for a while.
  void serve();

  alignas(64) std::atomic<int> state_{kIdle};
  std::atomic<bool> sleeping_{false};
  /// What a sleeping thread waits on: raised by whoever wakes it (a task, wake(), the end).
  std::atomic<unsigned> wakes_{0};
  void (*task_)(void*) = nullptr;
  void* argument_ = nullptr;
  std::exception_ptr error_;
  std::atomic<unsigned long long> side_runs_{0};
  std::atomic<unsigned long long> wake_ups_{0};
  alignas(64) std::thread thread_;
};

/// Calls body(begin, end) for consecutive pieces of [0, n) of at most `chunk` indices each, which
/// the calling thread and `side` take in turn from a shared counter as each finishes its last,
/// so that neither waits long for the other when some indices cost more than others (halves
/// fixed in advance left a thread idle for up to the difference). Every index is handed out
/// exactly once, to one thread or the other; all here when `side` is null. The body must
/// write only what belongs to its own indices (which thread runs an index depends on timing).
template <class Body>
void for_chunks(SideThread* side, std::size_t n, std::size_t chunk, Body&& body) {
  if (side == nullptr) {
    for (std::size_t begin = 0; begin < n; begin += chunk)
      body(begin, begin + chunk < n ? begin + chunk : n);
    return;
  }
  alignas(64) std::atomic<std::size_t> next{0};
  auto take = [&] {
    for (;;) {
      const std::size_t begin = next.fetch_add(chunk, std::memory_order_relaxed);
      if (begin >= n) return;
      body(begin, begin + chunk < n ? begin + chunk : n);
    }
  };
  side->run_beside(take, take);
}

}  // namespace carom
