#include "verify/psd/psd_filter.h"

#include <algorithm>
#include <cfenv>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

#include <gmp.h>
#include <mpfr.h>

#include "core/gmp_raii.h"
#include "core/helper_thread.h"
#include "core/number_text.h"
#include "verify/psd/power_of_two.h"

static_assert(std::numeric_limits<double>::is_iec559, "psd_filter needs IEEE-754 binary64 doubles");
static_assert(std::numeric_limits<double>::digits == 53, "psd_filter needs 53-bit doubles");
#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "psd_filter needs double arithmetic evaluated in double precision (FLT_EVAL_METHOD == 0, e.g. SSE2)"
#endif

// Everything defined below this point rounds a·b and x − a·b separately
// (the theorem in psd_filter.h assumes it). Included after the other
// #includes on purpose: it applies to our functions only. The kernel is also
// probed at run time (contraction_problem()).
#include "core/no_fp_contraction.h"

namespace lpvid {
namespace {

/// s[j] = fl(s[j] − fl(a·r[j])) for j < len. Elementwise, so vectorising
/// across j never re-associates anything. Never inlined nor cloned, so that
/// the Cholesky and the run-time contraction probe execute the same code.
#if defined(__clang__)
__attribute__((noinline))
#elif defined(__GNUC__)
__attribute__((noinline, noclone))
#endif
void subtract_scaled_row(double* __restrict s, const double* __restrict r, double a, std::size_t len) {
  for (std::size_t j = 0; j < len; ++j) {
    const double p = a * r[j];
    s[j] = s[j] - p;
  }
}

/// Upper triangle of an N×N matrix, row-major in a full N×N buffer.
struct UpperMatrix {
  std::size_t n = 0;
  std::vector<double> a;
  double& at(std::size_t i, std::size_t j) { return a[i * n + j]; }
  double at(std::size_t i, std::size_t j) const { return a[i * n + j]; }
};

struct CholeskyRun {
  bool completed = false;
  std::size_t failed_step = 0;  // row whose pivot was ≤ 0, NaN, or whose row overflowed
  UpperMatrix R;               // rows 0..failed_step-1 valid when !completed
};

/// Rows per block and columns per tile of floating_cholesky.
constexpr std::size_t kRowBlock = 16, kColumnTile = 1024;

/// Subtracts the finished rows k ∈ [k0, k1) of R (stored in R's own rows)
/// from the working rows of the block [i0, i1) (row i of `w` holds the
/// columns j ≥ i at offset (i − i0)·n + j − i), k ascending for each entry,
/// column tile by column tile.
/// Only the columns [c0, c1) are touched, so two calls on disjoint column
/// ranges may run at once and each entry sees the same operations.
void subtract_finished_rows(const UpperMatrix& R, std::size_t k0, std::size_t k1, std::size_t i0, std::size_t i1,
                            std::vector<double>& w, std::size_t c0, std::size_t c1) {
  const std::size_t n = R.n;
  for (std::size_t j0 = std::max(c0, i0); j0 < c1; j0 += kColumnTile) {
    const std::size_t j1 = std::min(c1, j0 + kColumnTile);
    for (std::size_t k = k0; k < k1; ++k) {
      const double* rk = &R.a[k * n];
      for (std::size_t i = std::max(i0, k + 1); i < i1; ++i) {
        const std::size_t lo = std::max(j0, i);
        if (lo < j1) subtract_scaled_row(&w[(i - i0) * n + (lo - i)], rk + lo, rk[i], j1 - lo);
      }
    }
  }
}

/// Row-oriented floating Cholesky of the upper triangle of `At` (see the
/// formula in psd_filter.h), in place: row i of R is Ã's row i minus
/// R_ki·(row k of R), k = 0, 1, …, i−1 in that order, divided by
/// R_ii = √(pivot), and overwrites Ã's row i. Rows are taken kRowBlock at a
/// time: every row finished before the block is subtracted from all of the
/// block's rows (k ascending), then the block's own rows in turn, so every
/// entry sees exactly the operations of the row-by-row loop in the same
/// order (the same doubles), while each finished row is read once per block
/// instead of once per row. From order 1024 on a machine with two cores a
/// helper thread takes the right half of the columns of that first step
/// (core/helper_thread.h): every entry is still computed by one thread in
/// the same order, so the doubles do not depend on it. Stops at the first
/// pivot that is not > 0 or the first non-finite entry.
CholeskyRun floating_cholesky(UpperMatrix At) {
  const std::size_t n = At.n;
  CholeskyRun run;
  run.R = std::move(At);
  UpperMatrix& R = run.R;
  std::vector<double> w(kRowBlock * n);
  const std::unique_ptr<HelperThread> helper = helper_for_order(static_cast<long>(n));
  for (std::size_t i0 = 0; i0 < n; i0 += kRowBlock) {
    const std::size_t i1 = std::min(n, i0 + kRowBlock);
    for (std::size_t i = i0; i < i1; ++i)
      for (std::size_t j = i; j < n; ++j) w[(i - i0) * n + (j - i)] = R.at(i, j);
    const std::size_t mid = i0 + (n - i0) / 2;
    if (helper && i0 > 0 && n - i0 >= 2 * kColumnTile)
      helper->run([&] { subtract_finished_rows(R, 0, i0, i0, i1, w, mid, n); },
                  [&] { subtract_finished_rows(R, 0, i0, i0, i1, w, i0, mid); });
    else
      subtract_finished_rows(R, 0, i0, i0, i1, w, i0, n);
    for (std::size_t i = i0; i < i1; ++i) {
      double* wi = &w[(i - i0) * n];
      const std::size_t len = n - i;
      for (std::size_t k = i0; k < i; ++k) subtract_scaled_row(wi, &R.a[k * n + i], R.at(k, i), len);
      const double pivot = wi[0];
      if (!(pivot > 0) || !std::isfinite(pivot)) {
        run.failed_step = i;
        return run;
      }
      const double d = std::sqrt(pivot);
      double* ri = &R.a[i * n + i];
      ri[0] = d;
      bool finite = std::isfinite(d) && d > 0;
      for (std::size_t j = 1; j < len; ++j) {
        ri[j] = wi[j] / d;
        finite = finite && std::isfinite(ri[j]);
      }
      if (!finite) {
        run.failed_step = i;
        return run;
      }
    }
  }
  run.completed = true;
  return run;
}

/// Detects contraction of the kernel into an FMA: with a = 1 + 2⁻³⁰,
/// fl(a·a) = 1 + 2⁻²⁹ while a·a = 1 + 2⁻²⁹ + 2⁻⁶⁰, so s − a·a with
/// s = 1 + 2⁻²⁹ is 0 when rounded separately and −2⁻⁶⁰ when fused.
std::string contraction_problem() {
  volatile double seed = 1.0;  // keeps the compiler from folding the probe
  const double a = seed + std::ldexp(1.0, -30);
  const double s0 = seed + std::ldexp(1.0, -29);
  constexpr std::size_t kLen = 37;  // vector body and scalar tail
  std::vector<double> s(kLen, s0), r(kLen, a);
  subtract_scaled_row(s.data(), r.data(), a, kLen);
  for (double x : s)
    if (x != 0.0) return "the Cholesky kernel was compiled with FMA contraction";
  return {};
}

/// The largest double ≤ q (MPFR, rounding downward twice: to 53 bits with an
/// unbounded exponent, then to the double range; both round down).
double round_down(const Rational& q) {
  Mpfr f(53);
  mpfr_set_q(f.f, q.mpq(), MPFR_RNDD);
  return mpfr_get_d(f.f, MPFR_RNDD);
}

/// The candidate v = [−R11⁻¹·R(0:k−1, k); 1] for the failed step k of an
/// unshifted Cholesky: vᵀAv ≈ pivot_k ≤ 0. Empty if it does not stay finite.
Vec<double> negative_direction_from(const CholeskyRun& run) {
  const std::size_t k = run.failed_step;
  std::vector<double> v(k + 1, 0.0);
  v[k] = 1.0;
  for (std::size_t ii = k; ii-- > 0;) {
    double s = 0;
    for (std::size_t j = ii + 1; j <= k; ++j) s += run.R.at(ii, j) * v[j];
    v[ii] = -s / run.R.at(ii, ii);
    if (!std::isfinite(v[ii])) return {};
  }
  Vec<double> out = Vec<double>::Zero(static_cast<Eigen::Index>(run.R.n));
  for (std::size_t i = 0; i <= k; ++i) out(static_cast<Eigen::Index>(i)) = v[i];
  return out;
}

}  // namespace

std::string floating_environment_problem() {
  if (std::fegetround() != FE_TONEAREST) return "the floating-point rounding mode is not round-to-nearest";
  volatile double smallest_normal = DBL_MIN;
  volatile double half = smallest_normal / 2;  // subnormal, 0 under flush-to-zero
  volatile double back = half * 2;             // DBL_MIN, 0 under denormals-are-zero
  if (half == 0.0 || back != DBL_MIN) return "subnormal numbers are flushed to zero (FTZ/DAZ)";
  return contraction_problem();
}

/// What the true matrix may differ from A by, entrywise, beyond the
/// theorem's underflow term: the rounding of rational entries to doubles
/// (`rounded`), and a radius the caller has proved (`proved`). Without
/// `candidate`, a matrix that is not proved PD is not factored a second
/// time to look for a candidate direction (one buffer of N² doubles less).
struct InputRadius {
  bool rounded = false;
  Rational proved{0};
  bool candidate = true;
};

/// The theorem applied to A (upper triangle filled): proves PD every real
/// matrix within the radius of A.
static PsdFilterResult filter_prepared(UpperMatrix A, const InputRadius& radius, PsdFilterResult out);

/// An empty matrix (PD) or a floating environment the theorem does not
/// cover ("don't know"): true with *out set, before any work.
static bool settled_before_the_filter(std::size_t n, PsdFilterResult& out) {
  if (n == 0) {
    out.proved_pd = true;
    out.reason = "empty matrix";
    return true;
  }
  if (std::string p = floating_environment_problem(); !p.empty()) {
    out.reason = "filter skipped: " + p;
    return true;
  }
  return false;
}

/// The checks both entry points share, then A = the upper triangle of
/// `entry(i, j)` (doubles; a non-finite one stops with `not_finite`).
template <typename Matrix, typename Entry>
static PsdFilterResult filter_matrix(const Matrix& M, Entry entry, const InputRadius& radius, const char* not_finite) {
  PsdFilterResult out;
  const Eigen::Index N = M.rows();
  if (N != M.cols()) {
    out.reason = "not square";
    return out;
  }
  if (settled_before_the_filter(static_cast<std::size_t>(N), out)) return out;
  const std::size_t n = static_cast<std::size_t>(N);
  UpperMatrix A;
  A.n = n;
  A.a.assign(n * n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j) {
      const double x = entry(M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)));
      if (!std::isfinite(x)) {
        out.reason = not_finite;
        return out;
      }
      A.at(i, j) = x;
    }
  return filter_prepared(std::move(A), radius, std::move(out));
}

