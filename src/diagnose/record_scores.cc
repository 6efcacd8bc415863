#include "diagnose/record_scores.h"

#include "model/simulate.h"
#include "toeplitz/record_lengths.h"

namespace lpvid {

RecordScores score_records(const LpvModel<double>& before, const LpvModel<double>& after, const Experiment<double>& est) {
  const Mat<double> yb = simulate(before, est).output, ya = simulate(after, est).output;
  RecordScores s;
  Eigen::Index first = 0;
  for (const Eigen::Index m : record_lengths_of(est.records, est.n())) {
    const Mat<double> y = est.y.middleRows(first, m);
    const size_t k = s.records.size();
    s.records.push_back({m, score_outputs(y, yb.middleRows(first, m)), score_outputs(y, ya.middleRows(first, m)),
                         record_start_state(before, k), record_start_state(after, k)});
    first += m;
  }
  s.pooled = {est.n(), score_outputs(est.y, yb), score_outputs(est.y, ya), {}, {}};
  return s;
}

}  // namespace lpvid
