#pragma once
/// Fast rigorous filter for positive definiteness (docs/design.md §13.3: "a fast filter
/// may answer first when it is certain; otherwise exact rationals decide").
/// In the CGAL "filter, then exact" style it answers only "PD for sure" or
/// "don't know". A "don't know" may carry a floating candidate v for
/// vᵀMv < 0; that candidate proves nothing until verify/psd/psd_witness.cc checks it
/// in exact integer arithmetic.
///
/// THEOREM USED (Rump's criterion).
///   S.M. Rump, "Verification of positive definiteness", BIT Numerical
///   Mathematics 46 (2006) 433–452, Theorem 2.3 / Corollary 2.4 (shifted
///   floating Cholesky) and Corollary 2.7 (all matrices within a radius).
///   Formally proved in Coq, in exactly the form used here, by P. Roux,
///   "Formal proofs of rounding error bounds — with application to an
///   automatic positive definiteness check", J. Automated Reasoning 57 (2016)
///   135–156 (ValidSDP, theories/cholesky.v,
///   `corollary_2_7_with_c_r_upper_bounds`, instantiated for binary64).
///
///   Let F be IEEE-754 binary64 with rounding to nearest (any tie rule),
///   u = 2⁻⁵³, η = 2⁻¹⁰⁷⁴ (the smallest positive subnormal; the proofs use an
///   underflow constant no larger than this, and c below grows with η),
///   γ_k = k·u/(1 − k·u). Let A ∈ F^{N×N} be symmetric with A_ii ≥ 0,
///   4(N+1)u < 1, maxdiag ≥ max_i A_ii, and
///     c ≥ ½·γ_{2(N+1)}·tr(A) + 4·η·N·(2(N+1) + maxdiag)
///         (½γ_{2(N+1)} = γ_{N+1}/(1−γ_{N+1}), Rump's constant),
///     Rad ≥ 0 entrywise with Rad_ij ≤ r for all i, j,
///     Ã ∈ F^{N×N} with Ã_ij = A_ij (i ≠ j) and Ã_ii ≤ A_ii − c − N·r.
///   If floating-point Cholesky of Ã,
///     R_ij = fl( fl(…fl(fl(Ã_ij − fl(R_0i R_0j)) − fl(R_1i R_1j))…) / R_ii ),
///     R_jj = fl( √ fl(…fl(Ã_jj − fl(R_0j R_0j))…) ),
///   (each product and each difference rounded separately, the sum taken
///   left to right over k = 0, 1, …) runs to completion without overflow with
///   every R_jj > 0, then every real X with |X − A| ≤ Rad entrywise is
///   positive definite.
///
/// HOW IT IS APPLIED to a rational symmetric M:
///   - A_ij = nearest double of M_ij (MPFR, correctly rounded; A is symmetric
///     because M is). Any faithful rounding gives |M_ij − A_ij| ≤ 2u|A_ij| + 2η;
///     we take r = Rad_ij = 2u·max|A_ij| + 2η (conservative by a factor 2).
///   - c, r and the shift s = c + N·r are computed in exact rationals; each
///     Ã_ii is the exact rational A_ii − s rounded DOWNWARD by MPFR (not by
///     the FPU), so Ã_ii ≤ A_ii − c − N·r holds exactly.
///   - Cholesky is our own row-oriented loop (below), which evaluates every
///     R_ij with exactly the left-to-right order above (the loop is
///     vectorised across j, never re-associated across k; rows are taken in
///     blocks that only change WHEN an entry's next subtraction happens,
///     never their order). No BLAS, no Eigen LLT (their blocked updates sum
///     in other orders, which the theorem does not cover).
///   - Any non-finite value, any R_jj ≤ 0 or NaN: "don't know".
///
/// ASSUMPTIONS, each enforced:
///   - binary64 is IEEE-754 and evaluated without extra precision:
///     static_assert(is_iec559) and FLT_EVAL_METHOD == 0 (#error otherwise).
///   - round-to-nearest at run time (CGAL's interval code may switch the mode
///     and restores it; -frounding-math keeps the compiler from assuming a
///     mode): checked with fegetround(), otherwise "don't know".
///   - no flush-to-zero / denormals-are-zero (the η terms need gradual
///     underflow): probed at run time, otherwise "don't know".
///   - no contraction of x − a·b into an FMA (the theorem rounds the product
///     and the difference separately): this file turns contraction off
///     (GCC `#pragma GCC optimize("fp-contract=off")`, Clang
///     `#pragma clang fp contract(off)`), and the kernel itself is probed at
///     run time on inputs where a fused result differs; otherwise "don't know".
///   - sqrt is correctly rounded (IEEE-754 requires it; std::sqrt on x86-64
///     is sqrtsd).

#include <cstddef>
#include <string>
#include <vector>

#include "core/scalar.h"

namespace lpvid {

struct PsdFilterResult {
  /// True only if the theorem above proves M positive definite.
  bool proved_pd = false;
  /// Why it was proved (shift used) or why not (where Cholesky stopped, or
  /// which assumption failed).
  std::string reason;
  /// The shift s = c + N·r that was subtracted from the diagonal (0 if not run).
  double shift = 0;
  /// When not proved: a floating vector v for which the floating Cholesky of
  /// A (unshifted) suggests vᵀMv < 0; empty if none. NOT a proof.
  Vec<double> negative_direction;
  /// 0-based row at which the unshifted floating Cholesky met a pivot ≤ 0
  /// (-1 if it did not).
  long failed_row = -1;
  /// How the candidate was found ("negative diagonal entry", "floating
  /// Cholesky of fl(M) met a pivot <= 0"); empty if there is none.
  std::string candidate_reason;
};

/// Runs the filter on a symmetric M (the caller has checked symmetry exactly;
/// only the upper triangle is read). Never throws for numeric reasons.
PsdFilterResult run_psd_filter(const Mat<Rational>& M);

/// The theorem for a matrix the caller has formed in doubles itself:
/// `upper` is N×N row-major (only the upper triangle is read; the buffer is
/// taken over and overwritten by the factor, so no copy of the N² doubles is
/// made), and `radius` ≥ 0 is a bound the caller has PROVED on
/// |X_ij − A_ij| for every entry of the true matrix X (added to Rad above,
/// with the underflow term). Proves X positive definite, or says why not;
/// it does not look for a candidate direction (that would need a second
/// copy), so a matrix it cannot prove is left to the exact route.
PsdFilterResult run_psd_filter_within_radius(std::vector<double> upper, std::size_t n, const Rational& radius);

/// The upper-triangular floating factor R (RᵀR ≈ A) that the filter's
/// Cholesky computes for the square A (upper triangle read, no shift), or an
/// empty matrix where it stops: for tests and diagnostics.
Mat<double> floating_cholesky_factor(const Mat<double>& A);

/// Why the floating-point environment does not meet the assumptions above,
/// or an empty string when it does (exposed for tests and diagnostics).
std::string floating_environment_problem();

}  // namespace lpvid
