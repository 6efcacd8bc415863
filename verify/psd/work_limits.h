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
///  - max_floating_work: the floating cubic steps of the whole check, in
///    multiply-adds, counted apart from max_total_work because their memory
///    is bounded by their order (a few L² doubles), not by their time as the
///    exact numbers' is: the compact dual points' rebuilds (one per class
///    leaf) and the (C1) proof in doubles of one output and one input on a
///    long horizon (verify/certificate/work_budget.h); 1.2·10¹² admits the
///    full horizon of 10 000 samples (docs/exit_codes.md);
///  - max_records: the records one certificate may name.
///
/// The library's own callers (lpvid's builders, merge, oracle) run unlimited;
/// `lpvid-verify` sets the defaults below for each run (--max-dual-order,
/// --max-exact-work, --max-total-work, --max-floating-work, --max-records). Beyond a limit the check throws WorkLimitError and
/// `lpvid-verify` exits with kExitWorkLimit: nothing was decided.

#include <stdexcept>
#include <string>

namespace lpvid {

struct VerifyWorkLimits {
  long max_dual_order = 0;      ///< 0: unlimited
  double max_exact_work = 0;    ///< 0: unlimited
  double max_total_work = 0;    ///< 0: unlimited
  long max_records = 0;         ///< 0: unlimited
  double max_floating_work = 0; ///< 0: unlimited
};

/// `lpvid-verify`'s defaults.
inline constexpr long kDefaultMaxDualOrder = 10000;
inline constexpr double kDefaultMaxExactWork = 4e10;
inline constexpr double kDefaultMaxTotalWork = 2e11;
inline constexpr long kDefaultMaxRecords = 1000;
inline constexpr double kDefaultMaxFloatingWork = 1.2e12;

/// `lpvid-verify`'s defaults, all five.
inline VerifyWorkLimits default_verify_work_limits() {
  return {kDefaultMaxDualOrder, kDefaultMaxExactWork, kDefaultMaxTotalWork, kDefaultMaxRecords,
          kDefaultMaxFloatingWork};
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
/// require_exact_work charges its elimination too. charge_floating_work is
/// the same against max_floating_work (start_total_work zeroes both and
/// restarts the progress clock, verify/psd/check_progress.h).
void start_total_work();
void charge_total_work(double work, const std::string& what);
void charge_floating_work(double work, const std::string& what);
/// The totals charged since start_total_work.
double total_work_charged();
double floating_work_charged();

}  // namespace lpvid
