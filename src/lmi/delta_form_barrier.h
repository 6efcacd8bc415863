#pragma once
/// The full-horizon Δ form (lmi/delta_form_lmi.h, (C1') and (C2)), SISO and
/// MIMO, solved by a primal barrier method that exploits its Toeplitz
/// structure (SISO n = 400 with both ends certified within a minute; a
/// general SDP backend spends O(L⁴) per iteration there).
///
/// Variables h ∈ R^L and t = δ² (when δ is free), in the scaled units of
/// delta_form_lmi.cc; for MIMO one tap sequence h_ij ∈ R^L per entry (i, j)
/// of Δ (ny × nz), T_h block lower-triangular Toeplitz (rows a·ny + i,
/// columns b·nz + j) and d_i = r_i − Σ_j Z_j h_ij. The barrier is the LMIs' own:
///   −log det C1' = −log det(t·I − T_h T_hᵀ)        (Schur complement on I)
///   −log det C2  = −log(N·s − ‖d‖²),  d = r − Z h
/// and the method follows the central path of min cᵀx/μ − log det C1' −
/// log det C2 with damped Newton steps, μ ↓ 0. The noise variable s is
/// eliminated exactly: for fixed h the minimum over s of c_s·s/μ − log(N s −
/// ‖d‖²) is at N s − ‖d‖² = N μ/c_s, which leaves
///   F_μ(h, t) = c_t·t/μ + c_s·‖d‖²/(N μ) − log det(t·I − T_h T_hᵀ),
/// a quadratic plus a log-det (a primal barrier that keeps s as a variable
/// crawls along the boundary of (C2): measured, 200+ Newton steps at n = 200).
/// Derivatives (P = (tI − TTᵀ)⁻¹, Q = P·T, R = Tᵀ·P·T, S_l the l-th lower
/// shift, Ω_l the l-th subdiagonal sum, corr as in toeplitz/correlation_2d.h):
///   ∂/∂h_l [−log det] = 2 Ω_l(Q),   ∂/∂t = −tr P,
///   ∂²/∂h_k∂h_l = 2 [Σ_c P(c+k, c+l) + corr(Q, Qᵀ)(k, −l) + corr(P, R)(k, l)],
///   ∂²/∂t∂h_l = −2 Ω_l(P·Q),   ∂²/∂t² = ‖P‖_F²,
/// the correlations by FFT: O(L³) per Newton step instead of the O(L⁴) of a
/// general SDP backend's Schur complement. MIMO: the same sums on the L × L
/// sub-blocks X_ab(a, b) = X(a·p + i, b·q + j) of P, Q, R; the Hessian block
/// of entry (i, j) at shift k against (i', j') at shift l is
///   2·sym([j = j']·Σ_c P_ii'(c+k, c+l) + corr(Q_ij', Q_i'jᵀ)(k, −l) + corr(P_ii', R_jj')(k, l)),
/// the noise adds 2[i = i']·Z_jᵀZ_j' (scaled), ∂²/∂t∂h_ij = −2 Ω((PQ)_ij).
/// Along taps that do not change d (nz > 1) the noise term is singular and at
/// small μ it dwarfs the log-det curvature: a zero pivot gets a Levenberg
/// shift (measured: ny = nz = 2, n = 3 hit it).
/// On the central path Y = μ·C⁻¹ is dual feasible (the dual equality holds up
/// to the Newton residual), with C1'⁻¹ = [P, −Q; −Qᵀ, I + R] and
/// C2⁻¹ = [1/φ, −dᵀ/φ; −d/φ, I + d dᵀ/φ] (φ = N s − ‖d‖²): these are the
/// dual matrices handed to certify/dual_certify.h, which makes the dual
/// equality exact. Nothing here is trusted: both ends are certified exactly.
///
/// Objectives: min d_max² at δ, the weighted one (0 < λ < 1), and fixed
/// (δ, d_max), answered through min d_max² at δ: kOptimal when a point with
/// s ≤ d_max² is found (the taps are then feasible), kPrimalInfeasible when
/// the path's lower estimate exceeds d_max² (the dual matrices then give the
/// "invalidated" certificate).
/// min δ² at a fixed d_max: s is fixed and cannot be eliminated, so (C2)
/// keeps its barrier: F_μ(h, t) = t/μ − log det(t·I − T_h T_hᵀ) − log φ,
/// φ = N·s − ‖d‖², with ∂/∂h[−log φ] = −2 Zᵀd/φ and ∂²/∂h² = 4 Zᵀd dᵀZ/φ²
/// + 2 ZᵀZ/φ (Z the lower-triangular Toeplitz matrix of z). The start must
/// satisfy φ > 0: h = θ·Z⁻¹r (Z is invertible once the leading zeros of z are
/// cut) with θ putting ‖d‖² halfway between its floor (the rows before the
/// first nonzero z) and N·s. The dual matrices are μ·C⁻¹ as above, with φ
/// the actual slack of (C2).
///
/// Free regressors (lmi/free_regressors.h): with G ((n·ny) × P, column c the
/// stacked n × ny signal g_c, row k·ny + i = output i at sample k, the rows of
/// d in (C2)) the noise residual of Theorem 2.1's (C2) becomes
///   d = r − Z h − G q,   q ∈ R^P free (eq. (C2) with linear unknowns),
/// and minimising over q leaves d = P⊥(r − Z h), P⊥ = I − Q Qᵀ with Q an
/// orthonormal basis of range(G) (rank-revealing: zero or dependent columns
/// add nothing). Every formula above holds with d projected: ‖d‖² =
/// ‖P⊥r − P⊥Z h‖², ∂‖d‖²/∂h = −2 Zᵀd, ∂²‖d‖²/∂h² = 2 ZᵀZ − 2 W Wᵀ with
/// W = ZᵀQ (a rank-P correction of the Toeplitz Gram, built once), φ =
/// N s − ‖d‖², the ridge start on P⊥r, and C2⁻¹ built from the projected d.
/// Hence the dual of (C2), Y2 = μ·C2⁻¹ = (1/σ)[σ; g][σ; g]ᵀ + μ·[0, 0; 0, I]
/// with σ = μ/φ and g = −μ d/φ ∝ d, satisfies the dual equality of the q
/// variables, Gᵀg = 0, up to rounding and the rank tolerance: ‖Gᵀg‖ ≤
/// ~1e-10·‖G‖‖g‖ (tested at 1e-9; when d itself is at the rounding of r, as
/// for r in range(G) + what the taps fit, relative to g's size at ‖d‖ =
/// 1e-8‖r‖). Unlike the taps' dual equality it does not depend on centering:
/// d is projected exactly at every iterate. The answer
/// carries q = argmin ‖r − Z h − G q‖ for the final h (minimum-norm in G's
/// coordinates when G is rank deficient) and d = r − Z h − G q. All four
/// objectives accept free regressors. With P = 0 the computation is
/// bit-for-bit the one without them.
///
/// Several records (toeplitz/record_segments.h: K records stacked row-wise,
/// each from rest for Δ): the horizon is L = max_k (n_k − m_k) and only the
/// data term changes. Z_j stacks, record by record, the (n_k − m_k)-square
/// lower-triangular Toeplitz block of record k's z_j from its own first
/// nonzero sample m_k, padded with zero columns up to L; the rows before each
/// m_k are head rows (r only, no Δ). −log det(t·I − T_h T_hᵀ) and its
/// derivatives depend on L only; ZᵀZ (L × L) is formed once, so a Newton step
/// costs what one record of length L costs plus O((Σ_k (n_k − m_k))·L) for
/// the residual. N = (Σ n_k)·ny and (C2)'s rows, its dual and noise_residual
/// stay in the stacked order of r. With one record ({n} or the empty list)
/// the computation is bit-for-bit the one-record one.

