#pragma once
/// The two stages after an identification solve (written once,
/// used by identify, tradeoff, select-basis and the diagnose windows):
///   fix:     θ (with φ, x0) rounded to CertifyOptions::digits significant
///            digits and folded into the exact model, so that the model the
///            certificate names is a short rational one (docs/design.md §10.3);
///   certify: the identification's own Δ taps first when it has them (no
///            re-solve: certify_with_taps), else Theorem 2.1 solved again for
///            the fixed model (certify_fixed_model); when the taps certified
///            the upper end, the lower end of the optimum still needs a dual
///            point of the full-horizon problem (a dual certificate), solved
///            here too unless CertifyOptions::lower_end is false.
/// `identify_and_certify` runs fit → fix → certify for `lpvid identify`.

#include "core/scalar.h"
#include "data/experiment.h"
#include "toeplitz/affine_residual.h"
#include "certify/certify.h"
#include "identify/identify.h"
#include "model/lpv_model.h"
#include "model/problem.h"
#include "solvers/sdp_solver.h"

namespace lpvid {

struct FixedParameters {
  Vec<Rational> exact;      ///< p rounded to `digits` significant digits
  Vec<double> value;        ///< the same numbers as doubles (for reports)
  LpvModel<Rational> model; ///< the model with them folded in (apply_parameters)
  /// Several records with free x0 (layout.x0_records ≥ 2): each record's own
  /// initial state with the rounded change folded in (Experiment::record_x0);
  /// otherwise the `record_x0` given to fix_parameters.
  std::vector<Vec<Rational>> record_x0;
};

/// Stage "fix": rounds p and folds it into `model` (and into each record's
/// initial state, `record_x0` being the experiment's: record_initial_states).
FixedParameters fix_parameters(const LpvModel<Rational>& model, const ParameterLayout& layout, const Vec<double>& p,
                               int digits, const std::vector<Vec<Rational>>& record_x0 = {});

/// `exp` with the fixed parameters' record initial states (the experiment the
/// fixed model is certified on).
Experiment<Rational> with_fixed_initial_states(const Experiment<Rational>& exp, const FixedParameters& fixed);

/// Stage "certify" for an identified, fixed model. `taps` (K × ny·nz, may be
/// empty) is the identification's own Δ. `note`, if given, receives why the
/// taps did not certify when a re-solve was needed.
CertifiedBounds certify_identified(const LpvModel<Rational>& fixed, const Experiment<Rational>& exp,
                                   const Mat<double>& taps, const CertifyOptions& options, SdpSolver& solver,
                                   std::string* note = nullptr);

/// fit → fix → certify (docs/design.md §8, §10): identify() on the double data, θ fixed
/// to `certify.digits` digits in the exact model, the fixed model certified
/// on the exact data. When the fit ends without a solution, `fixed` and
/// `bounds` are left empty (not verified) and `fit.status` says why.
struct IdentifiedModel {
  IdentifyResult fit;
  FixedParameters fixed;
  CertifiedBounds bounds;
  std::string taps_note;  ///< why the fit's own Δ did not certify (then Theorem 2.1 was solved again)
  /// How it ended, the one stored status (bounds.outcome): the
  /// certification's outcome; without a fit, kUndecided when the relaxation
  /// (a restriction of the BMI) was infeasible — that invalidates nothing —
  /// and kSolverFailed otherwise.
  CertifyOutcome outcome() const { return bounds.outcome; }
};
IdentifiedModel identify_and_certify(const Problem& problem, const IdentifyOptions& identify_options,
                                     const CertifyOptions& certify_options, SdpSolver& solver);

}  // namespace lpvid
