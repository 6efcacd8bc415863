#pragma once
/// The factorisation of the structured barrier's Newton system H·dx = −g
/// (lmi/delta_form_barrier.cc): H is the Hessian of the barrier function
/// F_μ of "Robust identification and invalidation of LPV systems", Theorem
/// 2.1's LMI (8) in the Δ form, a dense symmetric matrix of order
/// L·ny·nz (+1 with δ² free).
///
/// H is positive definite wherever F_μ is strictly convex, so the Cholesky
/// factorisation H = L·Lᵀ is tried first: Eigen's blocked algorithm
/// (SplitLlt, its bits on one thread or two), about twice as fast as the
/// pivoted LDLᵀ at the 3×3 case's order 1 800. When rounding makes a pivot
/// non-positive (MIMO noise terms are flat along taps that do not change d,
/// lmi/delta_form_barrier.cc), the pivoted LDLᵀ (SplitLdlt) decides as
/// before: positive, or the caller shifts H. The final tight centering asks
/// for the pivoted LDLᵀ itself: near the optimum H is nearly singular, and
/// at SISO n = 3200 Cholesky there left a residual that took the lower
/// end's multiplier to x = 126·μ and the relative gap to 1.34e-3; with the
/// pivoted LDLᵀ for those last steps x = 12·μ and the gap 1.45e-4.

#include <Eigen/Dense>

#include "dense/split_factorisations.h"
#include "dense/split_llt.h"

namespace lpvid {

class HelperThread;

class NewtonFactor {
 public:
  /// Factors h (its lower triangle); `helper` (may be null) takes a share of
  /// the work; `pivoted`: the pivoted LDLᵀ without trying Cholesky.
  void compute(const Eigen::MatrixXd& h, HelperThread* helper, bool pivoted = false);
  /// Frees the factors' memory.
  void release();
  /// The factorisation succeeded and h is numerically positive definite.
  bool positive() const;
  /// h⁻¹·b (only when positive()).
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  /// The pivoted LDLᵀ was needed (the Cholesky factorisation met a non-positive pivot).
  bool pivoted() const { return pivoted_; }

 private:
  SplitLlt llt_;
  SplitLdlt ldlt_;
  bool pivoted_ = false;
};

}  // namespace lpvid
