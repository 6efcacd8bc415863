#pragma once
/// Theorem 3.1 (eq. 11–12) with the BMI relaxed by linearisation (docs/design.md §8.2),
/// in the w form of Theorem 2.1:
///
///   (C1)  [ Lin(q)   T_wᵀ ]
///         [ T_w      t·I  ]  ⪰ 0,   Lin(q) = T̄ᵀT_z(q) + T_z(q)ᵀT̄ − T̄ᵀT̄ ⪯ T_z(q)ᵀT_z(q)
///   (C2)  [ n·ny·s   dᵀ   ]
///         [ d        I    ]  ⪰ 0,   d = r(q) − w
///
/// with z(q) = zb + Z q, r(q) = rb − R q (affine in the unknowns q), T̄ =
/// T_z(q̄) at the linearisation point q̄. With q̄ = 0 and the initial model
/// this is exactly the paper's relaxation (after eq. 16); re-linearising at
/// the last solution is the convex–concave iteration (docs/design.md §8.3). Because
/// Lin ⪯ T_zᵀT_z, every feasible point is feasible for the true BMI.
/// When Z = 0 (additive uncertainty, or invalidation of a fixed model) Lin =
/// T_zᵀT_z and the program IS Theorem 2.1 / 3.1, not a relaxation.
///
/// Leading zeros (docs/design.md §7.3): if z_0 … z_{m−1} = 0 at q̄, the relaxation forces
/// them to stay 0 and forces w_0 … w_{m−1} = 0; callers keep those samples
/// at zero by construction (the columns of Z at those rows must vanish), and
/// the program lives on the horizon L = n − m.
///
/// All signals are n × (channels) in the layout of Experiment; q is scaled
/// per column and z, r by their RMS before reaching the solver.

#include <vector>

#include "core/scalar.h"
#include "lmi/bound_objective.h"
#include "solvers/lmi_program.h"
#include "solvers/sdp_solver.h"

namespace lpvid {

/// z(q) = zb + Σ_j q_j Z[j], r(q) = rb − Σ_j q_j R[j]; all n × nz / n × ny.
struct AffineSignals {
  Mat<double> zb, rb;
  std::vector<Mat<double>> Z, R;
  /// Paper mode only: T_z(q) is not the Toeplitz matrix of z. Then `Tz_paper`
  /// holds the fixed (n·nz) × n matrix and Z must be empty.
  Mat<double> Tz_paper;

  Eigen::Index n() const { return zb.rows(); }
  Eigen::Index nq() const { return static_cast<Eigen::Index>(Z.size()); }
  Mat<double> z_at(const Vec<double>& q) const;
  Mat<double> r_at(const Vec<double>& q) const;
};

struct RelaxedSolution {
  SolveResult solve;
  Eigen::Index leading_zeros = 0;  ///< m
  Vec<double> q;                   ///< unknowns, original units
  Mat<double> w;                   ///< n × ny (rows k < m are 0)
  double delta2 = 0.0, dmax2 = 0.0;
};

/// Builds the relaxed program at q̄ (size nq) and solves it.
RelaxedSolution solve_relaxed(const AffineSignals& sig, const Vec<double>& q_bar, const BoundObjective& objective,
                              SdpSolver& solver, const SolverOptions& options);

}  // namespace lpvid
