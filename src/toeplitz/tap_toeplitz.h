#pragma once
/// Products with the block lower-triangular Toeplitz matrix T_Δ of FIR taps
/// (L·ny × L·nz; rows a·ny + i, columns b·nz + j; T(a, b) = h_{a−b}, a ≥ b),
/// without forming dense products: the kernels of the structured barrier
/// (lmi/delta_form_barrier.h) and of the compact dual certificate
/// (verify/certificate/path_dual.h).
///
/// Taps are given as an L × (ny·nz) matrix: column i·nz + j holds h_ij(0 … L−1).

#include <memory>

#include "core/scalar.h"

namespace lpvid {

/// T itself, dense (L·ny × L·nz), over any scalar: the definition the fast
/// products are checked against, and the exact T of verify/certificate/path_dual.h.
template <typename S>
Mat<S> tap_toeplitz_dense(const Mat<S>& taps, Eigen::Index ny, Eigen::Index nz) {
  const Eigen::Index L = taps.rows();
  Mat<S> T = Mat<S>::Zero(L * ny, L * nz);
  for (Eigen::Index a = 0; a < L; ++a)
    for (Eigen::Index b = 0; b <= a; ++b)
      for (Eigen::Index i = 0; i < ny; ++i)
        for (Eigen::Index j = 0; j < nz; ++j) T(a * ny + i, b * nz + j) = taps(a - b, i * nz + j);
  return T;
}

/// T Tᵀ (L·ny square) by (T Tᵀ)(a, a') = (T Tᵀ)(a−1, a'−1) + h_a h_a'ᵀ
/// (blocks; the first block row and column are h_a h_0ᵀ, h_0 h_a'ᵀ):
/// O(L²·ny²·nz) instead of O(L³). Fixed loop order (deterministic).
Mat<double> tap_gram(const Mat<double>& taps, Eigen::Index ny, Eigen::Index nz);
/// The same into G (resized once: no allocation per call).
void tap_gram_into(const Mat<double>& taps, Eigen::Index ny, Eigen::Index nz, Mat<double>& G);

/// X·T for dense X (rows × L·ny) by FFT correlations along each row:
///   (X·T)(row, b·nz + j) = Σ_{i'} Σ_{c ≥ b} X(row, c·ny + i') h_{i'j}(c − b),
/// O(rows·L·log L·(ny + nz)) instead of O(rows·L²·ny·nz). Tᵀ·Y = (Yᵀ·T)ᵀ.
/// Thread-safe after construction.
class ToeplitzProduct {
 public:
  ToeplitzProduct(const Mat<double>& taps, Eigen::Index ny, Eigen::Index nz);
  ~ToeplitzProduct();
  ToeplitzProduct(const ToeplitzProduct&) = delete;
  ToeplitzProduct& operator=(const ToeplitzProduct&) = delete;
  Mat<double> right(const Mat<double>& X) const;
  /// out ← X·T (out resized once; the same numbers as right(X)).
  void right_into(const Mat<double>& X, Mat<double>& out) const;
  /// out ← Tᵀ·Y, bit for bit right(Yᵀ)ᵀ without the two transposed copies.
  void left_into(const Mat<double>& Y, Mat<double>& out) const;
  /// New taps of the same size: the plans are kept (a solver's one per solve, not one per Newton step).
  void set_taps(const Mat<double>& taps);

 private:
  /// For blocks of up to kRowBlock rows (row0 … row0 + n − 1):
  /// gather(row0, n, i, real, Ms) fills real[k·Ms + c] with sample c of input
  /// i of row row0 + k, scatter(row0, n, j, real, Ms, scale) stores
  /// (X·T)(row0 + k, b·nz + j) = real[k·Ms + b]·scale. Each row is transformed alone.
  template <typename Gather, typename Scatter>
  void apply(Eigen::Index rows, Gather gather, Scatter scatter) const;
  Eigen::Index L_, ny_, nz_, M_, H_;
  std::shared_ptr<std::complex<double>> h_hat_;  ///< (ny·nz) spectra of length H (column i·nz + j)
  void* forward_ = nullptr;
  void* backward_ = nullptr;
};

}  // namespace lpvid
