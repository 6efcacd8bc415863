#include "diagnose/quantiles.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace lpvid {
namespace {

void check_probability(double p, const char* who) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument(std::string(who) + ": probability must be in (0, 1), got " + std::to_string(p));
}

void check_dof(double dof, const char* who) {
  if (!(dof > 0.0) || !std::isfinite(dof))
    throw std::invalid_argument(std::string(who) + ": degrees of freedom must be positive, got " + std::to_string(dof));
}

/// Bisection for an increasing f on [lo, hi] with f(lo) <= 0 <= f(hi).
template <typename F>
double bisect(F&& f, double lo, double hi, double rel_tol) {
  for (int i = 0; i < 400 && hi - lo > rel_tol * std::max(1.0, std::abs(lo + hi) / 2); ++i) {
    const double mid = (lo + hi) / 2;
    (f(mid) < 0 ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

/// Regularised lower incomplete gamma P(a, x) (Numerical Recipes §6.2).
double gamma_p(double a, double x) {
  if (x <= 0) return 0.0;
  const double log_prefactor = -x + a * std::log(x) - std::lgamma(a);
  const double eps = std::numeric_limits<double>::epsilon();
  if (x < a + 1) {  // series: P = e^{-x} x^a / Γ(a) · Σ x^n / (a (a+1) … (a+n))
    double ap = a, term = 1.0 / a, sum = term;
    for (int n = 0; n < 10000 && std::abs(term) > std::abs(sum) * eps; ++n) {
      ap += 1;
      term *= x / ap;
      sum += term;
    }
    return std::min(1.0, sum * std::exp(log_prefactor));
  }
  // continued fraction for Q = 1 − P, modified Lentz
  const double tiny = 1e-300;
  double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    const double an = -i * (i - a);
    b += 2;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1 / d;
    const double del = d * c;
    h *= del;
    if (std::abs(del - 1) <= eps) break;
  }
  return std::max(0.0, 1.0 - std::exp(log_prefactor) * h);
}

}  // namespace

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

double normal_quantile(double p) {
  check_probability(p, "normal_quantile");
  return bisect([p](double x) { return normal_cdf(x) - p; }, -40.0, 40.0, 1e-15);
}

double chi_square_cdf(double x, double dof) {
  check_dof(dof, "chi_square_cdf");
  if (std::isnan(x)) throw std::invalid_argument("chi_square_cdf: x is NaN");
  return gamma_p(dof / 2, x / 2);
}

double chi_square_quantile_wilson_hilferty(double p, double dof) {
  check_probability(p, "chi_square_quantile_wilson_hilferty");
  check_dof(dof, "chi_square_quantile_wilson_hilferty");
  const double v = 2.0 / (9.0 * dof);
  const double base = 1.0 - v + normal_quantile(p) * std::sqrt(v);
  return base <= 0 ? 0.0 : dof * base * base * base;
}

double chi_square_quantile(double p, double dof) {
  check_probability(p, "chi_square_quantile");
  check_dof(dof, "chi_square_quantile");
  const auto f = [&](double x) { return chi_square_cdf(x, dof) - p; };
  const double start = std::max(chi_square_quantile_wilson_hilferty(p, dof), 1e-3);
  double lo = start, hi = start;
  while (lo > 1e-300 && f(lo) > 0) lo /= 2;
  while (f(hi) < 0) hi *= 2;
  if (f(lo) > 0) return 0.0;  // p below the distribution function at the smallest x
  return bisect(f, lo, hi, 1e-13);
}

}  // namespace lpvid
