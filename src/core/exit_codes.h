#pragma once
/// The exit codes of both programs, in one table (docs/exit_codes.md).
/// `lpvid` reports the outcome of a command; `lpvid-verify` reports whether
/// the claim it was given holds: 0 the certificate's claim holds / the
/// matrix is PD or PSD, 1 it does not hold / NOT_PSD (a false claim is never
/// code 0), 2 and 6 as for lpvid, 8 a check refused before it starts
/// because it would exceed a work limit (--max-dual-order,
/// --max-exact-work, --max-total-work, --max-floating-work, --max-records;
/// neither answer). `lpvid oracle` judges another
/// implementation: 1 a claim of it was refuted (checked exactly), 3 it gave
/// no usable answer for some case (or, with --strict, a suboptimal one).

namespace lpvid {

enum ExitCode {
  kExitOk = 0,           ///< bounds found and verified (lpvid-verify: the claim holds, PD/PSD)
  kExitInvalidated = 1,  ///< invalidated at the given bounds, checked exactly (lpvid-verify: the claim does not hold, NOT_PSD; oracle: a claim refuted)
  kExitBadInput = 2,     ///< missing, malformed or too large input (core/limits.h), bad options
  kExitSolver = 3,       ///< the SDP backend failed (no bound is reported; oracle: the outside command gave no usable answer)
  kExitNotVerified = 4,  ///< bounds were computed but the exact check did not accept them
  kExitUndecided = 5,    ///< fixed bounds: neither consistency nor invalidation could be certified
  kExitIo = 6,           ///< an existing input could not be read or an output could not be written (core/file_io.h)
  kExitWorkLimit = 8,    ///< lpvid-verify: the check would exceed a work limit (verify/psd/work_limits.h); nothing was decided
  kExitTimedOut = 124,   ///< the user's --timeout passed first: no answer, the run's outputs removed (core/deadline.h; GNU timeout's code)
  kExitInterrupted = 130,  ///< SIGINT/SIGTERM: the run's outputs were removed (core/file_io.h)
};

}  // namespace lpvid
