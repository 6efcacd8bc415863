#pragma once
/// What a fitted effect is on the record it was fitted to, when that is not
/// what its family's label says.
///
/// A candidate is labelled by the family it was drawn from before its fit
/// ("dead_zone (input)", "abs_value (sensor)"); its fitted parameters can
/// make it something simpler on the estimation record, and the report must
/// not claim a mechanism the fit did not find:
///   - a dead zone whose band is negligible against its argument's range, or
///     which no sample enters, is an offset of the argument;
///   - a saturation whose limits no sample reaches is the identity;
///   - |·| on an argument of one sign is the identity (or the negation);
///   - a state nonlinearity e·f(x_i − c) of the model's own state: |x_i − c|
///     or a hinge max(x_i − c, 0) whose argument never crosses its kink c is
///     the linear term (or zero) it is on the record; one that crosses it
///     says on which share of the samples x_i lies below c.
/// Negligible means the map differs from the simpler one by at most
/// kNegligibleShare of the argument's range on the record; the argument is
/// the delayed input u (input maps) or the linear part's output ŷ + Φ
/// (output maps), from the fitted model's free run on the record.

#include <string>
#include <vector>

#include "data/experiment.h"
#include "model/lpv_model.h"

namespace lpvid {

struct RankingResult;

inline constexpr double kNegligibleShare = 1e-3;

/// The reading of the effect `kind` in `fitted` on `est`: empty when the
/// label stands, else e.g. "an input offset: u' = u - 0.0082 (the dead band,
/// 5e-09 wide, is negligible against the input's range 2.1 to 9.3)".
std::string effect_reading(const std::string& kind, const LpvModel<double>& fitted, const Experiment<double>& est);

/// The reading of a state nonlinearity: `columns` are the scheduling
/// columns it introduced ("@abs(x2-6.18)", …; effect_parameters'
/// new_scheduling), read on the fitted model's own free run on `est`.
/// Every |.|, hinge and square root gets one ("" only when the model does
/// not simulate or no column is a state function).
std::string state_nonlinearity_reading(const LpvModel<double>& fitted, const Experiment<double>& est,
                                       const std::vector<std::string>& columns);

/// Sets ScoredCandidate::reading of every ranked candidate (from its own fit)
/// and of every chosen effect (from the final model `res.after`).
void read_effects(RankingResult& res, const Experiment<double>& est);

}  // namespace lpvid
