#pragma once
/// The state each window of a job plan starts from (jobs/plan.h): the model's
/// own state at the window's first row, simulated in floating point from its
/// x0 over the record and rounded to `digits` significant digits (the value
/// the window's model file declares as its x0).

#include <vector>

#include "core/scalar.h"
#include "data/experiment.h"
#include "model/lpv_model.h"

namespace lpvid::jobs {

/// One state per entry of `first_rows` (0-based rows of `exp`).
std::vector<Vec<Rational>> window_start_states(const LpvModel<double>& model, const Experiment<double>& exp,
                                               const std::vector<Eigen::Index>& first_rows, int digits);

}  // namespace lpvid::jobs
