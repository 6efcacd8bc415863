#pragma once
/// (C1) of form "delta" for one output and one input on a long horizon
/// (verify/certificate/c1_delta_form.cc, step 3), proved without the exact
/// L × L matrix: the Schur complement
///   M = d2·I − T Tᵀ,   T the L × L lower-triangular Toeplitz matrix of the taps t,
/// is formed in doubles by the displacement recurrence of
/// verify/certificate/tap_gram.h, a bound r on |M_ij − A_ij| is proved for
/// every entry of the doubles A, and the floating filter
/// (verify/psd/psd_filter.h, Rump's criterion for all matrices within the
/// radius r of A) decides. O(L²) exact-free work to form A, L³/6 floating
/// multiply-adds to factor it, and one buffer of L² doubles (0.8 GB at
/// L = 10 000) instead of L² exact rationals.
///
/// THE RADIUS, term by term (u = 2⁻⁵³, η = 2⁻¹⁰⁷⁴, γ_m = m·u/(1 − m·u)):
///  1. The taps rounded: t̂_k = nearest double of t_k, E = max_k |t_k − t̂_k|
///     (exact). For every entry, |Σ_m t_m t_{m+p} − Σ_m t̂_m t̂_{m+p}|
///     ≤ Σ_m (|t_m − t̂_m|·|t_{m+p}| + |t̂_m|·|t_{m+p} − t̂_{m+p}|)
///     ≤ E·(‖t‖₁ + ‖t̂‖₁) ≤ E·(2‖t̂‖₁ + K·E)   (K taps).
///  2. The recurrence in doubles: Ĝ(i, j) = fl(Ĝ(i−1, j−1) + fl(t̂_i·t̂_j))
///     (the product only while j < K) adds the at most L products of the
///     entry's dot product left to right, so (Higham, Accuracy and Stability
///     of Numerical Algorithms, 2nd ed., eq. (3.5))
///       |Ĝ − G| ≤ γ_L·Σ_m |t̂_m t̂_{m+p}| ≤ γ_L·Σ_m t̂_m²   (Cauchy–Schwarz),
///     plus the underflow of the products (each at most η/2, carried by at
///     most L additions of relative error ≤ u: below 2·L·η in all). Sums
///     have no underflow error. Contraction into FMA is turned off in the
///     .cc (it would only remove roundings; the bound holds either way).
///  3. The diagonal: D = nearest double of d2 (|d2 − D| exact), and
///     A_ii = fl(D − Ĝ(i, i)) is within u·|D − Ĝ(i, i)| ≤ 2u·|A_ii| of the
///     difference. The off-diagonal A_ij = −Ĝ(i, j) is exact.
/// r is the sum of 1., 2. and 3. (the largest diagonal's), computed in exact
/// rationals; it holds for every entry.

#include <string>
#include <vector>

#include "core/scalar.h"

namespace lpvid {

/// Horizons (one output, one input) on which check_c1_delta_form tries this
/// proof before the exact matrix, and the work budget
/// (verify/certificate/work_budget.h) charges it instead of the dense check.
inline constexpr long kStructuredC1Horizon = 4096;
inline bool structured_c1_applies(long L, long ny, long nz) { return ny == 1 && nz == 1 && L >= kStructuredC1Horizon; }

/// The proof's floating operations, as the work budget counts them: the
/// Cholesky's L³/6 multiply-adds and the complement's L² entries.
inline double structured_c1_work(long L) {
  const double n = static_cast<double>(L);
  return n * n * n / 6 + n * n;
}

struct TapGramFilterResult {
  bool proved_pd = false;
  /// How it was proved (radius, shift) or why not.
  std::string reason;
};

/// Tries to prove d2·I − T Tᵀ positive definite for the taps t_0 … t_{K−1}
/// (exact rationals, K ≤ L used) on the horizon L. Never proves a matrix
/// that is not PD; "not proved" leaves the decision to the exact route.
TapGramFilterResult prove_tap_gram_complement_pd(const std::vector<Rational>& taps, long L, const Rational& d2);

}  // namespace lpvid
