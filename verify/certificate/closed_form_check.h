#pragma once
/// Exact check of the claims decided in closed form, with no dual point
/// (docs/dual_certificates.md, "The δ = 0 lower end"). Called by
/// check_certificate after it has read the data exactly and simulated the
/// certified model exactly (steps 1–3 of certificate_check.h); r = y − ŷ − Φ,
/// n·ny counts every sample and output of every record.
///
/// Form "zero_delta": the claims "lower_bound" (objective "min_dmax") and
/// "invalidated" (objective "feasibility"), both at δ² = 0 exactly.
///   Why δ² = 0 decides d_max² exactly ("Robust identification and
///   invalidation of LPV systems", Theorem 2.1, the LMIs of eq. 7): (C1) is
///   [T_zᵀT_z, T_wᵀ; T_w, δ²I] ⪰ 0 (and in the Δ form of the model set of
///   eq. 5, [δ²I, T_Δ; T_Δᵀ, I] ⪰ 0). With δ² = 0 a diagonal block is zero,
///   and a PSD matrix with a zero diagonal entry has a zero row there (its
///   2×2 principal submatrix [a, b; b, 0] has determinant −b² ≥ 0 only for
///   b = 0), so T_w = 0 (T_Δ = 0), hence w = 0 and d = r. (C2),
///   ‖d‖² ≤ n·ny·d_max², then reads ‖r‖² ≤ n·ny·d_max²: every feasible
///   d_max² is ≥ ‖r‖²/(n·ny), and that value is attained by Δ = 0. This
///   holds in both Toeplitz modes (T_z plays no part) and for several
///   records (one Δ = 0 for all; (C2) pools every sample). So, exactly:
///     "lower_bound" holds iff n·ny·lower_bound ≤ ‖r‖²;
///     "invalidated" holds iff n·ny·d_max² < ‖r‖² (equality is consistent).
///   Any other objective, or δ² ≠ 0, is refused (invalid).
///
/// Form "nonnegative": the claim "lower_bound", any objective. At every
/// feasible point δ² ≥ 0 ((C1) holds only if its block δ²I is PSD) and
/// d_max² ≥ 0 (n·ny·d_max² ≥ ‖d‖² ≥ 0), and λ ∈ [0, 1], so δ², d_max² and
/// λδ² + (1−λ)d_max² are ≥ 0: the claim holds iff lower_bound ≤ 0. It says
/// nothing about the data; lpvid writes it where the upper end is 0 too (a
/// closed-form primal point at objective 0), so that the interval is [0, 0].
/// "invalidated" in this form is refused (being ≥ 0 excludes nothing).

#include <string>

#include "core/scalar.h"
#include "data/experiment.h"
#include "model/simulate.h"
#include "verify/certificate/certificate.h"
#include "verify/certificate/certificate_verdict.h"

namespace lpvid {

/// ‖r‖² of the residual r = y − ŷ − Φ (n × ny, every record stacked),
/// exactly: what (C2) bounds when Δ = 0.
Rational residual_energy(const Mat<Rational>& r);

/// The least d_max² consistent at δ² = 0: ‖r‖²/(n·ny), n·ny = r.size()
/// (0 for an empty r). Certification (certify/closed_form.h) and the check
/// of form "zero_delta" both use it.
Rational zero_delta_dmax2(const Mat<Rational>& r);

/// The claims of forms "zero_delta" and "nonnegative" (see the file
/// comment); `details` is what the caller already checked.
CertificateVerdict check_closed_form_claim(const Certificate& c, const Experiment<Rational>& exp,
                                           const Simulation<Rational>& sim, std::string details);

}  // namespace lpvid
