#include "core/side_thread.hpp"

#include <chrono>
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace carom {

namespace {
/// Tells the core that this is a spin loop (spares the other hardware thread, if any).
inline void relax_cpu() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#else
  std::this_thread::yield();
#endif
}
/// Runs task(argument); returns its exception, if any (either thread runs tasks this way).
std::exception_ptr run_catching(void (*task)(void*), void* argument) {
  try {
    task(argument);
  } catch (...) {
    return std::current_exception();
  }
  return nullptr;
}
}  // namespace

SideThread::SideThread() : thread_([this] { serve(); }) {}

SideThread::~SideThread() {
  state_.store(kStop, std::memory_order_seq_cst);
  wakes_.fetch_add(1, std::memory_order_seq_cst);
  wakes_.notify_one();
  thread_.join();
}

void SideThread::post(void (*task)(void*), void* argument) {
  task_ = task;
  argument_ = argument;
  error_ = nullptr;
  state_.store(kPosted, std::memory_order_seq_cst);
  wake();
}

void SideThread::wake() {
  // Paired with serve, which reads wakes_, then raises sleeping_, then looks at the state a last
  // time: either it sees the new state there, or this sees it asleep and raises wakes_ after
  // serve read it, so that serve's wait returns at once.
  if (sleeping_.load(std::memory_order_seq_cst)) {
    wakes_.fetch_add(1, std::memory_order_seq_cst);
    wakes_.notify_one();
  }
}

bool SideThread::reclaim() {
  int expected = kPosted;
  return state_.compare_exchange_strong(expected, kIdle, std::memory_order_acq_rel);
}

std::exception_ptr SideThread::run_here() {
  return run_catching(task_, argument_);
}

std::exception_ptr SideThread::wait() {
  // The side thread is running the task: at most a few microseconds, unless it was descheduled.
  for (unsigned spins = 0; state_.load(std::memory_order_acquire) != kDone; ++spins) {
    if (spins < 4096)
      relax_cpu();
    else
      std::this_thread::yield();
  }
  std::exception_ptr error = error_;
  state_.store(kIdle, std::memory_order_relaxed);
  return error;
}

void SideThread::serve() {
  using Clock = std::chrono::steady_clock;
  // Tasks come every few microseconds while events are processed; a pause ten times longer
  // than the longest gap between them (a fluid step, a snapshot) puts the thread to sleep.
  constexpr auto kPatience = std::chrono::microseconds(200);
  Clock::time_point idle_since = Clock::now();
  for (unsigned spins = 0;;) {
    int state = state_.load(std::memory_order_acquire);
    if (state == kStop) return;
    if (state == kPosted) {
      if (state_.compare_exchange_strong(state, kRunning, std::memory_order_acquire)) {
        error_ = run_catching(task_, argument_);
        side_runs_.fetch_add(1, std::memory_order_relaxed);
        state_.store(kDone, std::memory_order_release);
      }
      idle_since = Clock::now();
      spins = 0;
      continue;
    }
    relax_cpu();
    if (++spins % 256 != 0 || Clock::now() - idle_since < kPatience) continue;
    // wakes_ is read before sleeping_ is raised: a wake() that sees the thread asleep raises
    // wakes_ after this read, so the wait below returns at once (read after sleeping_, a wake()
    // between the two would be lost and the thread would sleep on until the next task).
    const unsigned wakes = wakes_.load(std::memory_order_seq_cst);
    sleeping_.store(true, std::memory_order_seq_cst);
    state = state_.load(std::memory_order_seq_cst);
    if (state != kPosted && state != kStop) wakes_.wait(wakes, std::memory_order_seq_cst);
    sleeping_.store(false, std::memory_order_seq_cst);
    wake_ups_.fetch_add(1, std::memory_order_relaxed);
    idle_since = Clock::now();
    spins = 0;
  }
}

}  // namespace carom
