/// The PSD decision's entry points (verify/psd/exact_psd.h): the floating filter
/// with its exact witness check, then the exact path; plus the small helpers
/// of the contract (verdict_word, require_symmetric, quadratic_form).

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/number_text.h"
#include "verify/psd/power_of_two.h"
#include "verify/psd/psd_filter.h"
#include "verify/psd/psd_internal.h"

namespace lpvid {
namespace {


/// Integer vector proportional (positive factor) to a finite double vector.
std::vector<Mpz> integer_vector_of_doubles(const Vec<double>& v) {
  const std::size_t n = static_cast<std::size_t>(v.size());
  std::vector<Mpz> w(n);
  long emin = 0;
  bool any = false;
  std::vector<long long> mant(n, 0);
  std::vector<long> expo(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = v(static_cast<Eigen::Index>(i));
    if (x == 0) continue;
    int e = 0;
    const double f = std::frexp(x, &e);  // x = f·2^e, 0.5 ≤ |f| < 1
    mant[i] = static_cast<long long>(std::ldexp(f, 53));  // exact
    expo[i] = e - 53;
    emin = any ? std::min(emin, expo[i]) : expo[i];
    any = true;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (mant[i] == 0) continue;
    mpz_set_si(w[i].z, static_cast<long>(mant[i]));
    mpz_mul_2exp(w[i].z, w[i].z, static_cast<mp_bitcnt_t>(expo[i] - emin));
  }
  return w;
}

}  // namespace

const char* verdict_word(PsdVerdict v) {
  switch (v) {
    case PsdVerdict::kPositiveDefinite:
      return "PD";
    case PsdVerdict::kPositiveSemidefinite:
      return "PSD";
    case PsdVerdict::kNotPsd:
      return "NOT_PSD";
  }
  return "NOT_PSD";
}

void require_symmetric(const Mat<Rational>& M) {
  if (M.rows() != M.cols())
    throw std::invalid_argument("matrix is not square: " + std::to_string(M.rows()) + " rows, " +
                                std::to_string(M.cols()) + " columns");
  for (Eigen::Index i = 0; i < M.rows(); ++i)
    for (Eigen::Index j = i + 1; j < M.cols(); ++j)
      if (!mpq_equal(M(i, j).mpq(), M(j, i).mpq()))
        throw std::invalid_argument("matrix is not symmetric: entry (" + std::to_string(i) + "," +
                                    std::to_string(j) + ") = " + rational_to_text(M(i, j)) + " but (" +
                                    std::to_string(j) + "," + std::to_string(i) + ") = " +
                                    rational_to_text(M(j, i)) + " (0-based)");
}

PsdResult decide_psd_exact(const Mat<Rational>& M, int threads) {
  return psd_detail::decide_psd_exact_limited(M, threads, psd_detail::ExactPsdLimits{});
}

namespace psd_detail {

PsdResult decide_psd_exact_limited(const Mat<Rational>& M, int threads, const ExactPsdLimits& limits) {
  require_symmetric(M);
  const int workers = resolve_threads(threads);
  PsdResult screened;
  if (screen_leading_blocks(M, workers, limits, &screened)) return screened;
  ModularOutcome outcome = decide_psd_modular(M, workers, limits.max_primes);
  if (outcome.decided) return outcome.result;
  // The multi-modular path could not decide (verify/psd/psd_modular.cc, 5.):
  // Bareiss decides exactly, without primes.
  PsdResult r = decide_psd_bareiss(M, threads);
  r.reason += " [multi-modular path undecided (" + outcome.why + "); decided by fraction-free Bareiss elimination]";
  return r;
}

}  // namespace psd_detail

PsdResult decide_psd(const Mat<Rational>& M, const PsdOptions& options) {
  require_symmetric(M);
  const Eigen::Index n = M.rows();
  if (options.use_filter && n > 0) {
    // Rows (and, by symmetry, columns) that are exactly zero do not change
    // PSD-ness: M is PSD iff M without them is. The filter sees the rest.
    std::vector<Eigen::Index> keep;
    Eigen::Index first_zero = -1;
    for (Eigen::Index i = 0; i < n; ++i) {
      bool zero = true;
      for (Eigen::Index j = 0; j < n && zero; ++j) zero = CGAL::is_zero(M(i, j));
      if (!zero)
        keep.push_back(i);
      else if (first_zero < 0)
        first_zero = i;
    }
    const auto m = static_cast<Eigen::Index>(keep.size());
    Mat<Rational> reduced;
    if (m < n) {
      reduced.resize(m, m);
      for (Eigen::Index a = 0; a < m; ++a)
        for (Eigen::Index b = 0; b < m; ++b) reduced(a, b) = M(keep[static_cast<std::size_t>(a)], keep[static_cast<std::size_t>(b)]);
    }
    const Mat<Rational>& R = m < n ? reduced : M;
    const std::string zero_note =
        m < n ? " (after removing " + std::to_string(n - m) + " zero row(s)/column(s), the first at row " +
                    std::to_string(first_zero) + ")"
              : std::string();

    // Power-of-two balancing (verify/psd/power_of_two.h): when the diagonal spans
    // many binary orders (a dual matrix in original units, say), the filter's
    // absolute error terms would swamp the small rows; the exact congruence
    // D·R·D with D = diag(2^k) keeps the inertia and puts the diagonal near 1.
    const std::vector<long> k = diagonal_balance_exponents(R);
    const Mat<Rational> balanced = k.empty() ? Mat<Rational>() : diagonal_congruence(R, k);
    const std::string balance_note = k.empty() ? std::string() : " (after an exact power-of-two diagonal balancing)";
    PsdFilterResult f = run_psd_filter(k.empty() ? R : balanced);
    f.reason += balance_note;
    if (f.proved_pd) {
      PsdResult r;
      r.verdict = m < n ? PsdVerdict::kPositiveSemidefinite : PsdVerdict::kPositiveDefinite;
      r.decided_by_filter = true;
      r.method = PsdMethod::kFloatingFilter;
      r.rank = m;
      r.pivot_index = m < n ? first_zero : -1;
      r.reason = f.reason + zero_note;
      return r;
    }
    if (f.negative_direction.size() == m && m > 0) {
      // Try short integer roundings of the candidate first (readable
      // witnesses), then its exact binary value.
      std::vector<Mpz> w;
      bool found = false;
      const double vmax = f.negative_direction.cwiseAbs().maxCoeff();
      for (int bits : {3, 10, 24, 0}) {
        std::vector<Mpz> w_reduced =
            bits == 0 ? integer_vector_of_doubles(f.negative_direction)
                      : integer_vector_of_doubles(
                            (f.negative_direction * (std::ldexp(1.0, bits) / vmax)).array().round().matrix().eval());
        // back to R's coordinates: v_R = D·v_B, an exact shift per entry (kmin keeps the shifts ≥ 0)
        if (!k.empty()) {
          const long kmin = *std::min_element(k.begin(), k.end());
          for (std::size_t a = 0; a < w_reduced.size(); ++a)
            mpz_mul_2exp(w_reduced[a].z, w_reduced[a].z, static_cast<mp_bitcnt_t>(k[a] - kmin));
        }
        w = std::vector<Mpz>(static_cast<std::size_t>(n));
        for (std::size_t a = 0; a < keep.size(); ++a) mpz_swap(w[static_cast<std::size_t>(keep[a])].z, w_reduced[a].z);
        if (psd_detail::quadratic_form_sign(M, w) < 0) {
          found = true;
          break;
        }
      }
      if (found) {
        PsdResult r;
        r.verdict = PsdVerdict::kNotPsd;
        r.decided_by_filter = true;
        r.method = PsdMethod::kWitnessCheck;
        r.pivot_index = keep[static_cast<std::size_t>(f.failed_row)];
        r.witness = psd_detail::reduced_witness(w);
        r.reason = f.candidate_reason + balance_note + " at row " + std::to_string(r.pivot_index) +
                   "; its direction v satisfies v'Mv < 0, checked in exact integer arithmetic";
        return r;
      }
    }
  }
  return decide_psd_exact(M, options.threads);
}

Rational quadratic_form(const Mat<Rational>& M, const Vec<Rational>& v) {
  if (M.rows() != M.cols() || M.rows() != v.size())
    throw std::invalid_argument("quadratic_form: size mismatch");
  Rational q(0);
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    if (CGAL::is_zero(v(i))) continue;
    Rational row(0);
    for (Eigen::Index j = 0; j < M.cols(); ++j)
      if (!CGAL::is_zero(v(j))) row += M(i, j) * v(j);
    q += v(i) * row;
  }
  return q;
}

}  // namespace lpvid
