#include "fit/wiener_starts.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "fit/model_parameters.h"
#include "fit/output_error_fit.h"

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

namespace {

/// φ: each input through the Laguerre filters L_0 = √(1−a²)/(1 − a q⁻¹),
/// L_j = L_{j−1}·(q⁻¹ − a)/(1 − a q⁻¹), j < m (L_0 keeps the feedthrough).
Mat<double> laguerre_regressors(const Mat<double>& u, double a, int m) {
  const Eigen::Index n = u.rows();
  Mat<double> phi(n, u.cols() * m);
  const double g = std::sqrt(1 - a * a);
  for (Eigen::Index i = 0; i < u.cols(); ++i) {
    Eigen::Index c = i * m;
    for (Eigen::Index k = 0; k < n; ++k) phi(k, c) = g * u(k, i) + (k > 0 ? a * phi(k - 1, c) : 0.0);
    for (int j = 1; j < m; ++j, ++c)
      for (Eigen::Index k = 0; k < n; ++k)
        phi(k, c + 1) = k > 0 ? a * phi(k - 1, c + 1) + phi(k - 1, c) - a * phi(k, c) : -a * phi(k, c);
  }
  return phi;
}

}  // namespace

QuadraticKernel quadratic_kernel_signal(const Experiment<double>& est) {
  constexpr int kFilters = 6;
  const Eigen::Index n = est.n(), p = est.u.cols() * kFilters, q = 1 + p + p * (p + 1) / 2;
  QuadraticKernel out;
  if (est.y.cols() != 1 || p == 0 || n < 3 * q || !est.u.allFinite() || !est.y.allFinite()) return out;
  double best = std::numeric_limits<double>::infinity();
  for (const double a : {0.0, 0.5, 0.8}) {
    const Mat<double> phi = laguerre_regressors(est.u, a, kFilters);
    Mat<double> X(n, q);
    X.col(0).setOnes();
    X.middleCols(1, p) = phi;
    for (Eigen::Index i = 0, c = 1 + p; i < p; ++i)
      for (Eigen::Index j = i; j < p; ++j) X.col(c++) = phi.col(i).cwiseProduct(phi.col(j));
    const Vec<double> beta = X.colPivHouseholderQr().solve(Vec<double>(est.y.col(0)));
    if (!beta.allFinite()) continue;
    const double res = (X * beta - est.y.col(0)).squaredNorm();
    if (!(res < best)) continue;
    Mat<double> K = Mat<double>::Zero(p, p);
    for (Eigen::Index i = 0, c = 1 + p; i < p; ++i)
      for (Eigen::Index j = i; j < p; ++j, ++c) {
        K(i, j) += (i == j ? 1.0 : 0.5) * beta(c);
        if (i != j) K(j, i) += 0.5 * beta(c);
      }
    const Eigen::SelfAdjointEigenSolver<Mat<double>> eig(K);
    if (eig.info() != Eigen::Success) continue;
    const Vec<double> ev = eig.eigenvalues();
    Eigen::Index top = 0;
    ev.cwiseAbs().maxCoeff(&top);
    best = res;
    out.w = phi * eig.eigenvectors().col(top);
    out.rms = std::sqrt(res / static_cast<double>(n));
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
