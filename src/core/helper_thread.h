#pragma once
/// One persistent helper thread for fork-join steps too short to start a
/// thread for (one column of an LDLᵀ factorisation takes microseconds):
/// run(side, main) runs `side` on the helper and `main` on the caller and
/// returns when both are done. The users split work so that every number is
/// computed by the same operations in the same order as by one thread (each
/// job writes its own entries), so no answer depends on whether a helper
/// exists: dense/split_factorisations.h and the Newton step of
/// lmi/delta_form_barrier.cc. Hand-over by spinning on atomics (a
/// condition variable's wake-up, ~50 µs here, cost more than an LDLᵀ column
/// update saves); the helper sleeps after ~50 µs without work.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

namespace lpvid {

class HelperThread {
 public:
  HelperThread();
  ~HelperThread();
  HelperThread(const HelperThread&) = delete;
  HelperThread& operator=(const HelperThread&) = delete;
  /// side() on the helper, main() here; both run to the end even if one
  /// throws, then main's exception is rethrown, else side's.
  void run(const std::function<void()>& side, const std::function<void()>& main);

 private:
  void loop();
  /// Waits for job number `seen + 1` (or stop): spins, then sleeps. False on stop.
  bool wait_for_job(std::uint64_t seen);
  std::mutex mutex_;
  std::condition_variable wake_;
  const std::function<void()>* job_ = nullptr;
  std::atomic<std::uint64_t> posted_{0}, completed_{0};
  std::atomic<bool> sleeping_{false}, stop_{false};
  std::exception_ptr error_;
  std::thread thread_;
};

/// A helper for a step of order `order` ≥ 1024 on a machine with two or more
/// cores, outside the jobs of a parallel_for (whose workers already take the
/// cores); nullptr otherwise. The rule of the verifier's dense steps (the
/// compact dual's rebuild, the rigorous filter's Cholesky).
std::unique_ptr<HelperThread> helper_for_order(long order);

/// side() and main() on `helper` when there is one, else main() then side().
void fork_join(HelperThread* helper, const std::function<void()>& side, const std::function<void()>& main);

}  // namespace lpvid
