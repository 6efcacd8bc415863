/// Fraction-free (Bareiss) symmetric elimination on GMP integers
/// (decide_psd_bareiss, verify/psd/exact_psd.h).

#include <gmp.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/number_text.h"
#include "core/parallel_for.h"
#include "core/stop_request.h"
#include "verify/psd/psd_internal.h"

namespace lpvid {
namespace {

using psd_detail::check_witness;
using psd_detail::IntegerMatrix;
using psd_detail::reduced_witness;

/// Runs f(lo, hi) on [begin, end) split into `threads` chunks of about equal
/// work, row i costing (n − i) entries, the chunks at once through
/// core/parallel_for.h (one worker per chunk).
template <typename F>
void for_rows_split(std::size_t begin, std::size_t end, std::size_t n, int threads, F&& f) {
  const std::size_t rows = end - begin;
  const double work = static_cast<double>(rows) * static_cast<double>(n - begin) / 2.0;
  if (threads <= 1 || rows < 8 || work < 4096) {
    f(begin, end);
    return;
  }
  // Chunk boundaries by cumulative work Σ (n − i).
  std::vector<std::size_t> cut{begin};
  double total = 0;
  for (std::size_t i = begin; i < end; ++i) total += static_cast<double>(n - i);
  double acc = 0;
  int part = 1;
  for (std::size_t i = begin; i < end && part < threads; ++i) {
    acc += static_cast<double>(n - i);
    if (acc >= total * part / threads) {
      cut.push_back(i + 1);
      ++part;
    }
  }
  cut.push_back(end);
  // The nonempty chunks (at most `threads`), one job each on core's workers.
  std::vector<std::pair<std::size_t, std::size_t>> chunks;
  for (std::size_t c = 0; c + 1 < cut.size(); ++c)
    if (cut[c] < cut[c + 1]) chunks.emplace_back(cut[c], cut[c + 1]);
  parallel_for(chunks.size(), static_cast<unsigned>(threads),
               [&](std::size_t c) { f(chunks[c].first, chunks[c].second); });
}

// ---------------------------------------------------------------------------
// Fraction-free symmetric elimination (Bareiss) with symmetric pivoting.
//
// U holds the upper triangle in LOGICAL order (perm[logical] = original row).
// After steps 0..k−1 with pivots P_0..P_{k−1} (logical rows 0..k−1):
//   U(i, j), k ≤ i ≤ j : det of the (k+1)×(k+1) submatrix of rows {0..k−1, i}
//                        and columns {0..k−1, j} (Sylvester's identity), i.e.
//                        Δ_k · S_ij with S the Schur complement and
//                        Δ_k = det(leading k×k) = U(k−1, k−1) (Δ_0 = 1) > 0;
//   U(m, j), m < k ≤ j  : row m as it was when it was the pivot row.
// The update U(i,j) ← (P·U(i,j) − U(k,i)·U(k,j)) / Δ_k is an exact division.

class Bareiss {
 public:
  Bareiss(std::unique_ptr<IntegerMatrix> A, int threads)
      : n_(A->n), U_(std::move(A)), perm_(n_), threads_(threads) {
    for (std::size_t i = 0; i < n_; ++i) perm_[i] = static_cast<long>(i);
    mpz_set_ui(delta_.z, 1);
  }

  PsdResult run(const Mat<Rational>& M) {
    for (std::size_t k = 0; k < n_; ++k) {
      check_stop();  // a requested stop, between pivots
      // 1. Negative Schur diagonal (smallest original index) ⇒ NOT_PSD.
      std::size_t neg = n_, pos = n_;
      for (std::size_t i = k; i < n_; ++i) {
        const int s = mpz_sgn(U(i, i));
        if (s < 0 && (neg == n_ || perm_[i] < perm_[neg])) neg = i;
        if (s > 0 && (pos == n_ || perm_[i] < perm_[pos])) pos = i;
      }
      if (neg != n_) return not_psd_negative_pivot(M, k, neg);
      if (pos == n_) return zero_block(M, k);
      // 2. Pivot on the positive diagonal with the smallest original index.
      swap_logical(k, pos);
      eliminate(k);
    }
    PsdResult r;
    r.verdict = PsdVerdict::kPositiveDefinite;
    r.rank = static_cast<long>(n_);
    r.step = static_cast<long>(n_);
    r.reason = "exact LDL^T: all " + std::to_string(n_) + " pivots are positive";
    return r;
  }

