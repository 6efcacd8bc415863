#pragma once
/// One model and one data set, each in two views read from the same text:
/// exact (`model_q`, `exp_q`: what the certificates state) and double
/// (`model_d`, `exp_d`: what the solvers and the fits use). The views are
/// not derived from each other in general (each is read from the text, as
/// cli/inputs.h does), so a caller that builds one from the other says so.
/// The functions that need both views take one `const Problem&`; a body
/// that reads all four names them with
/// `const auto& [model_q, model_d, exp_q, exp_d] = problem;`.

#include "core/scalar.h"
#include "data/experiment.h"
#include "model/lpv_model.h"

namespace lpvid {

struct Problem {
  LpvModel<Rational> model_q;  ///< the model, exactly
  LpvModel<double> model_d;    ///< the same model as doubles
  Experiment<Rational> exp_q;  ///< the data, exactly
  Experiment<double> exp_d;    ///< the same data as doubles
};

}  // namespace lpvid
