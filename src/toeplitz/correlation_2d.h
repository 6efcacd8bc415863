#pragma once
/// Two-dimensional cross-correlations of square matrices by FFT, the kernel
/// of the structured (Toeplitz) Hessian in lmi/delta_form_barrier.h.
///
///   corr(X, Y)(p, q) = Σ_{i,j} X(i + p, j + q) · Y(i, j)
///
/// (entries outside X are zero). For L × L inputs and shifts p ∈ [0, L),
/// q ∈ (−L, L) this costs O(L² log L) instead of the O(L⁴) of the sum.

#include "core/scalar.h"

namespace lpvid {

/// The spectra of L × L real matrices zero-padded to an M × M grid
/// (M ≥ 2L), reused across several correlations.
class CorrelationGrid {
 public:
  explicit CorrelationGrid(Eigen::Index L);
  Eigen::Index size() const { return M_; }
  /// The 2-D DFT of X (L × L), zero-padded to M × M.
  Eigen::MatrixXcd spectrum(const Mat<double>& X) const;
  /// corr(X, Y)(p, sign·q) for p, q ∈ [0, L) from the spectra of X and Y:
  /// sign = +1 gives shifts q ≥ 0, sign = −1 gives q ≤ 0.
  Mat<double> correlate(const Eigen::MatrixXcd& X_hat, const Eigen::MatrixXcd& Y_hat, int sign) const;

 private:
  Eigen::Index L_, M_;
};

/// The same sum evaluated directly, O(L⁴): the reference for tests.
Mat<double> correlate_direct(const Mat<double>& X, const Mat<double>& Y, int sign);

}  // namespace lpvid