#include "lmi/bound_objective.h"
#include "lmi/delta_form_lmi.h"

namespace lpvid {

/// How reports and certificates name this solver (DeltaFormSolution::solver_used).
inline constexpr const char* kStructuredBarrierName = "structured barrier";

struct BarrierOptions {
  /// Stop when ν·μ ≤ rel_gap·|objective| (ν = 2L + N + 1). Not smaller: near
  /// the boundary C⁻¹ (the dual) loses accuracy, and the residual of the dual
  /// equality costs a PSD margin in the certified lower end (measured: at
  /// 1e-5 the margin cost 9e-4 of the objective on SISO n = 100).
  double rel_gap = 1e-4;
  double feasibility_rel_gap = 1e-9;  ///< fixed (δ, d_max): keep going until decided, down to this
  double abs_gap = 1e-14;    ///< … or ν·μ ≤ abs_gap (scaled units)
  int max_newton = 400;      ///< Newton steps in all
  double mu_factor = 8.0;    ///< μ ← μ / mu_factor between centerings
  /// … for min δ at a fixed d_max, where (C2) keeps its barrier and each
  /// centering crawls along it: measured on SISO n = 400 (i.i.d. z, r with a
  /// delayed part), factor 8: 237 Newton steps, 29 s; 4: 101, 12.7 s; 2: 78, 10 s.
  double mu_factor_fixed_noise = 2.0;
  /// The reduction adapts to the central path's curvature: after a centering
  /// that took more than slow_centering Newton steps the next factor is the
  /// square root of the last one (not below min_mu_factor), after one of at
  /// most 2 steps it is squared (not above the factor above). A fixed factor 8
  /// crawled where the path bends sharply: each Newton step lowered F_μ by a
  /// constant ~2 (damped steps, decrement λ² ≈ 4.9 for 140 steps in one
  /// centering) and the run hit max_newton. Measured on 200-row windows of the
  /// cascaded-tanks record (diagnose's "after" and the linear model, λ =
  /// 0.99) and of the coupled-drives analogue (src/examples/plant_analogues.h,
  /// orders 1 and 3, λ = 0.5), 20 windows: fixed 8, 196–400 Newton steps and
  /// 5 runs stopped at 400 (then CSDP, 33–49 s each); adaptive (4, 1.5),
  /// 72–168 steps, none stopped (3.2–7.0 s per window with the exact checks).
  /// It counts steps, never time: the same iterates on any machine and load.
  int slow_centering = 4;
  double min_mu_factor = 1.5;
  /// After each μ update, a step along the central path's tangent before
  /// Newton recentres (measured: SISO n = 800 17.4 → 15.3 s, 3×3 n = 200
  /// 38.5 → 32.9 s).
  bool predictor = true;
  /// nz > 1: Newton steps start from α = min(1, damping/(1 + λ)), λ the
  /// Newton decrement. Measured at 2 (3×3 n = 200: no convergence in 400
  /// steps → 32.9 s; 2×2 n = 400: 37.7 → 45.8 s, the price). SISO: full steps.
  double damping = 2.0;
  /// Threads of a Newton step: 0 = the machine's cores (one on the workers of
  /// a parallel_for, e.g. diagnose's bound windows), ≥ 2 = a helper thread
  /// takes half of P = F⁻¹, of the Newton system's Cholesky rank updates and of the
  /// spectra and correlations (dense/split_factorisations.h). Every number is
  /// computed by the same operations whatever the count: the same iterates,
  /// bounds and certificates, bit for bit (tests/lmi/barrier_threads_test.cc).
  unsigned threads = 0;
};

/// True when the structured solver handles the case: ny = nz = 1 and an
/// objective listed above (with δ > 0 when fixed).
bool barrier_applies(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective);

/// Solves the full-horizon Δ form (K = L). On a numerical failure the status
/// is kBackendError with the reason in solve.message (callers fall back to an
/// SDP backend). Dual matrices are always returned with a solution or an
/// infeasibility answer (original units, as DeltaFormSolution documents).
/// `free_regressors` ((n·ny) × P, the layout above; 0 columns: none) adds
/// the free unknowns q; throws std::invalid_argument when it has columns but
/// not n·ny rows, or a non-finite entry. The answer's free_coefficients
/// (length P; empty without regressors) and noise_residual (n × ny, d =
/// r − Z h − G q) are filled with a solution or an infeasibility answer.
/// `records` (the lengths n_k of the stacked records; empty: one record)
/// selects the several-records program above; throws std::invalid_argument
/// when the lengths do not add up to n. The answer's horizon is
/// records_horizon(z, records) and its leading_zeros the number of head rows
/// Σ_k m_k (one record: m = n − L; several: not n − L).
DeltaFormSolution solve_delta_form_barrier(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective,
                                           const BarrierOptions& options = {}, const Mat<double>& free_regressors = {},
                                           const RecordLengths& records = {});

/// F_μ, its gradient and Hessian at x = (h, t?) of the SCALED problem (for
/// the finite-difference test of the formulas above; value = +∞ outside the
/// interior).
struct BarrierDerivatives {
  double value = 0;
  Eigen::VectorXd gradient;
  Eigen::MatrixXd hessian;
};
BarrierDerivatives barrier_derivatives(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective,
                                       const Eigen::VectorXd& x, double mu, const Mat<double>& free_regressors = {},
                                       const RecordLengths& records = {}, unsigned threads = 1);

}  // namespace lpvid
