#pragma once
/// `lpvid-verify psd M.txt` (docs/design.md §11.2): decides whether the exact rational
/// symmetric matrix in M.txt is PD, PSD or not PSD.
///
/// Output: the first word is `PD`, `PSD` or `NOT_PSD`, then the reason on the
/// same line; indented detail lines follow (n, which path decided, pivot
/// index, witness, timings). Exit code 0 for PD and PSD, 1 for NOT_PSD, 2 for
/// input that cannot be decided (6 when the operating system could not read
/// an existing file, 8 when the exact path would exceed --max-exact-work,
/// verify/psd/work_limits.h): missing or non-regular file, too large (core/limits.h), bad number text, zero
/// denominator, NaN/inf, ragged or non-square matrix, non-symmetric matrix,
/// out of memory, any other error (message on `err`, never a crash).

#include <iosfwd>
#include <string>

#include "core/exit_codes.h"

namespace lpvid {

struct PsdCommandOptions {
  /// Skip the floating-point filter and the witness check: exact LDLᵀ only.
  bool exact_only = false;
  /// Threads for the exact elimination (≤ 0: hardware concurrency, max 8).
  int threads = 0;
};

/// Exit codes of run_psd_command.
inline constexpr int kPsdExitPsd = kExitOk;
inline constexpr int kPsdExitNotPsd = kExitInvalidated;
inline constexpr int kPsdExitBadInput = kExitBadInput;
inline constexpr int kPsdExitIo = kExitIo;  ///< the file exists but could not be read (core/exit_codes.h)
inline constexpr int kPsdExitWorkLimit = kExitWorkLimit;  ///< the exact path would exceed --max-exact-work

int run_psd_command(const std::string& path, std::ostream& out, std::ostream& err,
                    const PsdCommandOptions& options = {});

}  // namespace lpvid
