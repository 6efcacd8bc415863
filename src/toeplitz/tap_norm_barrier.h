#pragma once
/// The barrier B(h) = −log det(t·I − T_h T_hᵀ) of the SISO uncertainty LMI
/// (Theorem 2.1's (C1) with Δ lower-triangular Toeplitz, ‖T_h‖² ≤ t = δ²),
/// with its gradient and Hessian–vector products in O(L log L) after an
/// O(L²) factorisation: no L × L matrix is formed (the dense barrier of
/// lmi/delta_form_barrier.h costs O(L³) and O(L²) per Newton step).
///
/// P = F⁻¹ has displacement rank 2 with respect to Sᵀ (F − S F Sᵀ has rank 2,
/// toeplitz/displacement_cholesky.h):
///   D = P − Sᵀ P S = α·x xᵀ − β·y yᵀ,   x = P e_{L−1},  p = P h,  y = Sᵀ p,
///   α = 1 / x_{L−1},  β = 1 / (1 + hᵀ p),
/// hence P = Σ_j Sᵀʲ D Sʲ = α·H(x) H(x) − β·H(y) H(y) with H(u)(i, k) =
/// u_{i+k} (a Hankel matrix, zero past L−1): a Gohberg–Semencul form
/// (checked against the dense inverse in tests/toeplitz/tap_norm_barrier_test.cc).
/// The gradient (dF[v] = −(T_v T_hᵀ + T_h T_vᵀ), ⟨X, T_v⟩ = Σ_l v_l Ω_l(X),
/// Ω_l the l-th subdiagonal sum):
///   ∂B/∂h_l = 2 Ω_l(P T_h) = 2 Σ_k h_k Σ_{c≥0} P(l+c, k+c)
///           = 2 Σ_k h_k Σ_{s≥0} (s+1) D(l+s, k+s)
///           = 2α·(H(x) R T_hᵀ x)_l − 2β·(H(y) R T_hᵀ y)_l,   R = diag(1, 2, …, L),
/// and the Hessian–vector product is its derivative along v, with
///   dx = P M_v x,  dp = P (M_v p + v),  dy = Sᵀ dp,  M_v = T_v T_hᵀ + T_h T_vᵀ,
///   dα = −α² dx_{L−1},  dβ = −β² (vᵀp + hᵀdp),
///   d(H(u) R T_hᵀ u) = H(du) R T_hᵀ u + H(u) R (T_vᵀ u + T_hᵀ du).
/// Every product is a triangular Toeplitz or Hankel product of length-L
/// vectors (toeplitz/fft_convolver.h): about 30 transforms of size ≥ 2L per
/// Hessian–vector product.

#include "toeplitz/displacement_cholesky.h"
#include "toeplitz/fft_convolver.h"

namespace lpvid {

class TapNormBarrier {
 public:
  explicit TapNormBarrier(Eigen::Index L) : conv_(L) {}

  /// Sets the point (h of length L, t > 0); false outside the interior.
  bool set_point(const Eigen::VectorXd& h, double t);
  double value() const { return -chol_.log_det(); }
  const Eigen::VectorXd& gradient() const { return gradient_; }
  Eigen::VectorXd hessian_times(const Eigen::VectorXd& v) const;
  /// P w by the generator form.
  Eigen::VectorXd inverse_times(const Eigen::VectorXd& w) const;
  long transforms() const { return conv_.transforms(); }

 private:
  using Spectrum = FftConvolver::Spectrum;
  Eigen::VectorXd inverse_times_spectrum(const Spectrum& w_hat) const;
  Eigen::VectorXd uncertainty_times(const Spectrum& v_hat, const Spectrum& w_hat) const;  ///< M_v w
  /// The spectrum of κ·H(u) R T_hᵀ u's derivative: dκ·H(u)w + κ·(H(du) w + H(u) R (T_vᵀu + T_hᵀdu)), w = R T_hᵀ u.
  Spectrum generator_derivative(double kappa, double dkappa, const Spectrum& u_hat, const Spectrum& w_hat,
                                const Spectrum& v_hat, const Eigen::VectorXd& du) const;

  FftConvolver conv_;
  DisplacementCholesky chol_;
  Eigen::VectorXd h_, x_, p_, gradient_;
  double alpha_ = 0, beta_ = 0;
  Spectrum h_hat_, x_hat_, y_hat_, xw_hat_, yw_hat_;  ///< h, x, y and R T_hᵀ x, R T_hᵀ y
};

}  // namespace lpvid