PsdFilterResult run_psd_filter(const Mat<Rational>& M) {
  return filter_matrix(M, [](const Rational& q) { return nearest_double(q); }, InputRadius{true, Rational(0), true},
                       "an entry is outside the double range");
}

Mat<double> floating_cholesky_factor(const Mat<double>& A) {
  const std::size_t n = static_cast<std::size_t>(A.rows());
  UpperMatrix U;
  U.n = n;
  U.a.assign(n * n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j) U.at(i, j) = A(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
  const CholeskyRun run = floating_cholesky(std::move(U));
  if (!run.completed) return {};
  Mat<double> R = Mat<double>::Zero(A.rows(), A.rows());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j) R(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = run.R.at(i, j);
  return R;
}

PsdFilterResult run_psd_filter_within_radius(std::vector<double> upper, std::size_t n, const Rational& radius) {
  PsdFilterResult out;
  if (upper.size() != n * n || radius < 0) {
    out.reason = "bad input to the filter (buffer size or negative radius)";
    return out;
  }
  if (settled_before_the_filter(n, out)) return out;
  UpperMatrix A;
  A.n = n;
  A.a = std::move(upper);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      if (j < i) A.at(i, j) = 0.0;  // the lower triangle is never read; keep it defined
      if (!std::isfinite(A.at(i, j))) {
        out.reason = "an entry is not finite";
        return out;
      }
    }
  return filter_prepared(std::move(A), InputRadius{false, radius, false}, std::move(out));
}

