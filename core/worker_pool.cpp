#include "core/worker_pool.hpp"

#include <cstdlib>
#ifdef __linux__
#include <sched.h>
#endif
#include <stdexcept>
#include <string>

namespace carom {

namespace {
/// Chunk k of T over [0, n): [k n / T, (k + 1) n / T).
std::size_t chunk_start(std::size_t n, int k, int threads) {
  return n * static_cast<std::size_t>(k) / static_cast<std::size_t>(threads);
}
}  // namespace

WorkerPool::WorkerPool(int threads) {
  if (threads < 1) throw std::invalid_argument("WorkerPool: threads must be >= 1");
  workers_.reserve(static_cast<std::size_t>(threads - 1));
  for (int k = 1; k < threads; ++k) workers_.emplace_back([this, k] { work(k); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  start_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void WorkerPool::for_chunks(std::size_t n, const std::function<void(std::size_t, std::size_t)>& body) {
  const int threads = this->threads();
  if (threads == 1) {
    body(0, n);
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    body_ = &body;
    n_ = n;
    pending_ = threads - 1;
    error_ = nullptr;
    ++generation_;
  }
  start_.notify_all();
  std::exception_ptr own;
  try {
    body(0, chunk_start(n, 1, threads));
  } catch (...) {
    own = std::current_exception();
  }
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [this] { return pending_ == 0; });
  body_ = nullptr;
  if (own) std::rethrow_exception(own);
  if (error_) std::rethrow_exception(error_);
}

void WorkerPool::work(int k) {
  unsigned long long seen = 0;
  for (;;) {
    const std::function<void(std::size_t, std::size_t)>* body = nullptr;
    std::size_t n = 0;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      start_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      body = body_;
      n = n_;
    }
    std::exception_ptr error;
    try {
      (*body)(chunk_start(n, k, threads()), chunk_start(n, k + 1, threads()));
    } catch (...) {
      error = std::current_exception();
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (error && !error_) error_ = error;
      --pending_;
    }
    done_.notify_one();
  }
}

int WorkerPool::default_threads() {
  if (const char* text = std::getenv("CAROM_THREADS")) {
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (end != text && *end == '\0' && value >= 1 && value <= 1024) return static_cast<int>(value);
    throw std::invalid_argument("CAROM_THREADS = \"" + std::string(text) +
                                "\": must be an integer from 1 to 1024 (threads of one run)");
  }
#ifdef __linux__
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof(allowed), &allowed) == 0 && CPU_COUNT(&allowed) > 0)
    return CPU_COUNT(&allowed);
#endif
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware == 0 ? 1 : static_cast<int>(hardware);
}

}  // namespace carom
