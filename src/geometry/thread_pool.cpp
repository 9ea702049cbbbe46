#include "geometry/thread_pool.hpp"

#include "base/precondition.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace sweep {

namespace {

std::atomic<int> chosen_workers{0};  // set_worker_count's; 0: none

}  // namespace

int default_worker_count() {
  static const int count = [] {
    if (const char* text = std::getenv("SWEEP_THREADS")) {
      char* end = nullptr;
      const long n = std::strtol(text, &end, 10);
      if (end != text && *end == '\0' && n >= 1 && n <= kMaxWorkers) return static_cast<int>(n);
    }
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  }();
  return count;
}

int worker_count() {
  const int chosen = chosen_workers.load(std::memory_order_relaxed);
  return chosen > 0 ? chosen : default_worker_count();
}

void set_worker_count(int threads) {
  SWEEP_EXPECTS(threads >= 1 && threads <= kMaxWorkers, "1 <= threads <= kMaxWorkers");
  chosen_workers.store(threads, std::memory_order_relaxed);
}

void parallel_chunks(std::size_t count, std::size_t chunk, int threads,
                     const std::function<void(std::size_t begin, std::size_t end, int worker)>& body) {
  chunk = std::max<std::size_t>(chunk, 1);
  const std::size_t chunks = (count + chunk - 1) / chunk;
  const auto used = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), chunks));
  if (used <= 1) {
    for (std::size_t begin = 0; begin < count; begin += chunk) body(begin, std::min(count, begin + chunk), 0);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto run = [&](int worker) {
    try {
      for (std::size_t i = next++; i < chunks && !failed.load(std::memory_order_relaxed); i = next++) {
        const std::size_t begin = i * chunk;
        body(begin, std::min(count, begin + chunk), worker);
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
      failed = true;
    }
  };
  std::vector<std::thread> helpers;
  helpers.reserve(static_cast<std::size_t>(used - 1));
  for (int worker = 1; worker < used; ++worker) {
    try {
      helpers.emplace_back(run, worker);
    } catch (const std::system_error&) {
      break;  // no more threads to be had: the ones started (and this one) do the work
    }
  }
  run(0);
  for (std::thread& helper : helpers) helper.join();
  if (error) std::rethrow_exception(error);
}

void run_side_by_side(const std::vector<std::function<void()>>& tasks, int threads) {
  parallel_chunks(tasks.size(), 1, threads, [&tasks](std::size_t begin, std::size_t, int) { tasks[begin](); });
}

}  // namespace sweep
