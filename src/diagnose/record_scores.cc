#include "diagnose/record_scores.h"

#include "model/simulate.h"
#include "toeplitz/record_lengths.h"

namespace lpvid {

Vec<double> record_initial_state(const LpvModel<double>& model, size_t k) {
  if (k >= 1 && k - 1 < model.later_x0.size() && model.later_x0[k - 1].size() == model.nx) return model.later_x0[k - 1];
  return model.x0;
}

RecordScores score_records(const LpvModel<double>& before, const LpvModel<double>& after, const Experiment<double>& est) {
  const Mat<double> yb = simulate(before, est).output, ya = simulate(after, est).output;
  RecordScores s;
  Eigen::Index first = 0;
  for (const Eigen::Index m : record_lengths_of(est.records, est.n())) {
    const Mat<double> y = est.y.middleRows(first, m);
    const size_t k = s.records.size();
    s.records.push_back({m, score_outputs(y, yb.middleRows(first, m)), score_outputs(y, ya.middleRows(first, m)),
                         record_initial_state(before, k), record_initial_state(after, k)});
    first += m;
  }
  s.pooled = {est.n(), score_outputs(est.y, yb), score_outputs(est.y, ya), {}, {}};
  return s;
}

}  // namespace lpvid
