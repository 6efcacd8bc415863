#include "core/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

#include "core/stop_request.h"

namespace lpvid {

unsigned default_thread_count() { return std::max(1u, std::thread::hardware_concurrency()); }

namespace {
thread_local bool t_in_workers = false;  ///< this thread runs jobs of a parallel_for with several workers
}  // namespace

bool inside_parallel_jobs() { return t_in_workers; }

namespace parallel_detail {

std::size_t worker_count(std::size_t count, unsigned threads) {
  if (threads <= 1 || count <= 1) return std::min<std::size_t>(count, 1);
  return std::min<std::size_t>(threads, count);
}

void run_jobs(std::size_t count, unsigned threads, const std::function<void(std::size_t, std::size_t)>& job) {
  const std::size_t workers = worker_count(count, threads);
  if (workers <= 1) {
    for (std::size_t i = 0; i < count; ++i) {
      check_stop();
      job(0, i);
    }
    return;
  }
  std::vector<std::exception_ptr> errors(count);
  std::atomic<std::size_t> next{0};
  const auto worker = [&](std::size_t w) {
    const bool outer = t_in_workers;
    t_in_workers = true;
    struct Restore {
      bool value;
      ~Restore() { t_in_workers = value; }
    } restore{outer};
    for (std::size_t i = next++; i < count; i = next++) {
      try {
        check_stop();  // a requested stop: no new job starts
        job(w, i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(workers - 1);
  for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(worker, w);
  worker(0);
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace parallel_detail

void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& job) {
  parallel_detail::run_jobs(count, threads, [&job](std::size_t, std::size_t i) { job(i); });
}

}  // namespace lpvid
