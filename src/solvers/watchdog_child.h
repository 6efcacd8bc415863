#pragma once
/// Runs a computation in a forked child process under a stall watchdog.
///
/// Why: CSDP's sdp() can loop forever INSIDE one iteration (seen: ~1 in 1000
/// identification relaxations with perturbobj 0, spinning in copy_mat; its
/// maxiter cap is only checked between iterations), and calls exit() on some
/// errors. A child process can be stopped; a thread cannot.
///
/// The child's stdout goes (line buffered) to a pipe that the parent reads;
/// every output byte counts as progress (CSDP prints one line per iteration
/// when printlevel ≥ 1). Before the first output there is no limit (setup
/// time grows with the problem); after it, the child is killed when it is
/// silent for longer than max(min_stall_seconds, stall_factor × max(the
/// longest silence seen so far, the delay until the first output)). The
/// first delay (setup and the first iteration) scales the patience with the
/// problem, so one slow healthy iteration is not taken for a hang (a SISO
/// n = 400 full-horizon solve, > 1 s per iteration, was once killed after 2 s);
/// callers also raise min_stall_seconds with the problem size. The child writes its result to `result` (an
/// unlinked temporary file shared with the parent) and exits with _exit.

#include <cstdio>
#include <functional>
#include <string>

namespace lpvid {

struct WatchdogOptions {
  double min_stall_seconds = 2.0;
  double stall_factor = 20.0;
  bool echo = false;  ///< copy the child's output to our stdout
};

struct WatchdogOutcome {
  bool finished = false;  ///< the child ran `work` to the end and exited 0
  bool stalled = false;   ///< killed by the watchdog
  double stall_seconds = 0.0;  ///< the silence that triggered the kill
  std::string error;      ///< fork/pipe failure or abnormal exit, in words
};

/// Forks; the child calls work(result) with its stdout redirected, flushes
/// `result` and exits. The parent waits as above. `result` must be open for
/// reading and writing and empty; after a finished run it is rewound.
WatchdogOutcome run_in_watched_child(const std::function<void(std::FILE* result)>& work, std::FILE* result,
                                     const WatchdogOptions& options);

}  // namespace lpvid
