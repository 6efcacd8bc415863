/// The leading-block screen of decide_psd_exact (verify/psd/psd_internal.h).
///
/// A principal submatrix of a PSD matrix is PSD: for K ⊂ {0..n−1} and x on K,
/// xᵀ M_KK x = yᵀ M y with y = x padded by zeros. So a witness x for M_KK
/// (xᵀ M_KK x < 0), padded by zeros, is a witness for M, and a NOT_PSD block
/// decides M. The converse fails (a PSD block proves nothing), so only NOT_PSD
/// ends the screen; PD and PSD verdicts always come from the full decision.
///
/// Cost. The blocks are the leading m×m with m = 2, 4, 8, … ≤ n/d (d =
/// screen_divisor, 4 by default), each decided by the multi-modular path:
/// O(m³) word operations per prime and O(m) primes (Hadamard's bound of an
/// m×m block has O(m) times the bits of one row), so O(m⁴), and
/// Σ_{m = 2^k ≤ n/d} m⁴ ≤ (16/15)(n/d)⁴ = n⁴/240 for d = 4: below 0.5 % of
/// the full decision. A block the modular path leaves undecided is skipped
/// (no Bareiss here), so the bound holds in every case.
///
/// Use. Matrices such as v vᵀ − εI with tiny ε: the floating filter sees the
/// rank-one v vᵀ, the full exact path needs thousands of primes, but already
/// the leading 2×2 block has determinant −ε(v₀² + v₁²) + ε² < 0.

#include <stdexcept>
#include <string>

#include "verify/psd/psd_internal.h"

namespace lpvid::psd_detail {

bool screen_leading_blocks(const Mat<Rational>& M, int threads, const ExactPsdLimits& limits, PsdResult* out) {
  if (limits.screen_divisor == 0) return false;
  const auto n = static_cast<std::size_t>(M.rows());
  for (std::size_t m = 2; m <= n / limits.screen_divisor && m < n; m *= 2) {
    const auto mi = static_cast<Eigen::Index>(m);
    const Mat<Rational> block = M.topLeftCorner(mi, mi);
    ModularOutcome o = decide_psd_modular(block, threads, limits.max_primes);
    if (!o.decided || o.result.verdict != PsdVerdict::kNotPsd) continue;
    PsdResult r = std::move(o.result);
    Vec<Rational> w = Vec<Rational>::Zero(M.rows());
    w.head(mi) = r.witness;
    // Already checked on the block; checked again on M itself (only the m×m
    // block enters the sum, the other entries of w are 0).
    if (!(quadratic_form(M, w) < Rational(0)))
      throw std::logic_error("exact_psd: internal error: padded witness does not satisfy v'Mv < 0");
    r.witness = std::move(w);
    r.reason = "the leading " + std::to_string(m) + "x" + std::to_string(m) +
               " principal submatrix is not PSD, so neither is M: " + r.reason;
    *out = std::move(r);
    return true;
  }
  return false;
}

}  // namespace lpvid::psd_detail
