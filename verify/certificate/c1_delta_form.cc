/// (C1) of Theorem 2.1 for form "delta" (verify/certificate/c1_check.h):
///   M = [δ²I, T_Δ; T_Δᵀ, I] ⪰ 0  (size L·(ny + nz)),  i.e. ‖T_Δ‖ ≤ δ.
///
///  0. T_Δ = 0 (every tap it contains is zero, e.g. Δ = 0 of a closed-form
///     answer at δ² = 0): M = diag(δ²I, I) ⪰ 0 for δ² ≥ 0, decided at once.
///  1. Every entry h of T_Δ sits in a 2×2 principal submatrix [δ², h; h, 1]
///     of M (its row in the δ² block, its column in the I block), whose
///     determinant is δ² − h². A principal submatrix of a PSD matrix is PSD,
///     so h² > δ² for one tap entry that T_Δ contains (tap index < L) decides
///     NOT PSD at once, exactly: no elimination, whatever the size of δ².
///  2. Otherwise every |h| ≤ δ, and the congruence diag(I/s, I) with s ≈ δ
///     (nonsingular: same inertia) balances M to
///       [δ²/s² I, T_Δ/s; T_Δᵀ/s, I],
///     every entry within a factor 4 of 1 or smaller, which the floating
///     filter reads for any δ². s is δ rounded to a double while δ is within
///     [1e−150, 1e150], else a power of two (sqrt_scale: δ² = 1e4000 or
///     1e−5000 would overflow or underflow a double).
///  3. M ⪰ 0 is decided on a Schur complement of the balanced matrix, of
///     size L·min(ny, nz) instead of L·(ny + nz) (memory ÷ 4 or more, the
///     elimination ÷ 8 or more), with T = T_Δ/s and d² = δ²/s²:
///       ny ≤ nz: d²I − T Tᵀ ⪰ 0, the complement of the I block (I ≻ 0, so
///                exactly equivalent for every d² ≥ 0);
///       ny > nz: d²I − TᵀT ⪰ 0, the complement of the d²I block: for
///                d² > 0 equivalent (multiply I − TᵀT/d² ⪰ 0 by d²); for
///                d² = 0, 1. has left T = 0, and both sides hold.
///     T is block banded (taps 0 … K−1), so T Tᵀ and TᵀT are block banded
///     with K − 1 blocks on each side, formed by the displacement recurrence
///     of verify/certificate/tap_gram.h in O(L·K) block entries.
///  4. One output and one input with L ≥ kStructuredC1Horizon (4096): before the
///     exact matrix, verify/certificate/tap_gram_filter.h tries to prove
///     d²I − T Tᵀ PD from the complement formed in doubles with a proved
///     radius (L² doubles instead of L² rationals: 0.8 GB at L = 10 000
///     where the rationals took more than 11 GB). Only a proof of PD ends
///     the check there; anything else goes on to the exact matrix as before,
///     charged to the work budget at that point (the budget charged the
///     proof only, verify/certificate/work_budget.h).

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/number_text.h"
#include "verify/certificate/c1_check.h"
#include "verify/certificate/tap_gram.h"
#include "verify/certificate/tap_gram_filter.h"
#include "verify/psd/exact_psd.h"
#include "core/gmp_raii.h"
#include "verify/psd/check_progress.h"
#include "verify/psd/power_of_two.h"
#include "verify/psd/work_limits.h"
#include "verify/certificate/verdict_text.h"

