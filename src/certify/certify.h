#pragma once
/// From a floating answer to an exactly verified certificate (docs/design.md §10.3).
///
/// The model is FIXED here (θ, φ, x0 already rounded to short rationals and
/// folded in). Then:
///  1. z and r = y − ŷ − Φ are computed exactly from the data text;
///  2. Theorem 2.1 is solved in the Δ form (lmi/delta_form_solve.h: the
///     structured barrier on the full horizon, else the SDP with at most
///     `max_taps` taps): well conditioned, never forms T_zᵀT_z;
///  3. the taps are rounded to `digits` significant decimal digits;
///  4. w = Δ∗z, d = r − w are exact; d_max² := ‖d‖²/(n·ny) rounded UP to 15
///     digits (or the fixed d_max², which must then hold exactly);
///  5. δ² := ‖T_Δ‖²_floating·(1 + margin) rounded up to 12 digits, margin
///     starting at 1e-9 and multiplied by 100 until the exact check of step 6
///     passes (at most 5 tries);
///  6. each δ² tried is checked exactly ONCE, as a file would carry it: the
///     certificate goes through its JSON text and back and is checked by
///     the verifier's core (verify/certificate/certificate_check.h) on the
///     exact experiment. `verified` is that verdict. Nothing is
///     written here: the certificates are returned in CertifiedBounds, and
///     the front end places them in files (certify/certificate_files.h).
/// Then, in certify_fixed_model's stages: for an optimised bound the lower
/// end from the dual (certify/dual_certify.h), with a full-horizon solve when
/// a K-tap one leaves the gap above gap_target; for fixed bounds without a
/// primal certificate, an exactly checked "invalidated" certificate.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/scalar.h"
#include "data/data_reference.h"
#include "data/experiment.h"
#include "certify/bound_scaling.h"
#include "certify/certify_types.h"
#include "lmi/bound_objective.h"
#include "lmi/delta_form_lmi.h"
#include "model/lpv_model.h"
#include "model/simulate.h"
#include "solvers/sdp_solver.h"
#include "verify/certificate/certificate_file.h"

namespace lpvid {

enum class ToeplitzMode;  // toeplitz/uncertainty_toeplitz.h

/// With CertifyOptions::scale_signals, the options with the weighted
/// objective mapped to original units (certify/bound_scaling.h; `scales`
/// receives the scales); otherwise `options` unchanged. `exp` has its
/// state-scheduling columns, `sim` is its exact simulation.
CertifyOptions in_original_units(const CertifyOptions& options, const LpvModel<Rational>& model,
                                 const Simulation<Rational>& sim, const Experiment<Rational>& exp,
                                 SignalScales* scales = nullptr);

/// Runs steps 1–6 for a fixed model. Never throws for solver failure (that
/// is verified = false with the reason); throws InputError for bad input.
CertifiedBounds certify_fixed_model(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                                    const CertifyOptions& options, SdpSolver& solver);

/// certify_fixed_model with its solve already done: `solution` is a
/// full-horizon structured solve of this model's program for this objective
/// (e.g. the class optimum's, class_lower_bound, whose free parameters are this
/// model's: its central point is this model's too). Its primal gives the upper
/// end and its dual point the lower end, both checked exactly as always; when
/// either does not certify, or the solution does not fit (another horizon, a
/// fixed δ or d_max, KYP or the SDP), this is certify_fixed_model.
CertifiedBounds certify_fixed_model_from(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                                         const CertifyOptions& options, SdpSolver& solver,
                                         const DeltaFormSolution& solution);

/// Steps 3–6 for GIVEN floating taps (K × ny·nz, row l = h_l row-major),
/// e.g. the Δ of an alternating-identification iterate: no solve. The
/// horizon is n minus the leading zero samples of the exact z; taps beyond
/// it are dropped. Throws InputError when z ≡ 0.
CertifiedBounds certify_with_taps(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                                  const Mat<double>& taps, const CertifyOptions& options,
                                  const std::string& solver_name);

/// Paper mode (T_z = T_G12 T_u is not a signal Toeplitz matrix, so there is
/// no Δ form): the w form of Theorem 2.1 is solved, w rounded to `digits`
/// digits, and (C1) [T_zᵀT_z, T_wᵀ; T_w, δ²I] ⪰ 0 checked exactly (by the
/// verifier, on its Schur complement δ²T_zᵀT_z − T_wᵀT_w: verify/certificate/c1_w_form.cc) with δ²
/// inflated as above. T_zᵀT_z squares the data's conditioning; for long
/// records this can fail where the Δ form would pass.
CertifiedBounds certify_fixed_model_paper(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                                          const CertifyOptions& options, SdpSolver& solver);

/// Theorem 2.1 for a fixed model in either Toeplitz mode: the Δ form
/// (certify_fixed_model) for ToeplitzMode::kSignal, the w form
/// (certify_fixed_model_paper) for kPaper.
CertifiedBounds certify_fixed(const LpvModel<Rational>& model, const Experiment<Rational>& exp, ToeplitzMode mode,
                              const CertifyOptions& options, SdpSolver& solver);


}  // namespace lpvid
