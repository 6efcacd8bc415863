#pragma once
/// Exploration, not part of the product (bench/README.md, "The full horizon
/// at 10 000 samples"): the full-horizon SISO Δ form of Theorem 2.1, min
/// d_max² at a fixed δ,
///   min_h ‖r − Z h‖² / N   s.t.   ‖T_h‖ ≤ δ   (⟺ δ²·I − T_h T_hᵀ ⪰ 0, (C1) by a Schur complement),
/// along the central path of q(h)/μ − log det(I − T_h̄ T_h̄ᵀ) (h̄ = h/δ),
/// with Newton systems solved by conjugate gradients on Hessian–vector
/// products: the data term's 2ZᵀZ/N by FFTs, the barrier's by
/// toeplitz/tap_norm_barrier.h, its value and interior test by the O(L²)
/// displacement Cholesky. No L × L matrix but that factor's triangle.
///
/// The path: after each μ reduction a predictor step along the central
/// path's tangent (H·ẋ = ∇q/μ², one more CG solve), then damped Newton steps;
/// the reduction factor adapts as in lmi/delta_form_barrier.h. CG stops at
/// the relative residual cg_tolerance or when the residual has reached no
/// new minimum for 50 iterations (both count as converged: near the end the
/// gradient is a difference of terms 10⁷ times larger, and its rounding
/// keeps the residual from falling further), else
/// at max_cg. A point is centred when the decrement is below `centred` with
/// CG converged (a CG stopped at max_cg gives a decrement from below).
///
/// What it answers is a floating estimate, not a certified bound: the taps
/// (inside the norm ball by the floating Schur test), their d_max², and the
/// path's lower estimate d_max² − 2Lμ (the duality gap of the central
/// point's dual μ·C1⁻¹ of the order-2L LMI, exact only at an exactly centred
/// point). One record, no free regressors.

#include <functional>
#include <string>

#include "core/scalar.h"

namespace lpvid {

struct LongHorizonOptions {
  double rel_gap = 1e-4;       ///< stop when 2Lμ ≤ rel_gap·q(h) at a centred point
  int max_newton = 400;        ///< Newton steps in all (a count, never time)
  int max_cg = 1000;           ///< CG iterations per solve
  double cg_tolerance = 1e-2;  ///< relative residual of each Newton system
  double centred = 0.05;       ///< Newton decrement² of a centred point
  double mu_factor = 8.0;      ///< the largest μ reduction
  double min_mu_factor = 1.5;
  int slow_centering = 4;
  /// After the gap is reached: up to this many full Newton steps at the last
  /// μ with CG to final_cg_tolerance, for a point centred well enough that
  /// its dual point (the compact certificate's recipe) nearly meets the dual
  /// equality (explore/long_horizon_dual.h). Steps stop below a decrement²
  /// of 1e-14 or when a step would leave the ball; damped by
  /// 1/(1 + decrement) above 0.25. (At L = 10 000 rounding holds the
  /// decrement² near 1e-14, and the steps taken there still lower the dual
  /// equality's residual: stopping at 1e-12 left 4.8e-9 instead of 1.6e-9
  /// and a certified gap of 4.3e-4 instead of 2.9e-4.)
  int final_centering = 0;
  double final_cg_tolerance = 1e-10;
  /// The final centering's Newton systems formed densely (L Hessian–vector
  /// products, L² doubles) and factored, instead of CG.
  bool final_dense = false;
  std::function<void(const std::string&)> progress;  ///< a line every 10 Newton steps
};

struct LongHorizonAnswer {
  bool converged = false;
  std::string message;          ///< why not, when not converged
  Eigen::Index horizon = 0;     ///< L = n − leading zeros of z
  Eigen::VectorXd taps;         ///< h (original units), length L
  double dmax2 = NAN;           ///< ‖r − Z h‖² / N at those taps
  double lower_estimate = NAN;  ///< dmax2 − 2Lμ (original units; not certified)
  /// μ of the last point (original units of d_max²): its dual point is
  /// U = μ·(δ²·I − T_h T_hᵀ)⁻¹ with g = −(r − Z h)/N, the recipe of the
  /// compact dual certificate (verify/certificate/path_dual.h).
  double mu = NAN;
  bool inside = false;          ///< δ²·I − T_h T_hᵀ ≻ 0 by the floating Schur test
  int newton_steps = 0;
  long cg_iterations = 0;       ///< in all, predictor solves included
  long factorisations = 0;      ///< O(L²) displacement Cholesky sweeps
  double final_decrement2 = NAN;  ///< the Newton decrement² after the final centering
};

/// z, r: n-vectors (the uncertainty input and the residual y − ŷ of one SISO
/// record); δ > 0. Throws std::invalid_argument on other shapes, non-finite
/// values or δ ≤ 0.
LongHorizonAnswer solve_long_horizon(const Eigen::VectorXd& z, const Eigen::VectorXd& r, double delta,
                                     const LongHorizonOptions& options = {});

}  // namespace lpvid