namespace {

/// What the theorem needs of A's entries: the largest diagonal entry, the
/// largest |A_ij| and tr(A) exactly.
struct FilterEntryScan {
  double maxdiag = 0, maxabs = 0;
  Rational trace{0};
};

/// maxdiag, tr(A) exactly, max |A_ij|; false at the first negative diagonal
/// entry, with the reason and its direction e_i in *out.
bool scan_filter_entries(const UpperMatrix& A, FilterEntryScan* scan, PsdFilterResult* out) {
  const std::size_t n = A.n;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i; j < n; ++j) scan->maxabs = std::max(scan->maxabs, std::fabs(A.at(i, j)));
    const double d = A.at(i, i);
    if (d < 0) {
      out->reason = "negative diagonal entry at row " + std::to_string(i);
      out->failed_row = static_cast<long>(i);
      Vec<double> v = Vec<double>::Zero(static_cast<Eigen::Index>(n));
      v(static_cast<Eigen::Index>(i)) = 1;
      out->negative_direction = v;
      out->candidate_reason = "negative diagonal entry";
      return false;
    }
    scan->maxdiag = std::max(scan->maxdiag, d);
    scan->trace += Rational(d);  // exact: every double is a dyadic rational
  }
  return true;
}

/// The constants of the theorem, exactly: the shift s = c + N·r with
/// c = γ_{2(N+1)}/2·tr(A) + 4ηN(2(N+1) + maxdiag) and the radius r. False
/// when N is too large for the error bound (4(N+1)u ≥ 1).
bool filter_shift(std::size_t n, const FilterEntryScan& scan, const InputRadius& radius, Rational* shift) {
  const Rational u = power_of_two(-53), eta = power_of_two(-1074), Nq(static_cast<long>(n));
  const Rational two_n1 = Rational(2) * (Nq + Rational(1));
  if (!(Rational(2) * two_n1 * u < Rational(1))) return false;  // 4(N+1)u < 1
  const Rational gamma = two_n1 * u / (Rational(1) - two_n1 * u);  // γ_{2(N+1)}
  const Rational c =
      gamma / Rational(2) * scan.trace + Rational(4) * eta * Nq * (two_n1 + Rational(scan.maxdiag));
  // Rad: the rounding of M to A (none when A is M itself), the caller's
  // proved radius, and the η term, always kept.
  const Rational r =
      (radius.rounded ? Rational(2) * u * Rational(scan.maxabs) : Rational(0)) + radius.proved + Rational(2) * eta;
  *shift = c + Nq * r;
  return true;
}

