#include "cli/diagnose_report.h"

#include "model/simulate.h"

namespace lpvid::cli {

std::string test_rule_text(const FreeRunScore& score) {
  return "free run; x0 from the first " + std::to_string(score.warmup) +
         " samples (warm-up), RMS and fit % over the remaining " + std::to_string(score.scored);
}

void score_estimation_records(DiagnoseReport& report) {
  report.record_scores.clear();
  if (report.records.size() < 2) return;
  const DiagnoseResult& res = *report.result;
  const Experiment<double>& est = *report.est;
  const Mat<double> yb = simulate(res.before_model, est).output, ya = simulate(res.after_model, est).output;
  Eigen::Index first = 0;
  for (size_t k = 0; k < report.records.size(); ++k) {
    const Eigen::Index m = k < est.records.size() ? est.records[k] : est.n();
    const Mat<double> y = est.y.middleRows(first, m);
    report.record_scores.push_back({m, score_outputs(y, yb.middleRows(first, m)), score_outputs(y, ya.middleRows(first, m))});
    first += m;
  }
  report.pooled_records = {est.n(), score_outputs(est.y, yb), score_outputs(est.y, ya)};
}

}  // namespace lpvid::cli
