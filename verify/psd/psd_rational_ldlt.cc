/// The reference decision: textbook LDLᵀ over GMP rationals with the pivot
/// rule of verify/psd/exact_psd.h (decide_psd_rational_ldlt). Slow; kept as an
/// implementation independent of the integer paths, for the tests.

#include <gmp.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "core/number_text.h"
#include "verify/psd/exact_psd.h"
#include "core/gmp_raii.h"

namespace lpvid {


PsdResult decide_psd_rational_ldlt(const Mat<Rational>& M) {
  require_symmetric(M);
  const std::size_t n = static_cast<std::size_t>(M.rows());
  // S: upper triangle by ORIGINAL index (no physical permutation).
  MpqArray S(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j)
      mpq_set(S[i * n + j], M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)).mpq());
  auto at = [&](std::size_t i, std::size_t j) { return i <= j ? S[i * n + j] : S[j * n + i]; };

  std::vector<std::size_t> rem(n), piv;  // rem stays sorted by original index
  for (std::size_t i = 0; i < n; ++i) rem[i] = i;

  PsdResult r;
  r.method = PsdMethod::kExactLdlt;
  // Witness: x on remaining rows, then v_p = −(Σ_{j≠p} S_pj v_j)/S_pp for the
  // pivots in reverse order (S_p· is row p as it was when p was pivoted).
  auto make_witness = [&](const std::vector<std::pair<std::size_t, long>>& x) {
    MpqArray v(n);
    for (const auto& [i, xi] : x) mpq_set_si(v[i], xi, 1);
    Mpq t, prod;
    for (std::size_t m = piv.size(); m-- > 0;) {
      const std::size_t p = piv[m];
      mpq_set_ui(t.q, 0, 1);
      for (std::size_t j = 0; j < n; ++j)
        if (j != p && mpq_sgn(v[j]) != 0) {
          mpq_mul(prod.q, at(p, j), v[j]);
          mpq_add(t.q, t.q, prod.q);
        }
      mpq_div(v[p], t.q, at(p, p));
      mpq_neg(v[p], v[p]);
    }
    Vec<Rational> out(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) out(static_cast<Eigen::Index>(i)) = Rational(v[i]);
    return out;
  };

  Mpq l, prod;
  for (std::size_t k = 0;; ++k) {
    r.step = static_cast<long>(k);
    if (rem.empty()) {
      r.verdict = PsdVerdict::kPositiveDefinite;
      r.rank = static_cast<long>(n);
      r.reason = "rational LDL^T: all " + std::to_string(n) + " pivots are positive";
      return r;
    }
    std::size_t neg = n, pos = n;
    for (std::size_t i : rem) {
      const int s = mpq_sgn(at(i, i));
      if (s < 0 && neg == n) neg = i;
      if (s > 0 && pos == n) pos = i;
    }
    if (neg != n) {
      r.verdict = PsdVerdict::kNotPsd;
      r.pivot_index = static_cast<long>(neg);
      r.reason = "rational LDL^T: after " + std::to_string(k) + " positive pivot(s) the pivot of row " +
                 std::to_string(neg) + " is negative (" + rational_to_text(Rational(at(neg, neg))) + ")";
      r.witness = make_witness({{neg, 1}});
      return r;
    }
    if (pos == n) {
      for (std::size_t a = 0; a < rem.size(); ++a)
        for (std::size_t b = a + 1; b < rem.size(); ++b)
          if (mpq_sgn(at(rem[a], rem[b])) != 0) {
            r.verdict = PsdVerdict::kNotPsd;
            r.pivot_index = static_cast<long>(rem[a]);
            r.reason = "rational LDL^T: after " + std::to_string(k) + " positive pivot(s) the pivot of row " +
                       std::to_string(rem[a]) + " is 0 but its row is not (entry with row " +
                       std::to_string(rem[b]) + ")";
            r.witness = make_witness({{rem[a], 1}, {rem[b], -mpq_sgn(at(rem[a], rem[b]))}});
            return r;
          }
      r.verdict = PsdVerdict::kPositiveSemidefinite;
      r.rank = static_cast<long>(k);
      r.pivot_index = static_cast<long>(rem.front());
      r.reason = "rational LDL^T: " + std::to_string(k) + " positive pivot(s), then the remaining Schur complement is zero";
      return r;
    }
    rem.erase(std::find(rem.begin(), rem.end(), pos));
    piv.push_back(pos);
    for (std::size_t a = 0; a < rem.size(); ++a) {
      const std::size_t i = rem[a];
      if (mpq_sgn(at(pos, i)) == 0) continue;
      mpq_div(l.q, at(pos, i), at(pos, pos));
      for (std::size_t b = a; b < rem.size(); ++b) {
        const std::size_t j = rem[b];
        if (mpq_sgn(at(pos, j)) == 0) continue;
        mpq_mul(prod.q, l.q, at(pos, j));
        mpq_sub(at(i, j), at(i, j), prod.q);
      }
    }
  }
}

}  // namespace lpvid
