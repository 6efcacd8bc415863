#pragma once
/// The user's wall-clock limit on a whole command (`--timeout SECONDS`): the
/// only wall clock that may end a computation. It never changes an answer;
/// it only stops a run before it has one, reported as "timed out" with its
/// own exit code (kExitTimedOut, 124 as GNU timeout's) and with the run's
/// outputs removed. Every other limit counts work (iterations, Newton steps,
/// a solver child's CPU time: solvers/watchdog_child.h), so a loaded machine
/// gives the same results as a quiet one, only later.
///
/// Long loops call check_deadline() between steps (barrier Newton steps,
/// the watched solver's polling, bound windows, fits); a step in progress
/// finishes first. The executables add a backstop (enforce_deadline in
/// core/file_io.h) for a step that runs long without a check.
///
/// check_deadline() is also where a stop requested by another thread
/// (core/stop_request.h) is noticed: it throws Interrupted first.

#include <string>

#include "core/stop_request.h"

namespace lpvid {

/// Thrown by check_deadline once the deadline has passed.
class TimedOut : public RunStopped {
 public:
  using RunStopped::RunStopped;
};

/// Sets the deadline `seconds` from now (process-wide); seconds ≤ 0 or not
/// finite clears it.
void set_deadline(double seconds);

/// No deadline (the state at start-up).
void clear_deadline();

/// The --timeout given to set_deadline, 0 when there is none.
double deadline_timeout_seconds();

/// Seconds until the deadline (negative once passed); +∞ without one.
double seconds_to_deadline();

/// True once a set deadline has passed.
bool deadline_passed();

/// "timed out after N s (--timeout N)", the message of TimedOut.
std::string timed_out_message();

/// Throws Interrupted once a stop was requested (core/stop_request.h), and
/// TimedOut (timed_out_message, then " while " + `stage` when given) once
/// the deadline has passed.
void check_deadline(const char* stage = nullptr);

}  // namespace lpvid
