// core/parallel_for.h: every job runs exactly once, results land in their
// own slots (so the order is the sequential one), at most `threads` run at
// once, and the exception of the lowest failing index is the one rethrown.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/parallel_for.h"

namespace lpvid {
namespace {

TEST(ParallelFor, EachJobOnceInItsSlotWithBoundedConcurrency) {
  for (const unsigned threads : {1u, 2u, 3u, 8u}) {
    std::vector<int> slot(37, 0);
    std::atomic<int> running{0}, peak{0};
    parallel_for(slot.size(), threads, [&](std::size_t i) {
      const int now = ++running;
      int p = peak.load();
      while (now > p && !peak.compare_exchange_weak(p, now)) {
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      slot[i] += static_cast<int>(i * i);
      --running;
    });
    for (std::size_t i = 0; i < slot.size(); ++i) EXPECT_EQ(slot[i], static_cast<int>(i * i)) << threads;
    EXPECT_LE(peak.load(), static_cast<int>(threads));
    EXPECT_GE(peak.load(), 1);
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

TEST(ParallelFor, DefaultThreadCountIsPositive) { EXPECT_GE(default_thread_count(), 1u); }

}  // namespace
}  // namespace lpvid
