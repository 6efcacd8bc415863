#include "verify/certificate/tap_gram_filter.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <utility>

#include "core/number_text.h"
#include "verify/psd/power_of_two.h"
#include "verify/psd/psd_filter.h"

// The recurrence below rounds each product and each sum separately (the
// bound in the header allows fewer roundings too, but states these).
#include "core/no_fp_contraction.h"

namespace lpvid {
namespace {

Rational absolute(const Rational& q) { return q < 0 ? -q : q; }

/// The rounded taps and the exact sums the radius needs (header, 1. and 2.).
struct RoundedTaps {
  std::vector<double> t;
  Rational max_error{0}, l1{0}, sum_squares{0};
  bool finite = true;
};

RoundedTaps round_taps(const std::vector<Rational>& taps, std::size_t K) {
  RoundedTaps out;
  out.t.resize(K);
  for (std::size_t k = 0; k < K; ++k) {
    const double x = nearest_double(taps[k]);
    if (!std::isfinite(x)) {
      out.finite = false;
      return out;
    }
    out.t[k] = x;
    const Rational q(x);  // exact: a double is a dyadic rational
    out.max_error = std::max(out.max_error, absolute(taps[k] - q));
    out.l1 += absolute(q);
    out.sum_squares += q * q;
  }
  return out;
}

/// A = fl(D·I − Ĝ), row-major n × n, upper triangle (header, 2. and 3.);
/// returns max |A_ii|.
double form_complement(const std::vector<double>& t, std::size_t n, double D, std::vector<double>& A) {
  const std::size_t K = t.size();
  std::vector<double> g(n, 0.0);  // row i of Ĝ, columns j ≥ i
  double max_diagonal = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = n; j-- > i;) {
      const double previous = i > 0 ? g[j - 1] : 0.0;
      if (j < K) {
        const double product = t[i] * t[j];
        g[j] = previous + product;
      } else {
        g[j] = previous;
      }
    }
    double* row = &A[i * n];
    row[i] = D - g[i];
    max_diagonal = std::max(max_diagonal, std::fabs(row[i]));
    for (std::size_t j = i + 1; j < n; ++j) row[j] = -g[j];
  }
  return max_diagonal;
}

}  // namespace

TapGramFilterResult prove_tap_gram_complement_pd(const std::vector<Rational>& taps, long L, const Rational& d2) {
  TapGramFilterResult out;
  if (L <= 0) {
    out.reason = "empty horizon";
    return out;
  }
  const std::size_t n = static_cast<std::size_t>(L), K = std::min(taps.size(), n);
  const Rational u = power_of_two(-53), eta = power_of_two(-1074), Lq(L);
  if (!(Lq * u < Rational(1, 2))) {
    out.reason = "horizon too long for the error bound";
    return out;
  }
  const RoundedTaps rt = round_taps(taps, K);
  const double D = nearest_double(d2);
  if (!rt.finite || !std::isfinite(D)) {
    out.reason = "a tap or d2 is outside the double range";
    return out;
  }
  std::vector<double> A(n * n, 0.0);
  const double max_diagonal = form_complement(rt.t, n, D, A);
  const Rational gamma = Lq * u / (Rational(1) - Lq * u);
  const Rational Kq(static_cast<long>(K));
  const Rational radius = rt.max_error * (Rational(2) * rt.l1 + Kq * rt.max_error)  // 1.
                          + gamma * rt.sum_squares + Rational(2) * Lq * eta            // 2.
                          + absolute(d2 - Rational(D)) + Rational(2) * u * Rational(max_diagonal);  // 3.
  const PsdFilterResult f = run_psd_filter_within_radius(std::move(A), n, radius);
  std::ostringstream why;
  why << "formed in doubles from the taps with every entry within r = " << nearest_double(radius)
      << " of the exact one (proved bound, verify/certificate/tap_gram_filter.h); " << f.reason;
  out.proved_pd = f.proved_pd;
  out.reason = why.str();
  return out;
}

}  // namespace lpvid
