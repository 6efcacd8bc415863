#pragma once
/// Theorem 2.1 for a FIXED model in the well-conditioned Δ form (Poolla et
/// al.; SPEC §4, issue 3 item 5):
///
///   w = Δ ∗ z with a causal FIR Δ (taps h_0 … h_{L−1}, each ny × nz), and
///   (C1')  [ t·I      T_Δ ]
///          [ T_Δᵀ     I   ]  ⪰ 0     ⇔  ‖T_Δ‖² ≤ t = δ²       (size L·(ny+nz))
///   (C2)   [ n·ny·s   dᵀ  ]
///          [ d        I   ]  ⪰ 0     ⇔  ‖d‖² ≤ n·ny·s = n·ny·d_max²
///   d = r − w,  r = y − ŷ − Φ (the residual, stacked).
///
/// (C1') implies (C1): T_w = T_Δ T_z, so T_wᵀT_w ⪯ δ² T_zᵀT_z. For SISO (and
/// whenever T_z is invertible after removing leading zeros) the two are
/// equivalent. Unlike (C1) it never forms T_zᵀT_z, whose condition number is
/// the square of the data's.
///
/// Leading zeros: if z_0 = … = z_{m−1} = 0 then (C1) forces w_0 … w_{m−1} = 0
/// and the problem lives on the horizon L = n − m (SPEC §9): w_k =
/// Σ_{l=0}^{k−m} h_l z_{k−l}, and only the taps h_0 … h_{L−1} matter.
///
/// Numbers are scaled before they reach the solver (z by its RMS σ_z, r by
/// σ_r); `DeltaFormSolution` is in the original units.

#include <optional>

#include "core/scalar.h"
#include "lmi/bound_objective.h"
#include "lmi/lmi_program.h"
#include "solvers/sdp_solver.h"

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

/// w = Δ ∗ z on the horizon: w_k = Σ_{l=0}^{min(k−m, L−1)} h_l z_{k−l} for k ≥ m,
/// w_k = 0 for k < m, where L = taps.rows(), m = n − L. `taps` is L × (ny·nz),
/// row l = h_l row-major. Returns n × ny.
template <typename T>
Mat<T> apply_fir(const Mat<T>& taps, const Mat<T>& z, Eigen::Index ny) {
  const Eigen::Index n = z.rows(), nz = z.cols(), L = taps.rows(), m = n - L;
  Mat<T> w = Mat<T>::Zero(n, ny);
  for (Eigen::Index k = m; k < n; ++k)
    for (Eigen::Index l = 0; l <= k - m; ++l)
      for (Eigen::Index i = 0; i < ny; ++i) {
        T s(0);
        for (Eigen::Index j = 0; j < nz; ++j) s += taps(l, i * nz + j) * z(k - l, j);
        w(k, i) += s;
      }
  return w;
}

struct DeltaFormSolution {
  SolveResult solve;           ///< the backend's answer (x in scaled units)
  Eigen::Index leading_zeros;  ///< m
  Mat<double> taps;            ///< L × (ny·nz), original units
  double delta2 = 0.0;         ///< t (original units); the fixed value if δ was fixed
  double dmax2 = 0.0;          ///< s (original units); the fixed value if d_max was fixed
};

/// Builds and solves the Δ-form program. z is n × nz, r is n × ny (doubles).
/// Throws InputError when z ≡ 0 (δ undetermined: the data does not excite
/// the uncertainty channel, e.g. u ≡ 0 with x0 = 0).
DeltaFormSolution solve_delta_form(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective,
                                   SdpSolver& solver, const SolverOptions& options);

/// The program alone (for --write-sdpa), same scaling as solve_delta_form.
LmiProgram delta_form_program(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective);

}  // namespace lpvid
