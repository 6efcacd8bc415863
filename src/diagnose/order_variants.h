#pragma once
/// The linear part's order chosen jointly with an effect:
/// a |·| sensor after a 3rd-order resonant part is a different model from
/// |·| after the order-2 part that a linear fit THROUGH the |·| picked. So
/// every static output-map candidate is also offered on the current model
/// with one more state, and the folds decide between the two.
///
/// raise_order embeds the model in order n + 1 without changing its
/// input–output map: in observer canonical form (fit/observer_form.h) a
/// root at 0 is appended to the denominator (a_{n+1} = 0), the new state's
/// B row and C column are zero and x0 gets a zero, so x_{n+1} ≡ 0 and
/// ŷ is unchanged; the joint re-fit (A's first column, B) then moves the
/// extra pole and zero wherever the data want them.

#include <optional>
#include <vector>

#include "diagnose/effect_candidates.h"
#include "model/lpv_model.h"

namespace lpvid {

/// The model with one more state as above, or nullopt when the model is not
/// an observer-form model that can be embedded this way (constant A term not
/// in observer form, a state-scheduled column "@…", fixed correction A_i/B_i,
/// an explicit uncertainty channel C1).
std::optional<LpvModel<double>> raise_order(const LpvModel<double>& m);

/// The static output-map candidates (abs_value, output_polynomial,
/// output_saturation, output_piecewise_linear) of the raised model, labelled
/// ", linear part of order n+1" and counting the added parameters; empty when
/// raise_order does not apply.
std::vector<EffectCandidate> raised_order_candidates(const LpvModel<double>& current, const Experiment<double>& est,
                                                     const CandidateOptions& options);

}  // namespace lpvid