 private:
  mpz_ptr U(std::size_t i, std::size_t j) { return U_->at(i, j); }

  /// Exchanges logical positions k < p of the symmetric matrix whose upper
  /// triangle is stored (rows < k are finished pivot rows; they are permuted
  /// along, which is what the back-substitution needs).
  void swap_logical(std::size_t k, std::size_t p) {
    if (k == p) return;
    for (std::size_t i = 0; i < k; ++i) mpz_swap(U(i, k), U(i, p));
    mpz_swap(U(k, k), U(p, p));
    for (std::size_t i = k + 1; i < p; ++i) mpz_swap(U(k, i), U(i, p));
    for (std::size_t j = p + 1; j < n_; ++j) mpz_swap(U(k, j), U(p, j));
    std::swap(perm_[k], perm_[p]);
  }

  void eliminate(std::size_t k) {
    mpz_srcptr P = U(k, k);
    const bool first = mpz_cmp_ui(delta_.z, 1) == 0;
    for_rows_split(k + 1, n_, n_, threads_, [&](std::size_t lo, std::size_t hi) {
      Mpz t;
      for (std::size_t i = lo; i < hi; ++i) {
        mpz_srcptr a_ki = U(k, i);
        const bool zero_ki = mpz_sgn(a_ki) == 0;
        for (std::size_t j = i; j < n_; ++j) {
          mpz_ptr a_ij = U(i, j);
          if (zero_ki) {
            if (mpz_sgn(a_ij) == 0) continue;
            mpz_mul(t.z, P, a_ij);
          } else {
            mpz_mul(t.z, P, a_ij);
            mpz_submul(t.z, a_ki, U(k, j));
          }
          if (first)
            mpz_swap(a_ij, t.z);
          else
            mpz_divexact(a_ij, t.z, delta_.z);
        }
      }
    });
    mpz_set(delta_.z, P);
  }

  /// v (logical order, integers) = Δ_k · [−M_PP⁻¹ M_P· x; x] by back-substitution
  /// with the stored pivot rows; every division is exact (Cramer: Δ_k·M_PP⁻¹
  /// is the adjugate, an integer matrix). x is given on logical rows ≥ k.
  std::vector<Mpz> witness_logical(std::size_t k, const std::vector<std::pair<std::size_t, long>>& x) {
    std::vector<Mpz> w(n_);
    for (const auto& [i, xi] : x) mpz_mul_si(w[i].z, delta_.z, xi);
    Mpz t;
    for (std::size_t m = k; m-- > 0;) {
      mpz_set_ui(t.z, 0);
      for (std::size_t j = m + 1; j < n_; ++j)
        if (mpz_sgn(w[j].z) != 0) mpz_addmul(t.z, U(m, j), w[j].z);
      mpz_neg(t.z, t.z);
      mpz_divexact(w[m].z, t.z, U(m, m));
    }
    return w;
  }

  /// Maps a logical witness to original order, re-checks it, reduces it.
  Vec<Rational> finish_witness(const Mat<Rational>& M, std::vector<Mpz> w_logical) {
    std::vector<Mpz> w(n_);
    for (std::size_t i = 0; i < n_; ++i) mpz_swap(w[static_cast<std::size_t>(perm_[i])].z, w_logical[i].z);
    check_witness(M, w);
    return reduced_witness(w);
  }