/// Floating Cholesky of fl(M) − s·I (diagonal rounded down): PD when it
/// completes. Else looks for a candidate direction with the unshifted matrix.
PsdFilterResult filter_cholesky(UpperMatrix A, const Rational& shift, bool candidate, PsdFilterResult out) {
  std::vector<double> diagonal(A.n);
  for (std::size_t i = 0; i < A.n; ++i) diagonal[i] = A.at(i, i);
  UpperMatrix At;
  if (candidate) {
    At = A;  // A stays for the unshifted factorisation below
  } else {
    At = std::move(A);
  }
  for (std::size_t i = 0; i < At.n; ++i) At.at(i, i) = round_down(Rational(diagonal[i]) - shift);

  CholeskyRun shifted = floating_cholesky(std::move(At));
  std::ostringstream why;
  if (shifted.completed) {
    why << "floating Cholesky of fl(M) - s*I succeeded with s = " << out.shift
        << " (Rump 2006, Cor. 2.4/2.7: every X with |X - fl(M)| <= r entrywise is PD)";
    out.proved_pd = true;
    out.reason = why.str();
    return out;
  }
  why << "floating Cholesky of fl(M) - s*I (s = " << out.shift << ") stopped at row " << shifted.failed_step;
  if (!candidate) {
    out.reason = why.str();
    return out;
  }

  // Not proved. Look for a candidate direction with the unshifted matrix.
  CholeskyRun plain = floating_cholesky(std::move(A));
  if (!plain.completed) {
    out.failed_row = static_cast<long>(plain.failed_step);
    out.negative_direction = negative_direction_from(plain);
    if (out.negative_direction.size() > 0) out.candidate_reason = "floating Cholesky of fl(M) met a pivot <= 0";
    why << "; unshifted Cholesky stopped at row " << plain.failed_step;
  } else {
    why << "; unshifted Cholesky succeeded (smallest eigenvalue too close to 0 to prove)";
  }
  out.reason = why.str();
  return out;
}

}  // namespace

static PsdFilterResult filter_prepared(UpperMatrix A, const InputRadius& radius, PsdFilterResult out) {
  FilterEntryScan scan;
  if (!scan_filter_entries(A, &scan, &out)) return out;
  Rational shift;
  if (!filter_shift(A.n, scan, radius, &shift)) {
    out.reason = "matrix too large for the error bound";
    return out;
  }
  out.shift = nearest_double(shift);
  return filter_cholesky(std::move(A), shift, radius.candidate, std::move(out));
}

}  // namespace lpvid
