#pragma once
/// Theorem 2.1 for a fixed model answered in closed form, exactly and with
/// no solver, where the objective is degenerate ("Robust identification and
/// invalidation of LPV systems", Theorem 2.1; docs/dual_certificates.md,
/// "The δ = 0 lower end"). r = y − ŷ − Φ is the exact residual (every record
/// stacked), N = n·ny.
///
///  - δ² = 0 fixed: (C1) with a zero block forces w = 0 (Δ = 0), so d = r
///    (verify/certificate/closed_form_check.h has the argument). Minimise
///    d_max²: the interval [‖r‖²/N, ‖r‖²/N], upper end the primal point
///    Δ = 0, lower end a "zero_delta" certificate. Fixed d_max: consistent
///    (Δ = 0) iff N·d_max² ≥ ‖r‖², else "invalidated" ("zero_delta").
///  - the objective is 0 at the primal point Δ = 0 (so the optimum is 0):
///    minimise δ² at a fixed d_max with N·d_max² ≥ ‖r‖²; the weighted
///    objective with λ = 1 (or r ≡ 0); minimise d_max² at any δ when r ≡ 0;
///    fixed bounds when r ≡ 0 (consistent). Lower end 0: a "nonnegative"
///    certificate (every objective is ≥ 0).
///
/// The primal point is form "delta" with no taps on the horizon of z (signal
/// mode) or form "w" with w = 0 (paper mode). ‖r‖²/N is carried exactly,
/// unless its numerator and denominator together have more than
/// kMaxExactDigits decimal digits (the exact simulation's numbers grow with
/// the record: 13 084 digits at 200 samples of 17-digit data); then the
/// upper end is rounded up and the lower end down to 30 digits, and the
/// answer says so. Every certificate is checked exactly after its JSON round
/// trip (verify/certificate/certificate_check.h), like the solver's.

#include <optional>

#include "certify/certify_types.h"
#include "core/scalar.h"
#include "data/experiment.h"
#include "model/lpv_model.h"
#include "toeplitz/uncertainty_toeplitz.h"

namespace lpvid {

/// Most decimal digits (numerator plus denominator) of an exact ‖r‖²/N in a
/// certificate; beyond it the ends are rounded (see above). Below the
/// readers' default limit of one number (--max-digits, 50 000).
inline constexpr long kMaxExactDigits = 20000;

/// What the closed form needs: the model, the experiment with its
/// state-scheduling columns, the exact residual, the horizon of z (signal
/// mode) and the Toeplitz mode.
struct ClosedFormInput {
  const LpvModel<Rational>& model;
  const Experiment<Rational>& exp;
  const Mat<Rational>& r;
  Eigen::Index horizon = 0;
  ToeplitzMode mode = ToeplitzMode::kSignal;
};

/// The closed-form answer for `o` (objective in original units), when the
/// objective is one of the cases above and its certificates pass the exact
/// check; none otherwise (the caller solves). Sets every field of the
/// result except signals_seconds, total_seconds and scales.
std::optional<CertifiedBounds> certify_closed_form(const ClosedFormInput& in, const CertifyOptions& o);

}  // namespace lpvid
