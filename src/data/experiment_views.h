#pragma once
/// One data set in two views read from the same text: `exp_q` exactly (the
/// numbers the certificates state), `exp_d` as doubles (what the solvers and
/// the fits use). The views are not derived from each other in general (each
/// is read from the text; diagnose's double view is the text at the fits'
/// precision, data/fitting_precision.h), so a caller that builds one from
/// the other says so. model/problem.h holds a model beside them.

#include "core/scalar.h"
#include "data/experiment.h"

namespace lpvid {

struct ExperimentViews {
  Experiment<Rational> exp_q;  ///< exact: what the certificates state
  Experiment<double> exp_d;    ///< double: what the solvers and the fits read
};

}  // namespace lpvid
