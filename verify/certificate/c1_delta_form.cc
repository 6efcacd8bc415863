/// (C1) of Theorem 2.1 for form "delta" (verify/certificate/c1_check.h):
///   M = [δ²I, T_Δ; T_Δᵀ, I] ⪰ 0  (size L·(ny + nz)),  i.e. ‖T_Δ‖ ≤ δ.
///
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
///     with K − 1 blocks on each side: formed in O(L·K²) block products.

#include <cmath>
#include <string>
#include <utility>

#include "core/number_text.h"
#include "core/stop_request.h"
#include "verify/certificate/c1_check.h"
#include "verify/psd/exact_psd.h"
#include "core/gmp_raii.h"
#include "verify/psd/power_of_two.h"
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

/// The Schur complement of 3. (file comment): d2·I − T Tᵀ (ny ≤ nz) or
/// d2·I − TᵀT, T the block lower-triangular Toeplitz matrix of `taps` (row t
/// = Δ_t row-major, ny × nz) on L samples, formed on its band only. The taps
/// are held as integers N over one common denominator D, so each entry is one
/// integer dot product over D² (as in verify/certificate/column_gram.h), not a sum of
/// rational products with a gcd each.
Mat<Rational> schur_complement(const Mat<Rational>& taps, Eigen::Index L, Eigen::Index ny, Eigen::Index nz,
                               const Rational& d2) {
  const Eigen::Index K = taps.rows(), width = ny * nz;
  Mpz D, f;
  mpz_set_ui(D.z, 1);
  for (Eigen::Index t = 0; t < K; ++t)
    for (Eigen::Index c = 0; c < width; ++c)
      if (mpq_srcptr q = taps(t, c).mpq(); !mpz_divisible_p(D.z, mpq_denref(q))) mpz_lcm(D.z, D.z, mpq_denref(q));
  MpzArray num(static_cast<std::size_t>(K * width));
  const auto at = [width](Eigen::Index t, Eigen::Index c) { return static_cast<std::size_t>(t * width + c); };
  for (Eigen::Index t = 0; t < K; ++t)
    for (Eigen::Index c = 0; c < width; ++c) {
      mpq_srcptr q = taps(t, c).mpq();
      mpz_divexact(f.z, D.z, mpq_denref(q));
      mpz_mul(num[at(t, c)], f.z, mpq_numref(q));
    }
  Mpz D2;
  mpz_mul(D2.z, D.z, D.z);
  const bool rows = ny <= nz;  // T Tᵀ (blocks ny × ny) or TᵀT (blocks nz × nz)
  const Eigen::Index m = rows ? ny : nz;
  Mat<Rational> S = Mat<Rational>::Zero(L * m, L * m);
  for (Eigen::Index k = 0; k < L * m; ++k) S(k, k) = d2;
  Mpz dot;
  Mpq g;
  for (Eigen::Index a = 0; a < L; ++a)
    for (Eigen::Index c = a; c < std::min(L, a + K); ++c) {
      if (c == a) check_stop();  // a requested stop, once a block row
      // T Tᵀ block (a, c) = Σ_b Δ_{a−b} Δ_{c−b}ᵀ over b ≤ a with c − b < K;
      // TᵀT block (a, c) = Σ_r Δ_{r−a}ᵀ Δ_{r−c} over r ≥ c with r − a < K.
      for (Eigen::Index p = 0; p < m; ++p)
        for (Eigen::Index q = 0; q < m; ++q) {
          mpz_set_ui(dot.z, 0);
          if (rows) {
            for (Eigen::Index b = std::max<Eigen::Index>(0, c - K + 1); b <= a; ++b)
              for (Eigen::Index j = 0; j < nz; ++j)
                mpz_addmul(dot.z, num[at(a - b, p * nz + j)], num[at(c - b, q * nz + j)]);
          } else {
            for (Eigen::Index r = c; r < std::min(L, a + K); ++r)
              for (Eigen::Index i = 0; i < ny; ++i)
                mpz_addmul(dot.z, num[at(r - a, i * nz + p)], num[at(r - c, i * nz + q)]);
          }
          if (mpz_sgn(dot.z) == 0) continue;
          mpz_neg(mpq_numref(g.q), dot.z);
          mpz_set(mpq_denref(g.q), D2.z);
          mpq_canonicalize(g.q);
          const Rational entry(g.q);  // −(block entry of T Tᵀ or TᵀT)
          S(a * m + p, c * m + q) += entry;
          if (c != a) S(c * m + q, a * m + p) += entry;
        }
    }
  return S;
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
  if (arg_t >= 0 && largest > delta2) {
    const Eigen::Index i = arg_c / nz, j = arg_c % nz;
    return {false, "(C1) fails: " + full + " is not PSD: tap " + std::to_string(arg_t) + " entry (" + std::to_string(i) +
                       "," + std::to_string(j) + ") = h = " + approx_text(taps(arg_t, arg_c)) +
                       " has h^2 > delta2, so its 2x2 principal submatrix [delta2, h; h, 1] (rows " +
                       std::to_string(arg_t * ny + i) + " and " + std::to_string(L * ny + j) +
                       ") has determinant delta2 - h^2 < 0 (exact comparison of rationals)"};
  }
  // 2. Balanced by diag(I/s, I), then the Schur complement (3.).
  const auto [s, s_text] = delta2 > 0 ? balancing_scale(delta2) : std::pair<Rational, std::string>(Rational(1), "1");
  const Rational inv_s = Rational(1) / s;
  const Rational d2 = delta2 * inv_s * inv_s;
  const Mat<Rational> scaled = taps.topRows(std::min(K, L)) * inv_s;  // Δ_t / s
  const Mat<Rational> M = schur_complement(scaled, L, ny, nz, d2);
  const std::string which = std::string(ny <= nz ? "d2*I - T*T'" : "d2*I - T'*T") + ", T = T_Delta/s, d2 = delta2/s^2" +
                            ", s = " + s_text + " (Schur complement of " + full + ")";
  const PsdResult psd = decide_psd(M);
  if (psd.verdict == PsdVerdict::kNotPsd) return {false, "(C1) fails: " + which + " is not PSD (" + psd.reason + ")"};
  return {true, "(C1) holds: " + which + " (size " + std::to_string(M.rows()) + ") is " + psd_note(psd)};
}

}  // namespace lpvid
