#pragma once
/// Generators for stable single-output LTI systems in observer canonical form
/// (fit/observer_form.h) and their noise-free data, built by
/// construction: the denominator is the product of (z − p) over real poles
/// and (z² − 2r cos ω z + r²) over complex pairs with |p|, r ≤ 0.9, so A is
/// stable without rejection. Numerator (B, D), x0 and the input are uniform
/// integers/100 in [−1, 1]; each integer shrinks towards the low end of its
/// range.

#include <rapidcheck.h>

#include <cmath>
#include <vector>

#include "data/experiment.h"
#include "fit/observer_form.h"
#include "support/gen_models.h"

namespace lpvid::gen {

/// A value k/100 with k uniform in [lo, hi] (shrinks towards lo).
inline rc::Gen<double> hundredths(int lo, int hi) {
  return rc::gen::map(uniform_int(lo, hi), [](int k) { return k / 100.0; });
}

/// Denominator coefficients a_1..a_n of a stable polynomial of degree n.
inline rc::Gen<Vec<double>> stable_denominator(int n) {
  return rc::gen::exec([n] {
    std::vector<double> poly{1.0};  // highest power first
    auto multiply = [&](const std::vector<double>& f) {
      std::vector<double> out(poly.size() + f.size() - 1, 0.0);
      for (size_t i = 0; i < poly.size(); ++i)
        for (size_t j = 0; j < f.size(); ++j) out[i + j] += poly[i] * f[j];
      poly = out;
    };
    int left = n;
    while (left > 0) {
      if (left >= 2 && *rc::gen::arbitrary<bool>()) {
        const double r = *hundredths(10, 90), w = *hundredths(10, 300);
        multiply({1.0, -2.0 * r * std::cos(w), r * r});
        left -= 2;
      } else {
        multiply({1.0, -*hundredths(-90, 90)});
        left -= 1;
      }
    }
    Vec<double> a(n);
    for (int i = 0; i < n; ++i) a(i) = poly[static_cast<size_t>(i) + 1];
    return a;
  });
}

/// A stable observer-form system of order n with nu inputs (no offset).
inline rc::Gen<ObserverForm> stable_system(int n, int nu) {
  return rc::gen::exec([n, nu] {
    ObserverForm f = zero_observer_form(n, nu, false);
    f.a = *stable_denominator(n);
    for (Eigen::Index i = 0; i < f.B.size(); ++i) f.B.data()[i] = *hundredths(-100, 100);
    for (Eigen::Index i = 0; i < f.D.size(); ++i) f.D.data()[i] = *hundredths(-100, 100);
    for (Eigen::Index i = 0; i < n; ++i) f.x0(i) = *hundredths(-100, 100);
    return f;
  });
}

/// An N × nu input, uniform hundredths in [−1, 1] (white, persistently exciting).
inline rc::Gen<Mat<double>> white_input(Eigen::Index N, int nu) {
  return rc::gen::exec([N, nu] {
    Mat<double> u(N, nu);
    for (Eigen::Index i = 0; i < u.size(); ++i) u.data()[i] = *hundredths(-100, 100);
    return u;
  });
}

/// The system's noise-free free-run data on input u.
inline Experiment<double> lti_experiment(const ObserverForm& f, const Mat<double>& u) {
  Experiment<double> e;
  e.source = "generated";
  e.u = u;
  e.y = simulate_observer(f, u);
  e.rho = Mat<double>(u.rows(), 0);
  return e;
}

}  // namespace lpvid::gen