namespace lpvid {
namespace {

/// s ≈ δ > 0 (see the file comment, 2.) and its text for the message.
std::pair<Rational, std::string> balancing_scale(const Rational& delta2) {
  const double approx_delta = std::sqrt(nearest_double(delta2));
  if (approx_delta >= 1e-150 && approx_delta <= 1e150) {
    const Rational s = exact_rational_of_double(approx_delta);
    return {s, approx_text(s)};
  }
  const Rational s = sqrt_scale(delta2);
  return {s, "2^" + std::to_string(*binary_magnitude(s))};  // exactly e for s = 2^e
}

}  // namespace

C1Outcome check_c1_delta_form(const Mat<Rational>& taps, Eigen::Index horizon, Eigen::Index ny, Eigen::Index nz,
                              const Rational& delta2) {
  const Eigen::Index L = horizon, K = taps.rows();
  const std::string full = "[delta2*I, T_Delta; T_Delta', I]";
  // 1. The tap entry with the largest square, among the taps T_Δ contains.
  Eigen::Index arg_t = -1, arg_c = -1;
  Rational largest(0);
  for (Eigen::Index t = 0; t < std::min(K, L); ++t)
    for (Eigen::Index c = 0; c < ny * nz; ++c)
      if (const Rational h2 = taps(t, c) * taps(t, c); h2 > largest) {
        largest = h2;
        arg_t = t;
        arg_c = c;
      }
  if (arg_t < 0 && delta2 >= 0)  // 0. every tap entry is zero
    return C1Outcome::holding("(C1) holds: T_Delta = 0, so " + full + " = diag(delta2*I, I) is PSD (delta2 >= 0)");
  if (arg_t >= 0 && largest > delta2) {
    const Eigen::Index i = arg_c / nz, j = arg_c % nz;
    return C1Outcome::failing("(C1) fails: " + full + " is not PSD: tap " + std::to_string(arg_t) + " entry (" + std::to_string(i) +
                       "," + std::to_string(j) + ") = h = " + approx_text(taps(arg_t, arg_c)) +
                       " has h^2 > delta2, so its 2x2 principal submatrix [delta2, h; h, 1] (rows " +
                       std::to_string(arg_t * ny + i) + " and " + std::to_string(L * ny + j) +
                       ") has determinant delta2 - h^2 < 0 (exact comparison of rationals)");
  }
  // 2. Balanced by diag(I/s, I), then the Schur complement (3.).
  const auto [s, s_text] = delta2 > 0 ? balancing_scale(delta2) : std::pair<Rational, std::string>(Rational(1), "1");
  const Rational inv_s = Rational(1) / s;
  const Rational d2 = delta2 * inv_s * inv_s;
  const Mat<Rational> scaled = taps.topRows(std::min(K, L)) * inv_s;  // Δ_t / s
  const std::string which = std::string(ny <= nz ? "d2*I - T*T'" : "d2*I - T'*T") + ", T = T_Delta/s, d2 = delta2/s^2" +
                            ", s = " + s_text + " (Schur complement of " + full + ")";
  // 4. One output and one input on a long horizon: first the proof on the
  //    complement formed in doubles with a proved radius (no L² rationals).
  if (structured_c1_applies(L, ny, nz)) {
    std::vector<Rational> t(static_cast<std::size_t>(scaled.rows()));
    for (Eigen::Index k = 0; k < scaled.rows(); ++k) t[static_cast<std::size_t>(k)] = scaled(k, 0);
    check_progress(structured_c1_work(L), "(C1): the complement of order " + std::to_string(L) + " in doubles, its proof");
    const TapGramFilterResult f = prove_tap_gram_complement_pd(t, L, d2);
    if (f.proved_pd) return C1Outcome::holding("(C1) holds: " + which + " (size " + std::to_string(L) + ") is PD (" + f.reason + ")");
    // The budget charged the proof only; the exact matrix is charged now.
    const double m = static_cast<double>(L);
    charge_total_work(m * m * m, "the exact (C1) matrix of order " + std::to_string(L) + " (its proof in doubles failed: " + f.reason + ")");
  }
  const double m = static_cast<double>(L * std::min(ny, nz));
  check_progress(m * m * m, "(C1): the exact complement of order " + std::to_string(L * std::min(ny, nz)));
  const Mat<Rational> M = tap_gram_complement(scaled, L, ny, nz, d2);
  const PsdResult psd = decide_psd(M);
  if (psd.verdict == PsdVerdict::kNotPsd) return C1Outcome::failing("(C1) fails: " + which + " is not PSD (" + psd.reason + ")");
  return C1Outcome::holding("(C1) holds: " + which + " (size " + std::to_string(M.rows()) + ") is " + psd_note(psd));
}

}  // namespace lpvid
