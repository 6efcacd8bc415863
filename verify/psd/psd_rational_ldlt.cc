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
#include "core/stop_request.h"
#include "verify/psd/exact_psd.h"
#include "core/gmp_raii.h"

namespace lpvid {
namespace {

/// LDLᵀ over GMP rationals, pivoting at each step on the remaining row with
/// the smallest original index whose Schur diagonal is positive.
class RationalLdlt {
 public:
  /// S = M's upper triangle; every row remains.
  explicit RationalLdlt(const Mat<Rational>& M) : n_(static_cast<std::size_t>(M.rows())), S_(n_ * n_), rem_(n_) {
    for (std::size_t i = 0; i < n_; ++i)
      for (std::size_t j = i; j < n_; ++j)
        mpq_set(S_[i * n_ + j], M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)).mpq());
    for (std::size_t i = 0; i < n_; ++i) rem_[i] = i;
  }

  /// Step k: a negative Schur diagonal (smallest original index) ⇒ NOT_PSD;
  /// no positive one ⇒ the zero-diagonal case; else pivot on the first
  /// positive one. All n pivots positive ⇒ PD.
  PsdResult run() {
    for (std::size_t k = 0;; ++k) {
      check_stop();  // a requested stop, between pivots
      if (rem_.empty()) {
        PsdResult r = step_result(k);
        r.verdict = PsdVerdict::kPositiveDefinite;
        r.rank = static_cast<long>(n_);
        r.reason = "rational LDL^T: all " + std::to_string(n_) + " pivots are positive";
        return r;
      }
      std::size_t neg = n_, pos = n_;
      for (std::size_t i : rem_) {
        const int s = mpq_sgn(at(i, i));
        if (s < 0 && neg == n_) neg = i;
        if (s > 0 && pos == n_) pos = i;
      }
      if (neg != n_) return negative_pivot(k, neg);
      if (pos == n_) return zero_diagonal(k);
      pivot_on(pos);
    }
  }

 private:
  /// S_ij of the current Schur complement, upper triangle by ORIGINAL index
  /// (no physical permutation).
  mpq_ptr at(std::size_t i, std::size_t j) { return i <= j ? S_[i * n_ + j] : S_[j * n_ + i]; }

  /// A result of this method at step k (the verdict is the caller's).
  PsdResult step_result(std::size_t k) const {
    PsdResult r;
    r.method = PsdMethod::kExactLdlt;
    r.step = static_cast<long>(k);
    return r;
  }

  /// Witness: x on remaining rows, then v_p = −(Σ_{j≠p} S_pj v_j)/S_pp for the
  /// pivots in reverse order (S_p· is row p as it was when p was pivoted).
  Vec<Rational> make_witness(const std::vector<std::pair<std::size_t, long>>& x) {
    MpqArray v(n_);
    for (const auto& [i, xi] : x) mpq_set_si(v[i], xi, 1);
    Mpq t, prod;
    for (std::size_t m = piv_.size(); m-- > 0;) {
      const std::size_t p = piv_[m];
      mpq_set_ui(t.q, 0, 1);
      for (std::size_t j = 0; j < n_; ++j)
        if (j != p && mpq_sgn(v[j]) != 0) {
          mpq_mul(prod.q, at(p, j), v[j]);
          mpq_add(t.q, t.q, prod.q);
        }
      mpq_div(v[p], t.q, at(p, p));
      mpq_neg(v[p], v[p]);
    }
    Vec<Rational> out(static_cast<Eigen::Index>(n_));
    for (std::size_t i = 0; i < n_; ++i) out(static_cast<Eigen::Index>(i)) = Rational(v[i]);
    return out;
  }

  /// NOT_PSD: the Schur diagonal of row `neg` is negative after k positive pivots.
  PsdResult negative_pivot(std::size_t k, std::size_t neg) {
    PsdResult r = step_result(k);
    r.verdict = PsdVerdict::kNotPsd;
    r.pivot_index = static_cast<long>(neg);
    r.reason = "rational LDL^T: after " + std::to_string(k) + " positive pivot(s) the pivot of row " +
               std::to_string(neg) + " is negative (" + rational_to_text(Rational(at(neg, neg))) + ")";
    r.witness = make_witness({{neg, 1}});
    return r;
  }

  /// Every remaining Schur diagonal is 0: NOT_PSD by the 2×2 minor of the
  /// first nonzero entry (rows in original order), else PSD of rank k.
  PsdResult zero_diagonal(std::size_t k) {
    PsdResult r = step_result(k);
    for (std::size_t a = 0; a < rem_.size(); ++a)
      for (std::size_t b = a + 1; b < rem_.size(); ++b)
        if (mpq_sgn(at(rem_[a], rem_[b])) != 0) {
          r.verdict = PsdVerdict::kNotPsd;
          r.pivot_index = static_cast<long>(rem_[a]);
          r.reason = "rational LDL^T: after " + std::to_string(k) + " positive pivot(s) the pivot of row " +
                     std::to_string(rem_[a]) + " is 0 but its row is not (entry with row " +
                     std::to_string(rem_[b]) + ")";
          r.witness = make_witness({{rem_[a], 1}, {rem_[b], -mpq_sgn(at(rem_[a], rem_[b]))}});
          return r;
        }
    r.verdict = PsdVerdict::kPositiveSemidefinite;
    r.rank = static_cast<long>(k);
    r.pivot_index = static_cast<long>(rem_.front());
    r.reason = "rational LDL^T: " + std::to_string(k) +
               " positive pivot(s), then the remaining Schur complement is zero";
    return r;
  }

  /// One elimination step on the positive pivot `pos`: S_ij −= (S_pi/S_pp)·S_pj
  /// for the remaining i ≤ j.
  void pivot_on(std::size_t pos) {
    rem_.erase(std::find(rem_.begin(), rem_.end(), pos));
    piv_.push_back(pos);
    Mpq l, prod;
    for (std::size_t a = 0; a < rem_.size(); ++a) {
      const std::size_t i = rem_[a];
      if (mpq_sgn(at(pos, i)) == 0) continue;
      mpq_div(l.q, at(pos, i), at(pos, pos));
      for (std::size_t b = a; b < rem_.size(); ++b) {
        const std::size_t j = rem_[b];
        if (mpq_sgn(at(pos, j)) == 0) continue;
        mpq_mul(prod.q, l.q, at(pos, j));
        mpq_sub(at(i, j), at(i, j), prod.q);
      }
    }
  }

  std::size_t n_;
  MpqArray S_;
  std::vector<std::size_t> rem_;  // remaining rows, sorted by original index
  std::vector<std::size_t> piv_;  // pivots in order
};

}  // namespace

PsdResult decide_psd_rational_ldlt(const Mat<Rational>& M) {
  require_symmetric(M);
  RationalLdlt ldlt(M);
  return ldlt.run();
}

}  // namespace lpvid
