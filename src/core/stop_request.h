#pragma once
/// A request to stop the running command, made from another thread: the
/// cooperative Ctrl-C of an in-process caller (the Python module runs the
/// command line in its own process and must not be ended by it). The flag is
/// process-wide and atomic; request_stop() only sets it (no lock, safe from
/// any thread while a run holds its own locks). The long loops notice it at
/// their next check_deadline() (core/deadline.h), which throws Interrupted;
/// the command lines map that to exit 130 (kExitInterrupted) and remove the
/// run's outputs, as for Ctrl-C of the programs. A run that is not stopped
/// never reads anything but the flag, so its answer is unchanged.

#include <stdexcept>

namespace lpvid {

/// A run ended before its answer: the user's --timeout passed (TimedOut,
/// core/deadline.h) or a stop was requested (Interrupted). Stages that turn
/// their own failures into a reported reason let it through: it ends the
/// whole command.
class RunStopped : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Thrown by check_deadline() once request_stop() was called.
class Interrupted : public RunStopped {
 public:
  Interrupted() : RunStopped("interrupted") {}
};

/// Asks the running command to stop at its next check (any thread).
void request_stop();

/// Withdraws the request: the next run goes on normally.
void clear_stop();

/// Whether a stop was requested and not cleared.
bool stop_requested();

/// Throws Interrupted when a stop was requested.
void check_stop();

}  // namespace lpvid
