#pragma once
/// Theorem 2.1 for a FIXED model in the Δ form with the norm bound of Δ
/// written by the discrete-time bounded real (KYP) lemma instead of the
/// L·(ny+nz) Toeplitz block of (C1') (delta_form_lmi.h). Used by the
/// alternating identification (identify/alternating_identify.h) and by
/// certification when asked (CertifyOptions::delta_norm).
///
/// Δ is a causal FIR with K taps h_0 … h_{K−1} (ny × nz each), w = Δ ∗ z.
/// With ξ_k = [z_k; z_{k−1}; …; z_{k−K+1}] (K·nz) and the shift-register state
/// x_k = [z_{k−1}; …; z_{k−K+1}], w_k = H ξ_k, H = [h_0 h_1 … h_{K−1}], and
///
///   (KYP)  [ diag(t·I_nz, 0) + diag(0_nz, P) − diag(P, 0_nz)   Hᵀ  ]
///          [ H                                                 I_ny ]  ⪰ 0
///
/// (P symmetric, (K−1)·nz square) says ‖w_k‖² ≤ t‖z_k‖² + x_kᵀPx_k −
/// x_{k+1}ᵀPx_{k+1} for every k; on sinusoids this gives ‖Δ‖²_∞ ≤ t, and
/// ‖T_Δ‖ ≤ ‖Δ‖_∞ on every horizon, so (KYP) ⇒ (C1') ⇒ (C1) of Theorem 2.1
/// (T_wᵀT_w ⪯ t·T_zᵀT_z) whatever the number of leading zeros of z. It is a
/// restriction of (C1') (‖T_Δ‖ on a finite horizon can be below ‖Δ‖_∞), so
/// bounds are sound upper bounds; the certificate still carries the exact
/// finite-horizon ‖T_Δ‖² of the rounded taps (certify/certify.h).
///
///   (C2)   [ n·ny·s        (c − R h)ᵀ ]
///          [ c − R h       I          ]  ⪰ 0   ⇔  ‖r − Z h‖² ≤ n·ny·s
///
/// where [Z r] = Q [R c] is a thin QR of the regression of r on the taps
/// (d = r − w = r − Z h, Z is n·ny × K·ny·nz), so the block has K·ny·nz + 2
/// rows instead of n·ny + 1. The blocks are small: the program costs
/// O(K²·nz²) variables and no O(n) block, so its cost barely depends on n.
///
/// Optional extra regressors E (n·ny × m, stacked like r): d = r − w − E g
/// with g free. The alternating identification passes the columns of the
/// residual's Jacobian −∂r/∂p = Jr whose parameters do not move z (additive
/// structure, offsets φ): (C2) stays linear in (h, g), so those parameters
/// are optimised jointly with Δ (for the additive structure this is the
/// global optimum of the KYP-restricted Theorem 3.1).
///
/// Numbers are scaled as in delta_form_lmi.h (z by σ_z, r by σ_r; each
/// column of E by its RMS).

#include "core/scalar.h"
#include "lmi/bound_objective.h"
#include "solvers/lmi_program.h"
#include "solvers/sdp_solver.h"

namespace lpvid {

struct DeltaKypSolution {
  SolveResult solve;
  Mat<double> taps;     ///< K × (ny·nz), original units, row l = h_l row-major
  double delta2 = 0.0;  ///< t: an upper bound on ‖Δ‖²_∞ (original units), or the fixed δ²
  double dmax2 = 0.0;   ///< s (original units), or the fixed d_max²
  Vec<double> g;        ///< coefficients of the extra regressors (original units)
};

/// Solves (KYP) + (C2) for the objective. z is n × nz, r is n × ny; K taps
/// (clamped to 1 … n); `extra` is E (no columns: none). Throws InputError
/// when z ≡ 0 (as solve_delta_form).
DeltaKypSolution solve_delta_kyp(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective,
                                 SdpSolver& solver, const SolverOptions& options, Eigen::Index taps,
                                 const Mat<double>& extra = Mat<double>());

}  // namespace lpvid
