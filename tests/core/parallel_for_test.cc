// core/parallel_for.h: every job runs exactly once, results land in their
// own slots (so the order is the sequential one), at most `threads` run at
// once, and the exception of the lowest failing index is the one rethrown.
// parallel_for_with_scratch: the same, and each worker's scratch is its own
// (one thread, one job at a time) and is reused across that worker's jobs.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "core/parallel_for.h"

namespace lpvid {
namespace {

/// The most jobs running at once: a job calls enter() first and leave() last.
struct Concurrency {
  std::atomic<int> running{0}, peak{0};
  void enter() {
    const int now = ++running;
    int p = peak.load();
    while (now > p && !peak.compare_exchange_weak(p, now)) {
    }
  }
  void leave() { --running; }
};

TEST(ParallelFor, EachJobOnceInItsSlotWithBoundedConcurrency) {
  for (const unsigned threads : {1u, 2u, 3u, 8u}) {
    std::vector<int> slot(37, 0);
    Concurrency jobs;
    parallel_for(slot.size(), threads, [&](std::size_t i) {
      jobs.enter();
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      slot[i] += static_cast<int>(i * i);
      jobs.leave();
    });
    for (std::size_t i = 0; i < slot.size(); ++i) EXPECT_EQ(slot[i], static_cast<int>(i * i)) << threads;
    EXPECT_LE(jobs.peak.load(), static_cast<int>(threads));
    EXPECT_GE(jobs.peak.load(), 1);
  }
}

TEST(ParallelFor, RethrowsTheLowestFailingJob) {
  for (const unsigned threads : {1u, 4u}) {
    try {
      parallel_for(20, threads, [](std::size_t i) {
        if (i == 5 || i == 13) throw std::runtime_error("job " + std::to_string(i));
      });
      FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "job 5") << threads;
    }
  }
}

/// A worker's scratch as the jobs see it (the scratches end with the call, so
/// the jobs write down what they saw): its number (given at its first use),
/// the thread that owns it, whether a job is using it now, how many jobs
/// used it, and a buffer the jobs keep using.
struct TestScratch {
  int id = -1;
  std::thread::id owner;
  std::atomic<bool> busy{false};
  std::size_t uses = 0;
  std::vector<long> buffer;
};

/// The result of job i computed in the scratch's buffer (as the residue
/// matrices of verify/psd/psd_modular.cc are): Σ_{t ≤ i} t·(t + 1).
long scratch_job(std::size_t i, std::vector<long>& buffer) {
  buffer.assign(i + 1, 0);
  for (std::size_t t = 0; t <= i; ++t) buffer[t] = static_cast<long>(t * (t + 1));
  long sum = 0;
  for (long x : buffer) sum += x;
  return sum;
}

TEST(ParallelForWithScratch, OneScratchPerWorkerReusedNeverShared) {
  constexpr std::size_t kJobs = 41;
  std::vector<long> sequential(kJobs);
  std::vector<long> buffer;
  for (std::size_t i = 0; i < kJobs; ++i) sequential[i] = scratch_job(i, buffer);
  for (const unsigned threads : {1u, 2u, 3u, 8u}) {
    std::vector<long> result(kJobs, -1);
    std::vector<int> scratch_of(kJobs, -1);          // the number of the scratch job i got
    std::vector<std::size_t> use_of(kJobs, 0);       // job i was its scratch's use number use_of[i]
    std::vector<std::thread::id> thread_of(kJobs);   // the thread that ran job i
    std::atomic<int> scratches{0}, shared{0};
    Concurrency jobs;
    parallel_for_with_scratch<TestScratch>(kJobs, threads, [&](std::size_t i, TestScratch& s) {
      if (s.busy.exchange(true)) ++shared;  // another job is using this scratch right now
      if (s.id < 0) {
        s.id = scratches++;
        s.owner = std::this_thread::get_id();
      }
      if (s.owner != std::this_thread::get_id()) ++shared;  // a second thread got this scratch
      jobs.enter();
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      result[i] = scratch_job(i, s.buffer);
      scratch_of[i] = s.id;
      use_of[i] = ++s.uses;
      thread_of[i] = std::this_thread::get_id();
      jobs.leave();
      s.busy = false;
    });
    EXPECT_EQ(result, sequential) << threads;
    EXPECT_EQ(shared.load(), 0) << threads;
    EXPECT_LE(jobs.peak.load(), static_cast<int>(threads)) << threads;
    // No more scratches than workers; the jobs of one scratch ran on one
    // thread and were its uses 1, 2, … in the order they were handed out
    // (increasing index): the scratch is kept from one job to the next.
    ASSERT_GE(scratches.load(), 1) << threads;
    EXPECT_LE(static_cast<std::size_t>(scratches.load()), std::min<std::size_t>(threads, kJobs)) << threads;
    std::vector<std::size_t> uses(static_cast<std::size_t>(scratches.load()), 0);
    std::vector<std::thread::id> owner(uses.size());
    for (std::size_t i = 0; i < kJobs; ++i) {
      ASSERT_GE(scratch_of[i], 0) << threads << " job " << i;
      const auto id = static_cast<std::size_t>(scratch_of[i]);
      EXPECT_EQ(use_of[i], ++uses[id]) << threads << " job " << i;
      if (uses[id] == 1) owner[id] = thread_of[i];
      EXPECT_EQ(thread_of[i], owner[id]) << threads << " job " << i;
    }
    if (threads == 1) {
      EXPECT_EQ(scratches.load(), 1);
      EXPECT_EQ(uses[0], kJobs);
      EXPECT_EQ(owner[0], std::this_thread::get_id());  // run in order on the calling thread
    }
  }
}

TEST(ParallelForWithScratch, RethrowsTheLowestFailingJob) {
  for (const unsigned threads : {1u, 4u}) {
    std::atomic<int> ran{0};
    try {
      parallel_for_with_scratch<std::vector<int>>(20, threads, [&](std::size_t i, std::vector<int>& scratch) {
        ++ran;
        scratch.push_back(static_cast<int>(i));
        if (i == 5 || i == 13) throw std::runtime_error("job " + std::to_string(i));
      });
      FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "job 5") << threads;
    }
    // Sequential: the loop ends at the first throw; parallel: every job runs.
    EXPECT_EQ(ran.load(), threads == 1 ? 6 : 20) << threads;
  }
}

TEST(ParallelForWithScratch, NoJobsNoScratch) {
  int calls = 0;
  parallel_for_with_scratch<std::vector<int>>(0, 4, [&](std::size_t, std::vector<int>&) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(ParallelFor, DefaultThreadCountIsPositive) { EXPECT_GE(default_thread_count(), 1u); }

}  // namespace
}  // namespace lpvid

namespace lpvid {
namespace {

TEST(ParallelFor, WorkersKnowTheyAreInsideParallelJobs) {
  EXPECT_FALSE(inside_parallel_jobs());
  std::vector<int> inside(8, -1);
  parallel_for(inside.size(), 2, [&](std::size_t i) { inside[i] = inside_parallel_jobs() ? 1 : 0; });
  for (const int v : inside) EXPECT_EQ(v, 1);
  EXPECT_FALSE(inside_parallel_jobs());  // restored on the calling thread
  parallel_for(inside.size(), 1, [&](std::size_t i) { inside[i] = inside_parallel_jobs() ? 1 : 0; });
  for (const int v : inside) EXPECT_EQ(v, 0);  // one worker: the cores are free
}

}  // namespace
}  // namespace lpvid
