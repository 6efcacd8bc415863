#pragma once
/// The two stages after an identification solve (issue 10: written once,
/// used by identify, tradeoff, select-basis and the diagnose windows):
///   fix:     θ (with φ, x0) rounded to CertifyOptions::digits significant
///            digits and folded into the exact model, so that the model the
///            certificate names is a short rational one (SPEC §7);
///   certify: the identification's own Δ taps first when it has them (no
///            re-solve: certify_with_taps), else Theorem 2.1 solved again for
///            the fixed model (certify_fixed_model).

#include "core/scalar.h"
#include "data/experiment.h"
#include "identify/affine_residual.h"
#include "identify/certify.h"
#include "model/lpv_model.h"
#include "solvers/sdp_solver.h"

namespace lpvid {

struct FixedParameters {
  Vec<Rational> exact;      ///< p rounded to `digits` significant digits
  Vec<double> value;        ///< the same numbers as doubles (for reports)
  LpvModel<Rational> model; ///< the model with them folded in (apply_parameters)
};

/// Stage "fix": rounds p and folds it into `model`.
FixedParameters fix_parameters(const LpvModel<Rational>& model, const ParameterLayout& layout, const Vec<double>& p,
                               int digits);

/// Stage "certify" for an identified, fixed model. `taps` (K × ny·nz, may be
/// empty) is the identification's own Δ. `note`, if given, receives why the
/// taps did not certify when a re-solve was needed.
CertifiedBounds certify_identified(const LpvModel<Rational>& fixed, const Experiment<Rational>& exp,
                                   const Mat<double>& taps, const CertifyOptions& options, SdpSolver& solver,
                                   std::string* note = nullptr);

}  // namespace lpvid
