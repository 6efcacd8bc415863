#pragma once
/// The Cholesky factor of F = t·I − T_h T_hᵀ (T_h the L × L lower-triangular
/// Toeplitz matrix of the taps h: the Schur complement of the uncertainty LMI
/// [t·I, T_h; T_hᵀ, I] ⪰ 0 of Theorem 2.1's (C1) with SISO Δ, t = δ²) in
/// O(L²) operations, without forming F. T_h commutes with the lower shift S
/// and S Sᵀ = I − e₀e₀ᵀ, so
///   F − S F Sᵀ = t·e₀e₀ᵀ − h hᵀ = G J Gᵀ,  G = [√t·e₀, h],  J = diag(1, −1),
/// a displacement rank of 2. The generalised Schur algorithm turns the
/// generator's row k into (ρ_k, 0) by a hyperbolic rotation (in the mixed
/// form, stable for positive definite F); the first column is then column k
/// of the factor L (F = L Lᵀ, L_kk = ρ_k) and the next generator is
/// [S·g₁, g₂]. F is positive definite exactly when every rotation exists
/// (|g₂(k)| < g₁(k)), which is the interior test of the barrier; log det F =
/// 2 Σ log ρ_k.
/// Memory: O(L) for the test and log det alone; L(L+1)/2 doubles when the
/// factor is kept for solves (at L = 10 000: 400 MB).

#include <vector>

#include "core/scalar.h"

namespace lpvid {

class DisplacementCholesky {
 public:
  /// Factors F for these taps and t > 0; false when F is not positive
  /// definite (nothing else is valid then). keep_factor: store L for solve().
  bool factor(const Eigen::VectorXd& h, double t, bool keep_factor);
  double log_det() const { return log_det_; }
  Eigen::Index size() const { return L_; }
  /// F⁻¹ b (the factor must have been kept).
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  /// The dense factor (tests only).
  Eigen::MatrixXd dense_factor() const;

 private:
  const double* column(Eigen::Index k) const { return packed_.data() + k * L_ - k * (k - 1) / 2; }
  Eigen::Index L_ = 0;
  bool kept_ = false;
  double log_det_ = 0;
  std::vector<double> packed_;  ///< column k (rows k … L−1) from offset k·L − k(k−1)/2
};

/// log det(t·I − T_h T_hᵀ), or false when that matrix is not positive definite (O(L) memory).
bool displacement_log_det(const Eigen::VectorXd& h, double t, double* log_det);

/// ‖T_h‖² from above, by bisection on the interior test: the smallest t of
/// 64 halvings of [0, (Σ|h_l|)²] at which t·I − T_h T_hᵀ passed the Schur
/// test (floating point, O(L²) per test, O(L) memory).
double lower_toeplitz_norm2(const Eigen::VectorXd& h);

}  // namespace lpvid
