#pragma once
/// Exact positive (semi)definiteness of a rational symmetric matrix
/// (docs/design.md §10.2: "PSD/PD of a rational symmetric matrix by exact LDLᵀ with
/// symmetric pivoting (a zero pivot needs a zero row), no tolerance anywhere";
/// docs/design.md §13.3: the verifier returns a verdict, never a float).
///
/// Entry points:
///  - decide_psd_exact: the exact decision. Multi-modular symmetric
///    elimination of the integer matrix L·M (L = lcm of the denominators, a
///    positive scaling, so the verdict is that of M) modulo 31-bit primes,
///    lifted by the Chinese remainder theorem with enough primes for
///    Hadamard's bound: deterministic, exact, no floating point. In the rare
///    case where the first prime divides a nonzero Schur diagonal, and when
///    the bound needs more 31-bit primes than exist (about 7.8·10⁵), it falls
///    back to decide_psd_bareiss (the reason says so): it never gives up.
///    Before that, a screen decides the leading principal submatrices of
///    sizes 2, 4, 8, … ≤ n/4 (at most ~0.5 % of the cost of the full
///    decision): a principal submatrix of a PSD matrix is PSD, so a NOT_PSD
///    block ends the decision with its witness padded by zeros. PD and PSD
///    verdicts always come from the decision on all of M.
///  - decide_psd_bareiss: fraction-free (Bareiss) symmetric elimination on
///    GMP integers, in place. Exact; slower for large n (bench/README.md).
///  - decide_psd_rational_ldlt: textbook LDLᵀ over GMP rationals, the slowest;
///    kept as an independent reference that the tests compare against.
///  - decide_psd: filter first (verify/psd/psd_filter.h: a rigorous floating-point
///    proof of PD, and a floating candidate for vᵀMv < 0 that is then checked
///    exactly), then decide_psd_exact when neither is conclusive.
///
/// Pivot rule of decide_psd_bareiss and decide_psd_rational_ldlt (identical
/// verdict, pivot_index, rank and step): at elimination step k let S be the
/// current Schur complement (rows/columns not yet pivoted, in original order).
///   1. If some diagonal S_ii < 0: NOT_PSD (the first such i). Witness below.
///   2. Else pivot on the first (smallest original index) i with S_ii > 0.
///   3. If every S_ii = 0: if S has a nonzero entry S_ij (first in row-major
///      order) the 2×2 principal minor [[0, b], [b, 0]], b ≠ 0, is indefinite:
///      NOT_PSD. If S = 0 exactly: PSD of rank k (PD if k = n).
/// decide_psd_exact pivots on the first remaining row (smallest original
/// index) whose Schur diagonal is nonzero (modulo a prime, hence exactly) and
/// reports the first negative pivot in that order; its verdict is the same,
/// its pivot_index (and step) may differ when M is not PSD, in particular when
/// the screen decided on a leading block (then they are that block's, whose
/// rows are the first rows of M).
/// Witness: with P the pivoted rows so far, x a vector on the remaining rows
/// with xᵀSx < 0 (x = e_i in case 1, x = e_i − sign(b)·e_j in case 3),
///   v = [ −M_PP⁻¹ M_P· x ; x ]   (the back-substitution v = L⁻ᵀ x),
/// so that vᵀMv = xᵀSx < 0. It is returned scaled to integers (a positive
/// multiple), in the original row order, and re-checked exactly before return.

#include <string>

#include "core/scalar.h"

namespace lpvid {

enum class PsdVerdict { kPositiveDefinite, kPositiveSemidefinite, kNotPsd };

/// Which path decided a PsdResult.
enum class PsdMethod {
  kFloatingFilter,  ///< psd_filter: Rump's verified floating Cholesky proved PD
  kWitnessCheck,    ///< a floating candidate v was checked exactly: vᵀMv < 0
  kExactLdlt,       ///< exact fraction-free LDLᵀ (or the rational reference)
};

struct PsdResult {
  PsdVerdict verdict = PsdVerdict::kNotPsd;
  /// Human-readable reason (pivot, rank, which path decided).
  std::string reason;
  /// 0-based row of M that decided: for kNotPsd the row whose Schur pivot is
  /// negative (or the row of the zero pivot with a nonzero entry); for
  /// kPositiveSemidefinite the first row of the zero Schur complement;
  /// -1 for kPositiveDefinite and when the filter decided.
  long pivot_index = -1;
  /// For kNotPsd: v with vᵀMv < 0 exactly (original row order). Empty otherwise.
  Vec<Rational> witness;
  /// True when a fast path (PsdMethod::kFloatingFilter or kWitnessCheck) decided.
  bool decided_by_filter = false;
  PsdMethod method = PsdMethod::kExactLdlt;
  /// Exact rank when the exact path decided (n for PD); -1 if unknown.
  long rank = -1;
  /// Elimination step (number of positive pivots before the decision) at which
  /// the exact path decided; -1 if not applicable.
  long step = -1;
};

/// "PD", "PSD" or "NOT_PSD" (the first word of `lpvid-verify psd`, docs/design.md §11.2).
const char* verdict_word(PsdVerdict v);

/// Throws std::invalid_argument unless M is square and exactly symmetric
/// (the message names the first offending pair).
void require_symmetric(const Mat<Rational>& M);

/// Exact decision (multi-modular elimination, see the file comment).
/// Throws std::invalid_argument for non-square or non-symmetric M.
/// `threads` ≤ 0: use the hardware concurrency (at most 8); 1: single thread.
PsdResult decide_psd_exact(const Mat<Rational>& M, int threads = 0);

/// Fraction-free (Bareiss) elimination on GMP integers; same contract.
PsdResult decide_psd_bareiss(const Mat<Rational>& M, int threads = 0);

/// Reference implementation: LDLᵀ over rationals, same pivot rule and witness
/// as decide_psd_bareiss.
PsdResult decide_psd_rational_ldlt(const Mat<Rational>& M);

struct PsdOptions {
  bool use_filter = true;   ///< try psd_filter before the exact path
  int threads = 0;          ///< for the exact path (see decide_psd_exact)
};

/// Filter, then exact (docs/design.md §13.3). Same contract as decide_psd_exact.
PsdResult decide_psd(const Mat<Rational>& M, const PsdOptions& options = {});

/// vᵀMv, exactly.
Rational quadratic_form(const Mat<Rational>& M, const Vec<Rational>& v);

}  // namespace lpvid
