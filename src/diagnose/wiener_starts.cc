#include "diagnose/wiener_starts.h"

#include <algorithm>
#include <cmath>

#include "diagnose/effect_candidates.h"
#include "diagnose/output_error_fit.h"

namespace lpvid {

Vec<double> polynomial_inverse_target(const std::vector<double>& c, const Vec<double>& y, const Vec<double>& v) {
  Vec<double> out = v;
  for (Eigen::Index k = 0; k < y.size(); ++k) {
    double x = v(k);
    for (int it = 0; it < 30; ++it) {
      double g = 0, dg = 0;
      for (size_t i = c.size(); i-- > 0;) {
        dg = dg * x + g;
        g = g * x + c[i];
      }
      if (!(std::abs(dg) > 1e-12)) break;  // flat: keep the current value
      const double step = (g - y(k)) / dg;
      x -= step;
      if (!std::isfinite(x)) {
        x = v(k);
        break;
      }
      if (std::abs(step) <= 1e-12 * (1 + std::abs(x))) break;
    }
    out(k) = x;
  }
  return out;
}

Vec<double> sign_recovered_target(const Vec<double>& y) {
  const Eigen::Index n = y.size();
  Vec<double> out = y;
  if (n < 3) return out;
  std::vector<double> sorted(y.data(), y.data() + n);
  std::sort(sorted.begin(), sorted.end());
  const double low = sorted[static_cast<size_t>(0.15 * static_cast<double>(n - 1))];
  double sign = 1;
  bool armed = true;  // y has risen above 2·low since the last flip
  for (Eigen::Index k = 0; k < n; ++k) {
    if (y(k) > 2 * low) armed = true;
    const bool dip = k > 0 && k + 1 < n && y(k) <= y(k - 1) && y(k) <= y(k + 1) && y(k) < low;
    if (dip && armed) {
      sign = -sign;
      armed = false;
    }
    out(k) = sign * y(k);
  }
  return out;
}

LpvModel<double> fitted_to_target(const LpvModel<double>& start, const Experiment<double>& est,
                                  const Vec<double>& target) {
  if (start.ny != 1 || target.size() != est.n()) return start;
  LpvModel<double> linear = start;
  linear.statics.output = StaticMap<double>{};
  Experiment<double> e = est;
  e.y = target;
  const FitResult f = fit_slots(linear, with_dynamics_slots(refit_slots(linear), linear), e);
  if (!f.finite) return start;
  LpvModel<double> out = f.model;
  out.statics.output = start.statics.output;
  return out;
}

}  // namespace lpvid
