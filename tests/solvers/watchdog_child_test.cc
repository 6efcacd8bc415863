// The stall watchdog counts the watched child's CPU time, not the wall clock
// (solvers/watchdog_child.h). A child that waits without using the CPU
// stands for a healthy solve on a loaded machine (its iteration waits for a
// core); a child that spins stands for CSDP looping inside one iteration.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <ctime>
#include <functional>
#include <cstdio>
#include <string>

#include "core/deadline.h"
#include "solvers/watchdog_child.h"

namespace lpvid {
namespace {

/// Burns about `seconds` of CPU time (the process's own CPU clock).
void burn_cpu(double seconds) {
  const std::clock_t start = std::clock();
  volatile double x = 0;
  while (static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC < seconds) x = x + 1.0;
}

struct WatchedRun {
  WatchdogOutcome outcome;
  std::string result;
  double wall_seconds = 0;
};

WatchedRun run_watched(const std::function<void(std::FILE*)>& work, const WatchdogOptions& o) {
  std::FILE* f = std::tmpfile();
  EXPECT_NE(f, nullptr);
  const auto t0 = std::chrono::steady_clock::now();
  WatchedRun r;
  r.outcome = run_in_watched_child(work, f, o);
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  char buf[64] = {};
  if (r.outcome.finished && std::fgets(buf, sizeof buf, f) != nullptr) r.result = buf;
  std::fclose(f);
  return r;
}

// Failed before (wall clock): silent for 3 s after its first line, the child
// was killed at max(2 s, 20 × ~0 s) = 2 s. Waiting is not spinning: a
// healthy iteration that waits for a core spends no CPU time.
TEST(WatchdogChild, LongWallClockSilenceWithoutCpuIsNotAStall) {
  WatchdogOptions o;  // defaults: 2 CPU s floor, factor 20
  const WatchedRun r = run_watched(
      [](std::FILE* f) {
        std::printf("iteration 1\n");
        std::fflush(stdout);
        ::sleep(3);
        std::printf("iteration 2\n");
        std::fputs("done", f);
      },
      o);
  EXPECT_TRUE(r.outcome.finished) << r.outcome.error;
  EXPECT_FALSE(r.outcome.stalled);
  EXPECT_EQ(r.result, "done");
  EXPECT_GE(r.wall_seconds, 3.0);
}

// A spin inside one iteration burns CPU without output: stopped once its CPU
// time without output exceeds the budget (here the floor, 0.3 CPU s).
TEST(WatchdogChild, SpinWithoutOutputIsStoppedByItsCpuBudget) {
  WatchdogOptions o;
  o.min_stall_cpu_seconds = 0.3;
  const WatchedRun r = run_watched(
      [](std::FILE*) {
        std::printf("iteration 1\n");
        std::fflush(stdout);
        for (;;) burn_cpu(1.0);
      },
      o);
  EXPECT_FALSE(r.outcome.finished);
  EXPECT_TRUE(r.outcome.stalled);
  EXPECT_GE(r.outcome.stall_cpu_seconds, 0.3);
  EXPECT_DOUBLE_EQ(r.outcome.budget_cpu_seconds, 0.3);
}

// The budget scales with the costliest step seen: steps of ~0.1 CPU s with a
// factor 20 allow ~2 CPU s; a step of 0.5 CPU s is healthy (not stopped)
// although it is five times the floor of 0.1.
TEST(WatchdogChild, BudgetScalesWithTheCostliestStep) {
  WatchdogOptions o;
  o.min_stall_cpu_seconds = 0.1;
  const WatchedRun r = run_watched(
      [](std::FILE* f) {
        for (int i = 0; i < 3; ++i) {
          burn_cpu(0.1);
          std::printf("iteration %d\n", i);
          std::fflush(stdout);
        }
        burn_cpu(0.5);
        std::fputs("done", f);
      },
      o);
  EXPECT_TRUE(r.outcome.finished) << r.outcome.error;
  EXPECT_EQ(r.result, "done");
}

// The user's --timeout (core/deadline.h) is the one wall clock: it stops a
// child that is neither spinning nor done, and says so.
TEST(WatchdogChild, DeadlineStopsTheChild) {
  set_deadline(0.5);
  const WatchedRun r = run_watched(
      [](std::FILE*) {
        std::printf("iteration 1\n");
        std::fflush(stdout);
        ::sleep(30);
      },
      WatchdogOptions{});
  clear_deadline();
  EXPECT_TRUE(r.outcome.timed_out);
  EXPECT_FALSE(r.outcome.finished);
  EXPECT_LT(r.wall_seconds, 10.0);
}

}  // namespace
}  // namespace lpvid
