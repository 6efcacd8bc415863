#pragma once
/// Residual → missing effect (SPEC §6 steps 2–3, issue 4 items 3–4):
/// every candidate of the effect library is fitted on the ESTIMATION data
/// (output-error least squares, fit/output_error_fit.h) and scored on
/// the VALIDATION data, which the fit never saw:
///
///   validation RMS   free-run simulation from an x0 fitted on the first
///                    `init_samples` validation samples only (the cascaded
///                    tanks benchmark's rule), RMS over all its samples;
///   score            rms_val² · (1 + 2k/N_val), k = the effect's parameter
///                    count (Akaike's final prediction error penalty;
///                    Ljung, System Identification, 2nd ed., §16.4);
///   explained        1 − rms_val²/reference², the share of the validation
///                    residual energy the candidate removes.
///
/// The best score is accepted only if its validation RMS is at least
/// `min_gain` below the reference = min(current model, current model with
/// its output map re-fitted and no effect); otherwise the answer is `none`:
/// nothing beats refitting, i.e. what is left looks like noise. Accepted
/// effects are added and the search repeats (at most `max_effects` rounds).
/// Nothing here looks at the data set's name.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "diagnose/effect_candidates.h"
#include "fit/output_error_fit.h"

namespace lpvid {

struct RankingOptions {
  CandidateOptions candidates;
  int max_effects = 3;
  double min_gain = 0.05;           ///< relative validation-RMS reduction an effect must achieve
  Eigen::Index init_samples = kValidationInitSamples;  ///< validation samples used to fit x0
  FitOptions fit;
  /// Re-fit A and B together with each effect and with the no-effect
  /// reference (Wiener/Hammerstein: issue 9 item 2); false: only the output
  /// map, offset, x0 and the effect move (the issue-4 behaviour).
  bool joint_dynamics = true;
};

struct ScoredCandidate {
  std::string kind, label;
  int effect_parameters = 0;
  double rms_estimation = 0, rms_validation = 0, explained = 0, score = 0;
  LpvModel<double> model;          ///< fitted on estimation data (x0 of the estimation record)
  nlohmann::ordered_json parameters;  ///< the effect's own parameters
};

struct RankingRound {
  LpvModel<double> current;         ///< the model the candidates were added to
  double reference_validation = 0;  ///< what an effect must beat
  double current_validation = 0, refit_validation = 0;
  std::vector<ScoredCandidate> ranked;  ///< best score first
  int chosen = -1;                      ///< index into ranked, -1: none
};

struct RankingResult {
  LpvModel<double> before, after;  ///< explicit models (no unknowns), x0 of the estimation record
  double before_estimation = 0, before_validation = 0, after_estimation = 0, after_validation = 0;
  std::vector<RankingRound> rounds;
  std::vector<ScoredCandidate> chosen;  ///< in the order they were added
};

/// "Before": the declared model with its declared unknowns (correction C_i,
/// D_i, offset φ) and x0 fitted on the estimation data; the initial model
/// S_I itself is kept.
FitResult fit_declared(const LpvModel<double>& declared, const Experiment<double>& est, const FitOptions& fit);

/// Runs the rounds.
RankingResult rank_effects(const LpvModel<double>& declared, const Experiment<double>& est,
                           const Experiment<double>& val, const RankingOptions& options);

/// The effect's own parameters as JSON (kind-specific: basis and matrices,
/// offset values, limits, coefficients, delay).
nlohmann::ordered_json effect_parameters(const std::string& kind, const std::string& label,
                                         const LpvModel<double>& fitted, const LpvModel<double>& previous);

}  // namespace lpvid
