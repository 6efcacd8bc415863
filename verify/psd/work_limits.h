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
///    loaded 2-core machine (n = 400 with 16-digit entries: 1.7·10¹⁰, 7 s);
///  - max_total_work: the whole check of one certificate or matrix, in the
///    same operations: the parts a certificate declares (dual points, class
///    leaves, records, data bytes, the exact simulation with the growth of
///    its digits; verify/certificate/work_budget.h) charged before their
///    work starts, and every exact elimination when its estimate is known;
///  - max_records: the records one certificate may name.
///
/// The library's own callers (lpvid's builders, merge, oracle) run unlimited;
/// `lpvid-verify` sets the defaults below for each run (--max-dual-order,
/// --max-exact-work, --max-total-work, --max-records). Beyond a limit the check throws WorkLimitError and
/// `lpvid-verify` exits with kExitWorkLimit: nothing was decided.

#include <stdexcept>
#include <string>

namespace lpvid {

struct VerifyWorkLimits {
  long max_dual_order = 0;      ///< 0: unlimited
  double max_exact_work = 0;    ///< 0: unlimited
  double max_total_work = 0;    ///< 0: unlimited
  long max_records = 0;         ///< 0: unlimited
};

/// `lpvid-verify`'s defaults.
inline constexpr long kDefaultMaxDualOrder = 2048;
inline constexpr double kDefaultMaxExactWork = 4e10;
inline constexpr double kDefaultMaxTotalWork = 1e11;
inline constexpr long kDefaultMaxRecords = 1000;

/// `lpvid-verify`'s defaults, all four.
inline VerifyWorkLimits default_verify_work_limits() {
  return {kDefaultMaxDualOrder, kDefaultMaxExactWork, kDefaultMaxTotalWork, kDefaultMaxRecords};
}

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

/// The running total of one check against max_total_work: start_total_work
/// sets it to zero; charge_total_work adds `work` operations of the part
/// `what` ("the exact simulation of 40000 rows", ...) before that part
/// starts and throws WorkLimitError naming it, the total and the limit when
/// the total would exceed it. Nothing is counted while the limit is 0.
/// require_exact_work charges its elimination too.
void start_total_work();
void charge_total_work(double work, const std::string& what);
/// The total charged since start_total_work.
double total_work_charged();

}  // namespace lpvid
