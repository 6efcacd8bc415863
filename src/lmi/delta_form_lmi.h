#pragma once
/// Theorem 2.1 for a FIXED model in the well-conditioned Δ form (Poolla et
/// al.; docs/design.md §7.5):
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
/// and the problem lives on the horizon L = n − m (docs/design.md §7.3): w_k =
/// Σ_{l=0}^{k−m} h_l z_{k−l}, and only the taps h_0 … h_{L−1} matter.
///
/// Several records (toeplitz/record_segments.h): z and r stack K records of
/// one system under one Δ, each from rest for Δ. The horizon is then
/// L = max_k (n_k − m_k) (m_k the leading zero samples of record k's z),
/// (C1') is the same block on that L, and d = r − Δ∗z with Δ∗z taken record
/// by record (apply_fir_records): no lag reaches into another record. (C2)
/// keeps N = (Σ n_k)·ny rows in the stacked order of r.
///
/// Numbers are scaled before they reach the solver (z by its RMS σ_z, r by
/// σ_r); `DeltaFormSolution` is in the original units.

#include <optional>
#include <string>

#include "core/scalar.h"
#include "lmi/bound_objective.h"
#include "lmi/noise_block.h"
#include "solvers/lmi_program.h"
#include "toeplitz/fir.h"
#include "toeplitz/record_segments.h"
#include "solvers/sdp_solver.h"

namespace lpvid {

struct DeltaFormSolution {
  SolveResult solve;           ///< the backend's answer (x in scaled units)
  /// m; several records: the rows before each record's first nonzero z,
  /// Σ_k m_k (then not n − L: use horizon, or records_horizon)
  Eigen::Index leading_zeros = 0;
  Mat<double> taps;            ///< K × (ny·nz), original units (K ≤ L = n − leading_zeros for one record)
  Eigen::Index horizon = 0;    ///< L (several records: max_k (n_k − m_k))
  double delta2 = 0.0;         ///< t (original units); the fixed value if δ was fixed
  double dmax2 = 0.0;          ///< s (original units); the fixed value if d_max was fixed
  /// With SolverOptions::want_dual: the dual matrices of (C1') and (C2) in
  /// ORIGINAL units (the solver's, mapped back by the congruences that scaled
  /// the program: Y1 = D Y1' D, D = diag(σ_z/σ_r·I, I); Y2 = E Y2' E,
  /// E = diag(1/σ_r, I)), for toeplitz/delta_form_dual.h. Empty otherwise.
  /// For a primal-infeasible solve they are the backend's infeasibility
  /// certificate (any positive scale).
  Mat<double> dual_c1, dual_c2;
  /// Set by the structured barrier (lmi/delta_form_barrier.h): dual_c1 is
  /// μ·C1⁻¹ at the point (taps, t = delta2) in original units, i.e.
  /// [I; −Tᵀ]·μ(t·I − T Tᵀ)⁻¹·[I; −Tᵀ]ᵀ + diag(0, μ·I) — the recipe of the
  /// compact dual certificate (verify/certificate/path_dual.h). 0 when the dual matrices
  /// come from elsewhere.
  double path_mu = 0.0;
  /// Why this answer is not the structured barrier's although it applied:
  /// the barrier's failure ("structured barrier: …"), after which the SDP
  /// backend solved the same program (lmi/delta_form_solve.h). Empty otherwise.
  std::string fallback;
  /// What produced this answer: "structured barrier", or the SDP backend's
  /// name (SdpSolver::name()) when it solved the program. Reports name it.
  std::string solver_used;
  /// With free regressors G (lmi/free_regressors.h; length P, empty without):
  /// q = argmin ‖r − Δ∗z − G q‖ for the returned taps, minimum-norm in G's
  /// coordinates when G is rank deficient.
  Vec<double> free_coefficients;
  /// d = r − Δ∗z − G q (n × ny, original units; r − Δ∗z without free
  /// regressors). Filled by the structured barrier and by solve_delta_form.
  Mat<double> noise_residual;
};

/// Builds and solves the Δ-form program. z is n × nz, r is n × ny (doubles).
/// Throws InputError when z ≡ 0 (δ undetermined: the data does not excite
/// the uncertainty channel, e.g. u ≡ 0 with x0 = 0).
/// `max_taps` K > 0 restricts Δ to K taps (h_l = 0 for l ≥ K): a restriction,
/// so the bounds are upper bounds on the full-length optimum, still sound,
/// and the program has K·ny·nz tap variables with O(K·L) nonzeros instead
/// of O(L²) (the cost that dominates the solvers here). 0 means K = L.
/// `free_regressors` G ((n·ny) × P, stacked like r; 0 columns: none) adds
/// free unknowns to d = r − Δ∗z − G q (lmi/free_regressors.h): the program
/// gets one free variable per column of an orthonormal basis Q of range(G)
/// (so zero or dependent columns cost nothing and leave the program well
/// posed), and the answer's free_coefficients are the minimum-norm q with
/// G q = Q·(those variables). Throws std::invalid_argument for a G without
/// n·ny rows.
/// `records` (lengths of the stacked records; empty: one record of all rows)
/// gives the several-records program above (K taps: h_0 … h_{K−1} of the
/// horizon L); throws std::invalid_argument when the lengths do not add up to n.
DeltaFormSolution solve_delta_form(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective,
                                   SdpSolver& solver, const SolverOptions& options, Eigen::Index max_taps = 0,
                                   const Mat<double>& free_regressors = {}, const RecordLengths& records = {});

/// Where a Δ-form program (this file or delta_kyp_lmi.h) keeps its scaled
/// variables: h_l(i, j) at tap0 + l·ny·nz + i·nz + j (K taps), δ²' at t and
/// d_max²' at s (−1 when fixed); z was divided by σ_z and r by σ_r.
struct DeltaScaledVariables {
  Eigen::Index K = 0, ny = 0, nz = 0;
  int tap0 = -1, t = -1, s = -1;
  double sigma_z = 1.0, sigma_r = 1.0;
};
/// The solution in original units: taps (K × ny·nz, zero without a
/// solution), δ² and d_max² (the fixed values when fixed or without a
/// solution; a solver's tiny negative value reads as 0).
void read_delta_solution(const SolveResult& solve, const DeltaScaledVariables& v, const BoundObjective& objective,
                         Mat<double>& taps, double& delta2, double& dmax2);

/// The program alone (for --write-sdpa and an outside solver's answer), the
/// same program and scaling as solve_delta_form, with its variables named
/// ("h<l>[<i>,<j>]", "delta2", "dmax2") and its meaning in
/// LmiProgram::about: kind "theorem-2.1-delta-form", sigma_z, sigma_r,
/// samples n, leading_zeros m, horizon L, taps K, ny, nz, and how each
/// variable maps back to original units (several records: also "records",
/// the lengths).
struct DeltaFormProgram {
  LmiProgram program;
  DeltaScaledVariables variables;
  Eigen::Index leading_zeros = 0, horizon = 0;
};
DeltaFormProgram delta_form_program(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective,
                                    Eigen::Index max_taps = 0, const RecordLengths& records = {});
/// The value of LmiProgram::about's "kind" for these programs.
inline constexpr const char* kDeltaFormKind = "theorem-2.1-delta-form";

}  // namespace lpvid
