#pragma once
/// Root mean square over all entries of a matrix or vector: √(‖m‖_F² / size),
/// 0 for an empty one. The one definition used for residuals, signal scales
/// (certify/bound_scaling.h, the σ_z, σ_r of the LMI builders) and the
/// output RMS a noise bound is compared with (docs/design.md §7.4 normalises over n·ny
/// entries the same way).

#include <cmath>

#include <Eigen/Core>

namespace lpvid {

template <typename Derived>
double rms(const Eigen::MatrixBase<Derived>& m) {
  if (m.size() == 0) return 0.0;
  return std::sqrt(m.squaredNorm() / static_cast<double>(m.size()));
}

}  // namespace lpvid
