#include "fit/compare_models.h"

#include <algorithm>

#include "core/input_error.h"
#include "data/experiment_builder.h"
#include "fit/k_step_prediction.h"
#include "fit/output_error_fit.h"
#include "model/simulate.h"

namespace lpvid {
namespace {

/// The record's rows in the model's columns, its window applied; throws
/// InputError when the window or the warm-up leaves it nothing to score.
void select_compared_rows(RecordComparison& c, const CompareRecord& r, bool several, const CompareOptions& o) {
  c.exp = make_experiment<double>(r.table, c.model.columns);
  if (r.rows) {
    const auto [b, e] = *r.rows;
    if (e > c.exp.n())
      throw InputError("--rows " + r.rows_text + ": " + (several ? r.file + " has" : std::string("the data has")) +
                       " only " + std::to_string(c.exp.n()) + " rows");
    c.exp = select_rows(c.exp, b, e);
    c.first = b;
  }
  if (o.warmup >= c.exp.n())
    throw InputError("--warmup " + std::to_string(o.warmup) + " leaves nothing to score in " + std::to_string(c.exp.n()) +
                     " rows" + (several ? " of " + r.file : ""));
}

RecordComparison compare_on_record(const LpvModel<double>& model, const std::string& model_file, const CompareRecord& r,
                                   bool several, const CompareOptions& o) {
  RecordComparison c{r.file, 0, o.warmup, {}, model, {}, {}};
  select_compared_rows(c, r, several, o);
  // x0: the model's, or fitted (multi-start, fit/output_error_fit.h) on the
  // warm-up rows, or on all compared rows without a warm-up
  if (o.fit_x0) {
    const FitResult f = fit_initial_state(c.model, c.exp, o.warmup > 0 ? o.warmup : c.exp.n());
    if (!f.finite)
      throw InputError(model_file + ": no initial state keeps the simulation finite on the rows of " + r.file);
    c.model.x0 = f.model.x0;
  }
  c.yhat = o.predict > 0 ? k_step_prediction(c.model, c.exp, o.predict, compare_state_window(o, c.model), c.skip)
                         : simulate(c.model, c.exp).output;
  const Eigen::Index scored = c.exp.n() - c.skip;
  c.scores = score_outputs(c.exp.y.bottomRows(scored), c.yhat.bottomRows(scored));
  return c;
}

/// Each record compared on its own (its own x0), then every scored sample of
/// every record pooled.
ModelComparison compare_one_model(const LpvModel<double>& model, const std::string& model_file,
                                  const std::vector<CompareRecord>& records, const CompareOptions& o) {
  ModelComparison m{model_file, model, compare_state_window(o, model), {}, {}, 0};
  for (const CompareRecord& r : records)
    m.records.push_back(compare_on_record(model, model_file, r, records.size() > 1, o));
  for (const RecordComparison& c : m.records) m.samples += c.exp.n() - c.skip;
  Mat<double> y(m.samples, model.ny), yhat(m.samples, model.ny);
  Eigen::Index at = 0;
  for (const RecordComparison& c : m.records) {
    const Eigen::Index scored = c.exp.n() - c.skip;
    y.middleRows(at, scored) = c.exp.y.bottomRows(scored);
    yhat.middleRows(at, scored) = c.yhat.bottomRows(scored);
    at += scored;
  }
  m.pooled = score_outputs(y, yhat);
  return m;
}

}  // namespace

Eigen::Index compare_state_window(const CompareOptions& options, const LpvModel<double>& model) {
  return options.predict_window > 0 ? options.predict_window : std::max(1, model.nx);
}

CompareResult compare_models(const std::vector<LpvModel<double>>& models, const std::vector<std::string>& model_files,
                             const std::vector<CompareRecord>& records, const CompareOptions& options) {
  CompareResult result;
  for (size_t i = 0; i < models.size(); ++i) {
    try {
      result.models.push_back(compare_one_model(models[i], model_files.at(i), records, options));
    } catch (...) {
      result.failure = std::current_exception();
      break;
    }
  }
  return result;
}

}  // namespace lpvid
