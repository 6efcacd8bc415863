#pragma once
/// Identification, Theorem 3.1, by block-coordinate ("alternating") descent
/// in the well-conditioned Δ form (not in the paper): far faster than the
/// paper's relaxation, whose one SDP solve takes minutes at n = 200.
///
/// Theorem 3.1 asks for θ (C_i, D_i, φ, x0: the vector p of
/// affine_residual.h) and w with (C1) T_wᵀT_w ⪯ δ²T_zᵀT_z and (C2)
/// ‖r − w‖² ≤ n·ny·d_max², where z(p) = z0 + Jz p and r(p) = r0 − Jr p are
/// affine in p (the output of eq. 10 is affine in θ). With w = Δ ∗ z for a
/// causal FIR Δ (Poolla et al.; delta_form_lmi.h), (C1) holds whenever
/// ‖T_Δ‖ ≤ δ, and the problem is bilinear only through T_Δ·z(p). We
/// minimise J(p, Δ) = objective(δ², d_max²) with
///
///   δ²(Δ) = t, an upper bound on ‖Δ‖²_∞ (delta_kyp_lmi.h),
///   d_max²(p, Δ) = ‖r(p) − T_Δ z(p)‖² / (n·ny)      (the residual d of (C2)),
///
/// alternating two exact minimisations:
///   Δ step (p fixed): Theorem 2.1 for the fixed model, an SDP with K taps
///      (jointly with the parameters that do not move z: additive
///      structure, offsets φ, whose effect on d is linear);
///   p step (Δ fixed): d = (r0 − T_Δ z0) − (Jr + T_Δ Jz) p is affine in p and
///      δ² does not depend on p, so min J is linear least squares (closed
///      form, complete orthogonal decomposition: rank deficiency allowed).
/// Start: p_0 from plain least squares (the p step at Δ = 0). Iterate k
/// solves the Δ step at p_k, giving Δ_k, then the p step for Δ_k, giving
/// p_{k+1}, at which iterate k + 1's Δ step is solved (IterateRecord::
/// p_delta_step records p_k). Each iterate (p_{k+1}, Δ_k) satisfies (KYP)
/// and (C2) as stated, so it is a feasible point of the TRUE BMI of
/// Theorem 3.1 and certifies with certify_with_taps (certify.h), no re-solve
/// needed; the result's p and taps are the accepted iterate's pair. J never
/// rises (Δ_k is feasible for the Δ step at p_{k+1}, and p_{k+1} for the p
/// step after it), up to the SDP's tolerance: an iterate that rises ends the
/// loop and is discarded. Stop when J improves by less than rel_tol
/// (relative) or after max_iterations Δ steps.
///
/// Several records (exp.records): the Δ step is Theorem 2.1 over the
/// records on their full horizon (solve_delta_form with the records; KYP's
/// state would run across records, so options.taps is not used), and
/// T_Δ z is taken record by record (apply_fir_records) in the p step.
///
/// Fixed bounds: for a fixed δ the Δ step minimises d_max at that δ; for
/// kFeasibility it does too, and the result is feasible when the final
/// d_max² ≤ the given d_max² (status kPrimalInfeasible otherwise, which here
/// only means "not shown consistent by this local method").

#include "identify/identify_types.h"

namespace lpvid {

IdentifyResult identify_alternating(const LpvModel<double>& model, const Experiment<double>& exp,
                                    const IdentifyOptions& options, SdpSolver& solver);

/// The p step: for fixed taps, the least-squares p and its d_max² =
/// ‖r(p) − T_Δ z(p)‖²/(n·ny). Exposed for tests.
Vec<double> alternating_parameter_step(const AffineResidual<double>& a, const Mat<double>& taps, double* dmax2);

}  // namespace lpvid
