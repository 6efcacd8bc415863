#include "core/helper_thread.h"

#include "core/parallel_for.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace lpvid {

namespace {

/// A short pause in a spin loop (frees the pipeline for the sibling thread).
inline void spin_pause() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#else
  std::this_thread::yield();
#endif
}

constexpr int kSpins = 20000;  // pauses before the helper sleeps (~50 µs)

}  // namespace

HelperThread::HelperThread() : thread_([this] { loop(); }) {}

HelperThread::~HelperThread() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_.store(true);
  }
  wake_.notify_one();
  thread_.join();
}

bool HelperThread::wait_for_job(std::uint64_t seen) {
  for (int i = 0; i < kSpins; ++i) {
    if (posted_.load(std::memory_order_acquire) > seen) return true;
    if (stop_.load(std::memory_order_relaxed)) return false;
    spin_pause();
  }
  std::unique_lock<std::mutex> lock(mutex_);
  sleeping_.store(true);  // seq_cst, against run()'s store of posted_ then load of sleeping_
  wake_.wait(lock, [&] { return stop_.load() || posted_.load() > seen; });
  sleeping_.store(false);
  return !stop_.load();
}

void HelperThread::loop() {
  for (std::uint64_t seen = 0;; ++seen) {
    if (!wait_for_job(seen)) return;
    std::exception_ptr error;
    try {
      (*job_)();
    } catch (...) {
      error = std::current_exception();
    }
    error_ = error;
    completed_.store(seen + 1, std::memory_order_release);
  }
}

void HelperThread::run(const std::function<void()>& side, const std::function<void()>& main) {
  job_ = &side;
  error_ = nullptr;
  const std::uint64_t number = posted_.load(std::memory_order_relaxed) + 1;
  posted_.store(number);  // seq_cst: the helper's job_ and error_ writes are published with it
  if (sleeping_.load()) {
    std::lock_guard<std::mutex> lock(mutex_);
    wake_.notify_one();
  }
  std::exception_ptr main_error;
  try {
    main();
  } catch (...) {
    main_error = std::current_exception();
  }
  for (long spins = 0; completed_.load(std::memory_order_acquire) < number; ++spins)
    if (spins < kSpins) spin_pause();
    else std::this_thread::yield();  // the helper is descheduled (a loaded machine): give the core away
  if (main_error) std::rethrow_exception(main_error);
  if (error_) std::rethrow_exception(error_);
}

void fork_join(HelperThread* helper, const std::function<void()>& side, const std::function<void()>& main) {
  if (helper != nullptr) {
    helper->run(side, main);
    return;
  }
  main();
  side();
}

std::unique_ptr<HelperThread> helper_for_order(long order) {
  return order >= 1024 && default_thread_count() >= 2 && !inside_parallel_jobs() ? std::make_unique<HelperThread>()
                                                                                   : nullptr;
}

}  // namespace lpvid