  std::string schur_value_text(mpz_srcptr numerator) {
    // S = numerator / Δ_k; print only when short.
    if (mpz_sizeinbase(numerator, 2) + mpz_sizeinbase(delta_.z, 2) > 256) return {};
    Mpq s;
    mpq_set_num(s.q, numerator);
    mpq_set_den(s.q, delta_.z);
    mpq_canonicalize(s.q);
    return rational_to_text(Rational(s.q));
  }

  PsdResult not_psd_negative_pivot(const Mat<Rational>& M, std::size_t k, std::size_t i) {
    PsdResult r;
    r.verdict = PsdVerdict::kNotPsd;
    r.pivot_index = perm_[i];
    r.step = static_cast<long>(k);
    std::string value = schur_value_text(U(i, i));
    r.reason = "exact LDL^T: after " + std::to_string(k) + " positive pivot(s) the pivot of row " +
               std::to_string(perm_[i]) + " is negative" + (value.empty() ? "" : " (" + value + ")");
    r.witness = finish_witness(M, witness_logical(k, {{i, 1}}));
    return r;
  }

  PsdResult zero_block(const Mat<Rational>& M, std::size_t k) {
    // Every remaining diagonal is 0. Find the nonzero off-diagonal entry with
    // the smallest (original row, original column).
    std::size_t bi = n_, bj = n_;
    std::pair<long, long> best{-1, -1};
    for (std::size_t i = k; i < n_; ++i)
      for (std::size_t j = i + 1; j < n_; ++j)
        if (mpz_sgn(U(i, j)) != 0) {
          std::pair<long, long> key{std::min(perm_[i], perm_[j]), std::max(perm_[i], perm_[j])};
          if (bi == n_ || key < best) {
            best = key;
            bi = i;
            bj = j;
          }
        }
    PsdResult r;
    r.step = static_cast<long>(k);
    if (bi == n_) {
      r.verdict = PsdVerdict::kPositiveSemidefinite;
      r.rank = static_cast<long>(k);
      long first = n_ > k ? perm_[k] : -1;
      for (std::size_t i = k; i < n_; ++i) first = std::min(first, perm_[i]);
      r.pivot_index = first;
      r.reason = "exact LDL^T: " + std::to_string(k) + " positive pivot(s), then the remaining " +
                 std::to_string(n_ - k) + "x" + std::to_string(n_ - k) +
                 " Schur complement is exactly zero (rank " + std::to_string(k) + " < n = " +
                 std::to_string(n_) + ")";
      return r;
    }
    // x = e_i − sign(b)·e_j: xᵀSx = S_ii + S_jj − 2|S_ij| = −2|b| < 0.
    r.verdict = PsdVerdict::kNotPsd;
    const std::size_t i = perm_[bi] < perm_[bj] ? bi : bj, j = i == bi ? bj : bi;
    r.pivot_index = perm_[i];
    r.reason = "exact LDL^T: after " + std::to_string(k) + " positive pivot(s) the pivot of row " +
               std::to_string(perm_[i]) + " is 0 but its row is not (entry with row " + std::to_string(perm_[j]) +
               "): the 2x2 principal minor [[0,b],[b,0]] with b != 0 is indefinite";
    const long sj = -mpz_sgn(U(bi, bj));
    r.witness = finish_witness(M, witness_logical(k, {{i, 1}, {j, sj}}));
    return r;
  }

  std::size_t n_;
  std::unique_ptr<IntegerMatrix> U_;
  std::vector<long> perm_;
  int threads_;
  Mpz delta_;  // Δ_k, the previous pivot (1 before the first step)
};

}  // namespace

PsdResult decide_psd_bareiss(const Mat<Rational>& M, int threads) {
  require_symmetric(M);
  Bareiss elimination(psd_detail::integer_matrix(M), psd_detail::resolve_threads(threads));
  PsdResult r = elimination.run(M);
  r.method = PsdMethod::kExactLdlt;
  return r;
}

}  // namespace lpvid
