#pragma once
/// Levenberg–Marquardt minimisation of ½‖r(p)‖² (Marquardt 1963; Nocedal &
/// Wright, Numerical Optimization, 2nd ed., §10.3) with a forward-difference
/// Jacobian. Used for the output-error refinement of fit/linear_fit.h and
/// for fitting static blocks around it: the residual is a free-run simulation
/// error, whose exact Jacobian would need one sensitivity simulation per
/// parameter anyway.

#include <functional>

#include "core/scalar.h"

namespace lpvid {

struct LmOptions {
  int max_iterations = 200;         ///< accepted + rejected steps
  double relative_tolerance = 1e-12;  ///< stop when the cost falls by less than this fraction
  double initial_damping = 1e-3;    ///< λ relative to the mean diagonal of JᵀJ
};

struct LmResult {
  Vec<double> p;        ///< best parameters found
  double cost = 0;      ///< ½‖r(p)‖²
  int iterations = 0;   ///< steps tried
  bool converged = false;
};

/// Residual function r(p) (any fixed length m).
using Residual = std::function<Vec<double>(const Vec<double>&)>;
/// Optional admissibility test of a trial point (e.g. "A is stable"); a step
/// to an inadmissible point is rejected like one that raises the cost.
using Admissible = std::function<bool(const Vec<double>&)>;

/// What the forward-difference Jacobian evaluates for its column j: r(q) at
/// q = p + h_j·e_j (the point p, the column j). Given r itself, or a faster
/// way to the same numbers (fit/output_error_fit.cc: a column that moves only
/// the output map reuses p's state trajectory).
struct JacobianColumns {
  /// Called once per Jacobian, at p, before the columns (may be empty).
  std::function<void(const Vec<double>& p)> at;
  /// r(q) for q = p + h_j·e_j, j the column.
  std::function<Vec<double>(const Vec<double>& q, Eigen::Index j)> column;
};

/// Minimises ½‖r(p)‖² from p0 (which must be admissible and give a finite
/// residual; throws std::invalid_argument otherwise). Each iteration solves
/// (JᵀJ + λ diag(JᵀJ)) Δ = −Jᵀr (Marquardt's scaling), accepts the step if the
/// cost decreases (λ /= 3) and otherwise raises λ (×4). `columns`, when
/// given, computes the Jacobian's residuals (they must be r's numbers).
LmResult levenberg_marquardt(const Residual& r, const Vec<double>& p0, const LmOptions& options = {},
                             const Admissible& admissible = nullptr, const JacobianColumns* columns = nullptr);

/// Forward-difference Jacobian of r at p (m × size(p)), step
/// h_j = √ε · max(1, |p_j|), given r(p) = r0.
Mat<double> forward_difference_jacobian(const Residual& r, const Vec<double>& p, const Vec<double>& r0);
/// The same with the columns' residuals from `columns` (same steps, same sums).
Mat<double> forward_difference_jacobian(const JacobianColumns& columns, const Vec<double>& p, const Vec<double>& r0);

}  // namespace lpvid
