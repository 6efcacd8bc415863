#pragma once
/// Runs a computation in a forked child process under a stall watchdog that
/// counts the child's CPU time, never the wall clock.
///
/// Why a watchdog: CSDP's sdp() can loop forever INSIDE one iteration (seen:
/// ~1 in 1000 identification relaxations with perturbobj 0, spinning in
/// copy_mat; its maxiter cap is only checked between iterations), and calls
/// exit() on some errors. A child process can be stopped; a thread cannot.
///
/// Why CPU time: the watchdog used to stop a child that printed nothing for
/// max(2 s, 20 × the longest silence) of wall-clock time. On a loaded machine
/// (2 cores, load 4–15) a healthy iteration waits for a core, its silence
/// grows with the load, and the watchdog stopped 4 of 10 window bounds of the
/// tanks demo: the load decided the result. The failure it exists for is a
/// spin, which burns CPU without end; a healthy iteration burns a bounded
/// amount of CPU that does not depend on how long it waited for a core. So
/// the budget is the child's own CPU time (its POSIX CPU clock,
/// clock_getcpuclockid: user + system time of all its threads), which a
/// loaded machine only spreads out over more wall time.
///
/// Why this budget: one iteration's cost is set by the problem (the Schur
/// matrix and the factorisations), and CSDP's iterations cost about the same
/// within a run. The CPU time the child spent up to its first output (setup
/// and the first iteration) measures that cost on this machine, so the budget
/// per iteration is
///     max(min_stall_cpu_seconds, stall_factor × max(CPU time to the first
///         output, the most CPU time between two outputs so far)),
/// and callers raise min_stall_cpu_seconds with the problem's flop count
/// (solvers/csdp_backend.cc). A fixed budget of seconds could not serve both
/// n = 10 and n = 400; a budget of iterations cannot see inside one; the
/// first iteration's CPU time scales with both and is measured, not guessed.
/// A spin exceeds any finite budget and a healthy iteration stays a factor
/// 20 below it (CPU time varies by a few tens of percent with cache
/// contention, not by 20×), so the outcome is the same on a quiet and on a
/// loaded machine. Before the first output there is no budget (setup grows
/// with the problem; CSDP's spin happens between iterations' outputs).
///
/// The wall clock is read only to decide how often to look (at most every
/// second) and for the user's --timeout (core/deadline.h): past it the child
/// is killed and the outcome says timed_out.
///
/// The child's stdout goes (line buffered) to a pipe that the parent reads;
/// every output byte counts as progress (CSDP prints one line per iteration
/// when printlevel ≥ 1). The child writes its result to `result` (an unlinked
/// temporary file shared with the parent) and exits with _exit; it is killed
/// with the parent (PR_SET_PDEATHSIG), so an interrupted or timed-out run
/// leaves no solver running.

#include <cstdio>
#include <functional>
#include <string>

namespace lpvid {

struct WatchdogOptions {
  double min_stall_cpu_seconds = 2.0;  ///< floor of the CPU budget per output
  double stall_factor = 20.0;          ///< budget = factor × the costliest step so far (CPU s)
  bool echo = false;                   ///< copy the child's output to our stdout
};

struct WatchdogOutcome {
  bool finished = false;   ///< the child ran `work` to the end and exited 0
  bool stalled = false;    ///< killed by the watchdog: its CPU budget without output was spent
  bool timed_out = false;  ///< killed because the user's --timeout passed (core/deadline.h)
  double stall_cpu_seconds = 0.0;  ///< the CPU time without output that triggered the kill
  double budget_cpu_seconds = 0.0;  ///< the budget it exceeded
  std::string error;       ///< fork/pipe failure or abnormal exit, in words
};

/// Forks; the child calls work(result) with its stdout redirected, flushes
/// `result` and exits. The parent waits as above. `result` must be open for
/// reading and writing and empty; after a finished run it is rewound.
WatchdogOutcome run_in_watched_child(const std::function<void(std::FILE* result)>& work, std::FILE* result,
                                     const WatchdogOptions& options);

}  // namespace lpvid
