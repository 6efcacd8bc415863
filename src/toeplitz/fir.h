#pragma once
/// Causal FIR filters on signals: the Δ of the Poolla form of (C1) (SPEC §4)
/// acting on the uncertainty channel z, and the leading
/// zero samples that causality pins (SPEC §9). Templated on the scalar.

#include "core/scalar.h"

namespace lpvid {

/// Number of leading samples k with z_k = 0 exactly (z is n × nz).
template <typename T>
Eigen::Index leading_zero_samples(const Mat<T>& z) {
  Eigen::Index m = 0;
  while (m < z.rows()) {
    bool zero = true;
    for (Eigen::Index j = 0; j < z.cols(); ++j)
      if (z(m, j) != T(0)) zero = false;
    if (!zero) break;
    ++m;
  }
  return m;
}

/// w = Δ ∗ z on the horizon L: w_k = Σ_{l=0}^{min(k−m, K−1)} h_l z_{k−l} for
/// k ≥ m = n − L, w_k = 0 for k < m. `taps` is K × (ny·nz) (K ≤ L; taps
/// h_K … h_{L−1} are zero), row l = h_l row-major. Returns n × ny. Callers
/// check that z_k = 0 for k < m, otherwise this is not the convolution.
template <typename T>
Mat<T> apply_fir(const Mat<T>& taps, const Mat<T>& z, Eigen::Index ny, Eigen::Index horizon) {
  const Eigen::Index n = z.rows(), nz = z.cols(), K = taps.rows(), m = n - horizon;
  Mat<T> w = Mat<T>::Zero(n, ny);
  for (Eigen::Index k = m; k < n; ++k)
    for (Eigen::Index l = 0; l <= k - m && l < K; ++l)
      for (Eigen::Index i = 0; i < ny; ++i) {
        T s(0);
        for (Eigen::Index j = 0; j < nz; ++j) s += taps(l, i * nz + j) * z(k - l, j);
        w(k, i) += s;
      }
  return w;
}

}  // namespace lpvid
