/// The PSD decision's entry points (verify/psd/exact_psd.h): the floating filter
/// with its exact witness check, then the exact path; plus the small helpers
/// of the contract (verdict_word, require_symmetric, quadratic_form).

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/number_text.h"
#include "verify/psd/power_of_two.h"
#include "verify/psd/psd_filter.h"
#include "verify/psd/psd_internal.h"
#include "verify/psd/work_limits.h"

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

/// M without its exactly zero rows (and, by symmetry, columns): they do not
/// change PSD-ness, M is PSD iff M without them is. The filter sees the rest.
struct NonzeroRows {
  std::vector<Eigen::Index> keep;  // the nonzero rows of M, increasing
  Eigen::Index first_zero = -1;    // the first zero row (−1: none)
  Mat<Rational> reduced;           // M on `keep` when a row was removed (else empty)
  std::string note;                // for the reason ("" when none was removed)

  bool removed_any() const { return first_zero >= 0; }
  /// The matrix the filter sees: `reduced`, or M itself.
  const Mat<Rational>& matrix(const Mat<Rational>& M) const { return removed_any() ? reduced : M; }
};

/// Finds the zero rows of M and, when there are any, M without them.
NonzeroRows nonzero_rows(const Mat<Rational>& M) {
  const Eigen::Index n = M.rows();
  NonzeroRows out;
  for (Eigen::Index i = 0; i < n; ++i) {
    bool zero = true;
    for (Eigen::Index j = 0; j < n && zero; ++j) zero = CGAL::is_zero(M(i, j));
    if (!zero)
      out.keep.push_back(i);
    else if (out.first_zero < 0)
      out.first_zero = i;
  }
  if (!out.removed_any()) return out;
  const auto m = static_cast<Eigen::Index>(out.keep.size());
  out.reduced.resize(m, m);
  for (Eigen::Index a = 0; a < m; ++a)
    for (Eigen::Index b = 0; b < m; ++b)
      out.reduced(a, b) = M(out.keep[static_cast<std::size_t>(a)], out.keep[static_cast<std::size_t>(b)]);
  out.note = " (after removing " + std::to_string(n - m) + " zero row(s)/column(s), the first at row " +
             std::to_string(out.first_zero) + ")";
  return out;
}

/// The floating filter on R after power-of-two balancing
/// (verify/psd/power_of_two.h): when the diagonal spans many binary orders (a
/// dual matrix in original units, say), the filter's absolute error terms
/// would swamp the small rows; the exact congruence D·R·D with D = diag(2^k)
/// keeps the inertia and puts the diagonal near 1.
struct BalancedFilter {
  std::vector<long> k;  // the exponents of D (empty: not balanced, D = I)
  std::string note;     // for the reason ("" when not balanced)
  PsdFilterResult f;    // on D·R·D; f.reason carries the note
};

/// Balances R when its diagonal asks for it, then runs the filter.
BalancedFilter balanced_filter(const Mat<Rational>& R) {
  BalancedFilter out;
  out.k = diagonal_balance_exponents(R);
  if (out.k.empty()) {
    out.f = run_psd_filter(R);
  } else {
    out.note = " (after an exact power-of-two diagonal balancing)";
    out.f = run_psd_filter(diagonal_congruence(R, out.k));
  }
  out.f.reason += out.note;
  return out;
}

/// The filter's negative direction as an integer vector of M: rounded to
/// `bits` bits of its largest entry (0: its exact binary value), back to R's
/// coordinates (v_R = D·v_B), zeros at M's removed rows.
std::vector<Mpz> integer_candidate(Eigen::Index n, const NonzeroRows& rows, const BalancedFilter& b, int bits) {
  const Vec<double>& v = b.f.negative_direction;
  const double vmax = v.cwiseAbs().maxCoeff();
  std::vector<Mpz> w_reduced = bits == 0 ? integer_vector_of_doubles(v)
                                         : integer_vector_of_doubles(
                                               (v * (std::ldexp(1.0, bits) / vmax)).array().round().matrix().eval());
  // back to R's coordinates: v_R = D·v_B, an exact shift per entry (kmin keeps the shifts ≥ 0)
  if (!b.k.empty()) {
    const long kmin = *std::min_element(b.k.begin(), b.k.end());
    for (std::size_t a = 0; a < w_reduced.size(); ++a)
      mpz_mul_2exp(w_reduced[a].z, w_reduced[a].z, static_cast<mp_bitcnt_t>(b.k[a] - kmin));
  }
  std::vector<Mpz> w(static_cast<std::size_t>(n));
  for (std::size_t a = 0; a < rows.keep.size(); ++a)
    mpz_swap(w[static_cast<std::size_t>(rows.keep[a])].z, w_reduced[a].z);
  return w;
}

/// The filter's verdict PD (or PSD when zero rows were removed).
PsdResult filter_proved_pd(const NonzeroRows& rows, const PsdFilterResult& f) {
  PsdResult r;
  r.verdict = rows.removed_any() ? PsdVerdict::kPositiveSemidefinite : PsdVerdict::kPositiveDefinite;
  r.decided_by_filter = true;
  r.method = PsdMethod::kFloatingFilter;
  r.rank = static_cast<long>(rows.keep.size());
  r.pivot_index = rows.first_zero;
  r.reason = f.reason + rows.note;
  return r;
}

/// NOT_PSD by a filter candidate: tries short integer roundings of the
/// candidate first (readable witnesses), then its exact binary value; true
/// with *out when one of them satisfies vᵀMv < 0, checked exactly.
bool filter_witness(const Mat<Rational>& M, const NonzeroRows& rows, const BalancedFilter& b, PsdResult* out) {
  for (int bits : {3, 10, 24, 0}) {
    std::vector<Mpz> w = integer_candidate(M.rows(), rows, b, bits);
    if (psd_detail::quadratic_form_sign(M, w) >= 0) continue;
    PsdResult r;
    r.verdict = PsdVerdict::kNotPsd;
    r.decided_by_filter = true;
    r.method = PsdMethod::kWitnessCheck;
    r.pivot_index = rows.keep[static_cast<std::size_t>(b.f.failed_row)];
    r.witness = psd_detail::reduced_witness(w);
    r.reason = b.f.candidate_reason + b.note + " at row " + std::to_string(r.pivot_index) +
               "; its direction v satisfies v'Mv < 0, checked in exact integer arithmetic";
    *out = std::move(r);
    return true;
  }
  return false;
}

/// The floating filter's decision with its exact witness check (M ≠ 0×0):
/// true with *out when it proves PD (PSD) or finds a checked witness.
bool decide_by_filter(const Mat<Rational>& M, PsdResult* out) {
  const NonzeroRows rows = nonzero_rows(M);
  const BalancedFilter b = balanced_filter(rows.matrix(M));
  if (b.f.proved_pd) {
    *out = filter_proved_pd(rows, b.f);
    return true;
  }
  const auto m = static_cast<Eigen::Index>(rows.keep.size());
  return b.f.negative_direction.size() == m && m > 0 && filter_witness(M, rows, b, out);
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
  // Refused before any elimination when above lpvid-verify's work limit.
  if (verify_work_limits().max_exact_work > 0 && M.rows() > 0)
    require_exact_work(static_cast<long>(M.rows()), static_cast<double>(hadamard_bits(*integer_matrix(M))));
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
  PsdResult r;
  if (options.use_filter && M.rows() > 0 && decide_by_filter(M, &r)) return r;
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
