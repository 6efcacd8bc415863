#pragma once
/// Limits on the work of one exact check, so that no certificate or matrix
/// keeps `lpvid-verify` busy for longer than the data it names justify
/// (docs/exit_codes.md). Counted in operations, never
/// in seconds: the same input gives the same answer on any machine.
///
///  - max_dual_order: the order L·ny of the matrix U that a compact dual
///    certificate ("dual_delta_path") makes the verifier rebuild in floating
///    point (O(order³) operations, O(order²) memory: 2048 ≈ 14 s and 0.2 GB
///    measured on a loaded 2-core machine; the project writes up to 1600);
///  - max_exact_work: the operations of one exact elimination, estimated
///    before it starts as (primes of 31 bits that Hadamard's bound needs) ×
///    n³/3 modular multiply-adds (verify/psd/exact_psd.h); 4·10¹⁰ ≈ 17 s on a
///    loaded 2-core machine (n = 400 with 16-digit entries: 1.7·10¹⁰, 7 s).
///
/// The library's own callers (lpvid's builders, merge, oracle) run unlimited;
/// `lpvid-verify` sets the defaults below for each run (--max-dual-order,
/// --max-exact-work). Beyond a limit the check throws WorkLimitError and
/// `lpvid-verify` exits with kExitWorkLimit: nothing was decided.

#include <stdexcept>
#include <string>

namespace lpvid {

struct VerifyWorkLimits {
  long max_dual_order = 0;      ///< 0: unlimited
  double max_exact_work = 0;    ///< 0: unlimited
};

/// `lpvid-verify`'s defaults.
inline constexpr long kDefaultMaxDualOrder = 2048;
inline constexpr double kDefaultMaxExactWork = 4e10;

/// The process-wide limits (unlimited until a command line sets them).
VerifyWorkLimits& verify_work_limits();

/// A check that would exceed a limit; what() names the limit and its option.
class WorkLimitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Throws WorkLimitError when an exact elimination of an n×n integer matrix
/// whose Hadamard bound has `hadamard_bits` bits exceeds max_exact_work.
void require_exact_work(long n, double hadamard_bits);

/// Throws WorkLimitError when a compact dual point of order L·ny exceeds max_dual_order.
void require_dual_order(long order);

}  // namespace lpvid
