// The Wiener starting points of fit/wiener_starts.h against answers
// known by construction.
#include <gtest/gtest.h>

#include <cmath>

#include "support/test_signals.h"
#include "fit/wiener_starts.h"

namespace lpvid {
namespace {

/// v = h ∗ u for a short FIR h (h_0 is the feedthrough).
Vec<double> fir(const std::vector<double>& h, const Vec<double>& u) {
  Vec<double> v = Vec<double>::Zero(u.size());
  for (Eigen::Index k = 0; k < u.size(); ++k)
    for (size_t j = 0; j < h.size() && static_cast<Eigen::Index>(j) <= k; ++j) v(k) += h[j] * u(k - static_cast<Eigen::Index>(j));
  return v;
}

double abs_correlation(const Vec<double>& a, const Vec<double>& b) {
  const Vec<double> x = a.array() - a.mean(), y = b.array() - b.mean();
  return std::abs(x.dot(y)) / (x.norm() * y.norm());
}

Experiment<double> wiener_record(const Vec<double>& u, const Vec<double>& y) {
  Experiment<double> e;
  e.u = u;
  e.y = y;
  e.rho = Mat<double>::Zero(u.size(), 0);
  return e;
}

const std::vector<double> kH = {0.5, 1.0, -0.3, 0.2};

// y = (h∗u)² lies in the span of the quadratic regression with Laguerre pole
// 0 (pure delays, h has 4 < 6 taps), so K = h hᵀ exactly and w = ±(h∗u)/‖h‖.
TEST(QuadraticKernelSignal, SquareOfAFirIsRecoveredUpToSignAndScale) {
  const Vec<double> u = gaussian(400, 1, 3).col(0);
  const Vec<double> v = fir(kH, u);
  const QuadraticKernel qk = quadratic_kernel_signal(wiener_record(u, v.array().square().matrix()));
  const Vec<double>& w = qk.w;
  ASSERT_EQ(w.size(), u.size());
  EXPECT_GT(abs_correlation(w, v), 0.9999);
  EXPECT_LT(qk.rms, 1e-9);  // y is in the regression's span
}

// |v| is not quadratic, but for Gaussian v its best quadratic approximation
// is a + b v² (Price's theorem: the second-order kernel is E[f'']/2·h hᵀ):
// the direction is still h, up to the approximation's noise.
TEST(QuadraticKernelSignal, AbsoluteValueSensorGivesTheSignedSignal) {
  const Vec<double> u = gaussian(600, 1, 4).col(0);
  const Vec<double> v = fir(kH, u);
  const Vec<double> w = quadratic_kernel_signal(wiener_record(u, v.cwiseAbs())).w;
  ASSERT_EQ(w.size(), u.size());
  EXPECT_GT(abs_correlation(w, v), 0.95);
  // while the linear correlation of |v| with v, all a linear fit can use, is ~0
  EXPECT_LT(abs_correlation(v.cwiseAbs(), v), 0.2);
}

TEST(QuadraticKernelSignal, TooFewRowsOrNonFiniteDataGiveNoSignal) {
  const Vec<double> u = gaussian(40, 1, 5).col(0);  // 28 regressors need ≥ 84 rows
  EXPECT_EQ(quadratic_kernel_signal(wiener_record(u, fir(kH, u))).w.size(), 0);
  Vec<double> u2 = gaussian(400, 1, 6).col(0);
  Vec<double> y2 = fir(kH, u2);
  y2(7) = std::nan("");
  EXPECT_EQ(quadratic_kernel_signal(wiener_record(u2, y2)).w.size(), 0);
}

}  // namespace
}  // namespace lpvid
