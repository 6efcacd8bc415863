#pragma once
/// Causal FIR filters on signals: the Δ of the Poolla form of (C1) (docs/design.md §7.5)
/// acting on the uncertainty channel z, and the leading
/// zero samples that causality pins (docs/design.md §7.3). Templated on the scalar.

#include "core/scalar.h"
#include "toeplitz/record_segments.h"

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
/// (One record; several: apply_fir_records of toeplitz/record_segments.h.)
template <typename T>
Mat<T> apply_fir(const Mat<T>& taps, const Mat<T>& z, Eigen::Index ny, Eigen::Index horizon) {
  return apply_fir_records(taps, z, ny, horizon, RecordLengths{});
}

}  // namespace lpvid
