#include "fit/k_step_prediction.h"

#include <algorithm>
#include <stdexcept>

#include "data/experiment_builder.h"
#include "fit/output_error_fit.h"
#include "model/simulate.h"

namespace lpvid {

Mat<double> k_step_prediction(const LpvModel<double>& model, const Experiment<double>& exp, Eigen::Index k,
                              Eigen::Index window, Eigen::Index first) {
  if (k < 1) throw std::invalid_argument("k-step prediction: k must be >= 1");
  if (window < 1) throw std::invalid_argument("k-step prediction: the state window must be >= 1 sample");
  Mat<double> out = simulate(model, exp).output;
  // the delayed, mapped input of the whole record; the windows then run the
  // LPV part on it directly (a window's first rows see their true past input)
  LpvModel<double> lpv = model;
  lpv.statics.input_delay = 0;
  lpv.statics.input = StaticMap<double>{};
  Experiment<double> e = exp;
  e.u = model.statics.model_input(exp.u);
  for (Eigen::Index t = std::max(first, k); t < exp.n(); ++t) {
    const Eigen::Index p = t - k, s = std::max<Eigen::Index>(0, p - window + 1);
    const Experiment<double> w = select_rows(e, s, t + 1);
    const FitResult f = fit_initial_state(lpv, w, p - s + 1);
    out.row(t) = simulate(f.model, w).output.row(t - s);
  }
  return out;
}

}  // namespace lpvid
