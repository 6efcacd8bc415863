// The JSON report of `lpvid diagnose` (cli/diagnose_report.h).
#include <algorithm>
#include <cmath>

#include "cli/blas_kernel.h"
#include "cli/diagnose_report.h"
#include "cli/report.h"
#include "diagnose/residual_analysis.h"
#include "plot/diagnose_plots.h"

namespace lpvid::cli {
namespace {

using ojson = nlohmann::ordered_json;

ojson number_or_null(double x) { return std::isfinite(x) ? ojson(x) : ojson(nullptr); }
ojson vector_or_nulls(const Vec<double>& v) {
  ojson out = ojson::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(number_or_null(v(i)));
  return out;
}

/// The scales of certify/bound_scaling.h and the bounds in scaled units.
ojson scaling_json(const CertifiedBounds& b) {
  const SignalScales& sc = b.scales;
  return {{"y_scale", sc.y_scale_text()},
          {"z_scale", sc.z_scale_text()},
          {"lambda_scaled", sc.lambda_scaled},
          {"lambda_original_units", sc.lambda_original},
          {"delta_scaled", b.verified() ? ojson(sc.scaled_delta(b.delta)) : ojson(nullptr)},
          {"dmax_scaled", b.verified() ? ojson(sc.scaled_dmax(b.dmax)) : ojson(nullptr)},
          {"meaning", "the objective lambda*delta'^2 + (1-lambda)*dmax'^2 is minimised on z/z_scale and y/y_scale; "
                      "delta' = delta*z_scale/y_scale, dmax' = dmax/y_scale exactly (docs/bound_scaling.md); delta, "
                      "dmax and the certificate are in the data's units"}};
}

ojson window_json(const WindowBounds& w) {
  const CertifiedBounds& b = w.bounds;
  ojson e = {{"estimation_rows", {w.begin, w.end}}, {"file_rows", {w.file_begin, w.file_end}},
             {"delta", b.verified() ? ojson(b.delta) : ojson(nullptr)}, {"dmax", b.verified() ? ojson(b.dmax) : ojson(nullptr)},
             {"verified", b.verified()}, {"certificate", w.certificate.empty() ? ojson(nullptr) : ojson(w.certificate)}};
  if (!b.verified()) e["reason"] = b.reason;
  if (!b.fallback.empty()) e["fallback"] = b.fallback;
  e["rms_output"] = number_or_null(w.rms_output);
  e["rms_output_variation"] = number_or_null(w.rms_variation);
  e["informative"] = w.informative;
  e["note"] = w.note;
  if (b.scales.applied) e["scaling"] = scaling_json(b);
  return e;
}

/// Over all windows: δ, d_max are the largest of the per-window bounds (each
/// window satisfies them on its own rows; nothing is claimed across windows).
ojson side_json(double rms_est, double rms_val, const DiagnoseResult& res, DiagnoseSide side) {
  ojson j = ojson::object();
  j["rms_estimation"] = number_or_null(rms_est);
  j["rms_validation"] = number_or_null(rms_val);
  const BoundsSummary s = res.bounds_summary(side);
  ojson list = ojson::array();
  for (const WindowBounds& w : side == DiagnoseSide::kBefore ? res.before : res.after) list.push_back(window_json(w));
  j["delta"] = s.all_verified ? ojson(s.delta) : ojson(nullptr);
  j["dmax"] = s.all_verified ? ojson(s.dmax) : ojson(nullptr);
  j["verified"] = s.all_verified;
  j["uninformative_windows"] = s.uninformative;
  j["windows"] = std::move(list);
  j["bounds_meaning"] = "Theorem 2.1 on exactly the rows of each window: the model (numbers rounded to 12 digits, "
                        "initial state = the fitted model's own state at the window's first row) explains them with "
                        "||Delta|| <= delta and noise RMS <= dmax; delta, dmax here are the largest over the windows. "
                        "A window is informative when verified and dmax < rms_output_variation (the RMS of its "
                        "measured output's deviation from its mean): the constant model y = mean meets dmax = "
                        "rms_output_variation (rms_output, the RMS of y itself, includes the mean)";
  return j;
}

ojson identification_json(const WindowIdentification& id) {
  ojson j = ojson::object();
  j["applicable"] = id.applicable;
  if (!id.applicable) {
    j["why_not"] = id.why_not;
    return j;
  }
  const CertifiedBounds& b = id.bounds.bounds;
  j["method"] = "alternating Delta/theta (Theorem 3.1; iterates feasible for the true BMI)";
  j["failed"] = id.failed.empty() ? ojson(nullptr) : ojson(id.failed);
  j["basis"] = id.basis;
  j["unknowns"] = "C_i, D_i of the basis on top of the fitted values, x0";
  j["file_rows"] = {id.bounds.file_begin, id.bounds.file_end};
  j["delta"] = b.verified() ? ojson(b.delta) : ojson(nullptr);
  j["dmax"] = b.verified() ? ojson(b.dmax) : ojson(nullptr);
  j["verified"] = b.verified();
  if (!b.verified()) j["reason"] = b.reason;
  j["informative"] = id.bounds.informative;
  const std::string only_first = "Theorem 3.1 is run on the first bound window only";
  j["note"] = id.bounds.note.empty() ? only_first : id.bounds.note + "; " + only_first;
  j["certificate"] = id.bounds.certificate.empty() ? ojson(nullptr) : ojson(id.bounds.certificate);
  return j;
}

/// Held-out RMS of each fold (null when not finite); null in one-split mode.
ojson folds_json(const FoldFigures& f) {
  if (f.empty()) return nullptr;
  ojson a = ojson::array();
  for (size_t j = 0; j < f.sse.size(); ++j) a.push_back(number_or_null(f.rms(j)));
  return a;
}

/// A tie among the accepted candidates (null: none): their ranks, the
/// largest relative difference of their RMS, the tolerance and the rule.
ojson tie_json(const RankingRound& rr) {
  if (!rr.tie) return nullptr;
  ojson ranks = ojson::array();
  for (int k : rr.tie->tied) ranks.push_back(k + 1);
  return {{"ranks", ranks},
          {"chosen_rank", rr.chosen + 1},
          {"largest_relative_difference", rr.tie->margin},
          {"tolerance", kEffectTieTolerance},
          {"rule", rr.tie->rule}};
}

/// A grid family's start chosen by the held-out folds (null: no choice).
ojson start_choice_json(const StartChoice& s) {
  if (s.chosen < 0) return nullptr;
  return {{"start", s.chosen + 1},
          {"starts", s.starts},
          {"held_out_rms", number_or_null(s.held_out)},
          {"start_of_lowest_estimation_rms", s.lowest_estimation + 1},
          {"its_held_out_rms", number_or_null(s.held_out_of_lowest_estimation)}};
}

ojson candidate_json(const ScoredCandidate& c) {
  return {{"kind", c.kind},
          {"label", c.label},
          {"fitted_as", c.reading.empty() ? ojson(nullptr) : ojson(c.reading)},
          {"effect_parameters", c.effect_parameters},
          {"rms_estimation", number_or_null(c.rms_estimation)},
          {"rms_validation", number_or_null(c.rms_validation)},
          {"explained_validation", number_or_null(c.explained)},
          {"score", number_or_null(c.score)},
          {"joint_refit_of_A_B", c.joint},
          {"held_out_folds", folds_json(c.folds)},
          {"folds_won", c.folds.empty() ? ojson(nullptr) : ojson(c.folds_won)},
          {"start_chosen_by_folds", start_choice_json(c.start)},
          {"parameters", c.parameters}};
}

/// The physics-first comparison of a round (null when none was made).
ojson physical_alternative_json(const RankingRound& rr) {
  if (!rr.physical) return nullptr;
  const PhysicalAlternative& p = *rr.physical;
  return {{"physical", rr.ranked[static_cast<size_t>(p.physical)].label},
          {"black_box", rr.ranked[static_cast<size_t>(p.black_box)].label},
          {"held_out_differences_per_fold", p.differences},
          {"mean_difference", p.mean},
          {"standard_error", p.standard_error},
          {"physical_taken", p.taken},
          {"rule", "indistinguishable when the mean per-fold difference of held-out RMS (physical minus black box) is at "
                   "most its standard error; the physical form is taken when it passes the acceptance rule"}};
}

ojson rounds_json(const DiagnoseResult& res) {
  ojson rounds = ojson::array();
  for (size_t i = 0; i < res.rank.rounds.size(); ++i) {
    const RankingRound& rr = res.rank.rounds[i];
    ojson cands = ojson::array();
    for (size_t k = 0; k < rr.ranked.size(); ++k) {
      ojson cj = candidate_json(rr.ranked[k]);
      cj["share_of_estimation_residual"] = rr.ranked[k].estimation_share;
      cj["below_share_floor"] = rr.ranked[k].estimation_share < kMinEstimationShare;
      cands.push_back(cj);
    }
    rounds.push_back({{"reference_validation", rr.reference_validation},
                      {"reference_held_out_folds", folds_json(rr.reference_folds)},
                      {"chosen", rr.chosen >= 0 ? ojson(rr.ranked[static_cast<size_t>(rr.chosen)].kind) : ojson("none")},
                      {"tie", tie_json(rr)},
                      {"physical_alternative", physical_alternative_json(rr)},
                      {"candidates", cands}});
  }
  return rounds;
}

ojson effects_json(const RankingResult& r) {
  ojson effects = ojson::array();
  for (const ScoredCandidate& c : r.chosen) {
    ojson e = candidate_json(c);  // "parameters": the final model's values
    e["parameters_when_chosen"] = c.parameters_at_round;
    effects.push_back(std::move(e));
  }
  if (effects.empty())
    effects.push_back({{"kind", "none"},
                       {"label", "no effect explains the residual better than refitting (noise level)"},
                       {"rms_validation", r.before_validation}});
  return effects;
}

/// Whiteness and input correlation of a validation residual.
ojson analysis_json(const ResidualAnalysis& a) {
  ojson j = ojson::object();
  j["rms"] = a.rms.overall;
  j["max_lag"] = a.whiteness.max_lag;
  j["band_99"] = a.whiteness.band_99;
  ojson outs = ojson::array();
  for (const AutocorrelationTest& t : a.whiteness.outputs)
    outs.push_back({{"lags_outside_99", t.outside_99}, {"ljung_box_q", t.q}, {"q_threshold_99", t.q_threshold},
                    {"white", t.white}});
  j["autocorrelation"] = outs;
  ojson cross = ojson::array();
  for (const CrossCorrelation& c : a.input_correlation.pairs)
    cross.push_back({{"output", c.output + 1}, {"input", c.input + 1}, {"max_abs", c.max_abs}, {"at_lag", c.max_lag_at},
                     {"significant", c.significant}});
  j["input_correlation"] = cross;
  return j;
}

/// Test record t's signals against the estimation record's ranges (TestScore::excursions).
ojson test_range_json(const DiagnoseReport& in, size_t t) {
  const ColumnMap names = t < in.test_columns.size() ? in.test_columns[t] : ColumnMap{};
  const ColumnMap& est = in.result->before_model.columns;
  ojson out = ojson::array();
  for (const SignalExcursion& e : in.result->tests[t].excursions)
    out.push_back({{"signal", signal_column(names, e.role, e.column)},
                   {"estimation_signal", signal_column(est, e.role, e.column)},
                   {"role", to_string(e.role)},
                   {"estimation_range", {number_or_null(e.estimation_lo), number_or_null(e.estimation_hi)}},
                   {"test_range", {number_or_null(e.test_lo), number_or_null(e.test_hi)}},
                   {"samples", e.samples},
                   {"samples_below", e.below},
                   {"samples_above", e.above},
                   {"outside_percent", 100.0 * e.outside_share()},
                   {"beyond_width", e.beyond()}});
  return out;
}

ojson tests_json(const DiagnoseReport& in) {
  ojson tests = ojson::array();
  for (size_t t = 0; t < in.result->tests.size(); ++t) {
    const TestScore& ts = in.result->tests[t];
    const FreeRunScore &tb = ts.before, &ta = ts.after;
    tests.push_back({{"source", t < in.test_sources.size() ? in.test_sources[t] : ""},
                     {"samples", ts.samples},
                     {"rule", test_rule_text(tb)},
                     {"warmup_samples", tb.warmup},
                     {"scored_samples", tb.scored},
                     {"rms_before", number_or_null(tb.rms)},
                     {"rms_after", number_or_null(ta.rms)},
                     {"fit_percent_before", number_or_null(tb.fit_percent)},
                     {"fit_percent_after", number_or_null(ta.fit_percent)},
                     {"after_worse", ts.after_worse()},
                     {"range", test_range_json(in, t)},
                     {"note", "scored once, after the effects were selected on the validation (selection) data; the "
                              "models were fitted on the estimation rows only"}});
  }
  return tests;
}

/// Several test sets: the pooled score (DiagnoseResult::pooled_before/after).
ojson pooled_tests_json(const DiagnoseResult& res) {
  const FreeRunScore &b = res.pooled_before, &a = res.pooled_after;
  return {{"sets", res.tests.size()},
          {"scored_samples", a.scored},
          {"rms_before", number_or_null(b.rms)},
          {"rms_after", number_or_null(a.rms)},
          {"fit_percent_before", number_or_null(b.fit_percent)},
          {"fit_percent_after", number_or_null(a.fit_percent)}};
}

/// Several estimation records: each one's free-run figures of the models before and after.
ojson estimation_records_json(const DiagnoseReport& in) {
  ojson out = ojson::array();
  for (size_t k = 0; k < in.records.size() && k < in.result->estimation_records.records.size(); ++k) {
    const EstimationRecord& r = in.records[k];
    const EstimationRecordScore& s = in.result->estimation_records.records[k];
    out.push_back({{"file", r.data.file},
                   {"rows", {r.data.row_begin, r.data.row_end}},
                   {"sha256", r.data.sha256},
                   {"samples", s.samples},
                   {"rms_before", number_or_null(s.before.rms_all)},
                   {"rms_after", number_or_null(s.after.rms_all)},
                   {"fit_percent_before", number_or_null(s.before.fit_percent_all)},
                   {"fit_percent_after", number_or_null(s.after.fit_percent_all)},
                   {"x0_before", vector_or_nulls(s.x0_before)},
                   {"x0_after", vector_or_nulls(s.x0_after)}});
  }
  return out;
}

/// How the effects were selected: blocked folds or a validation record.
ojson selection_json(const DiagnoseReport& in) {
  const RankingResult& r = in.result->rank;
  if (!in.folds)
    return {{"source", in.validation}, {"samples", in.result->shown.data.n()}, {"init_samples", in.result->shown.init_samples},
            {"role", "selection: ranks the candidate effects"}};
  ojson blocks = ojson::array(), files = ojson::array();
  const std::vector<DataReference> per_record = fold_files(in);
  for (size_t j = 0; j < r.fold_blocks.size(); ++j) {
    const FoldBlock& b = r.fold_blocks[j];
    if (per_record.empty()) {
      blocks.push_back({in.file_row_offset + b.first, in.file_row_offset + b.last});
    } else {  // each block in its own file's rows
      blocks.push_back({per_record[j].row_begin, per_record[j].row_end});
      files.push_back(per_record[j].file);
    }
  }
  return {{"method", per_record.empty() ? "blocked folds of the estimation record" : "blocked folds within the estimation records"},
          {"folds", r.fold_blocks.size()},
          {"file_rows", blocks},
          {"files", per_record.empty() ? ojson(nullptr) : files},
          {"warmup_samples", in.fold_warmup},
          {"rule", acceptance_rule_text(r.fold_blocks.size(), r.min_gain)},
          {"before_held_out_folds", folds_json(r.before_folds)},
          {"after_held_out_folds", folds_json(r.after_folds)}};
}

ojson figures_json(const DiagnoseFigures& figures) {
  ojson plots = ojson::array();
  for (const DrawnFigure& f : figures.list) {
    const PlotOutcome& o = f.outcome;
    plots.push_back({{"png", o.ok ? ojson(f.path) : ojson(nullptr)},
                     {"svg", o.svg.empty() ? ojson(nullptr) : ojson(o.svg)},
                     {"csv", plot_csv_path(f.path)},
                     {"message", o.message}});
  }
  return plots;
}

/// before / after: the figures and bounds of each side with its Theorem 3.1 run.
void add_sides(ojson& j, const DiagnoseResult& res) {
  j["before"] = side_json(res.rank.before_estimation, res.rank.before_validation, res, DiagnoseSide::kBefore);
  j["after"] = side_json(res.rank.after_estimation, res.rank.after_validation, res, DiagnoseSide::kAfter);
  j["before"]["theorem_3_1"] = identification_json(res.before_id);
  j["after"]["theorem_3_1"] = identification_json(res.after_id);
}

}  // namespace

void write_diagnose_json(const DiagnoseReport& in, const DiagnoseFigures& figures, const std::string& report_path) {
  if (report_path.empty()) return;
  const DiagnoseResult& res = *in.result;
  ojson j = ojson::object();
  j["status"] = res.verified() ? "ok" : "not verified";
  j["command"] = "diagnose";
  j["estimation"] = {{"file", in.command_line_data}, {"rows", in.estimation}, {"samples", in.est->n()}};
  if (in.records.size() > 1) {  // every record's file, in the canonical order the fits used
    ojson files = ojson::array();
    for (const EstimationRecord& r : in.records) files.push_back(r.data.file);
    j["estimation"]["files"] = files;
  }
  j[in.folds ? "selection" : "validation"] = selection_json(in);
  const ojson tests = tests_json(in);
  j["test"] = tests.empty() ? ojson(nullptr) : tests.front();  // the first test set (the field of earlier reports)
  j["tests"] = tests;
  if (res.tests.size() > 1) j["tests_pooled"] = pooled_tests_json(res);
  if (in.records.size() > 1) j["records"] = estimation_records_json(in);
  j["effects"] = effects_json(res.rank);
  add_sides(j, res);
  j["noise_normalisation"] = "RMS: ||d||_2 <= dmax*sqrt(n*ny)";
  j["toeplitz_mode"] = "signal";
  j["solver"] = in.solver;
  j["blas"] = blas_kernel_text();  // docs/determinism.md
  j["relaxation"] = "delta, dmax: Theorem 2.1 for the least-squares model (output error on the whole estimation "
                    "record) on each window; theorem_3_1: the output map identified again on the first window by the "
                    "alternating method";
  j["verified"] = res.verified();
  j["rounds"] = rounds_json(res);
  ojson analysis = ojson::object();
  if (res.shown.finite) analysis = {{"before", analysis_json(res.shown.before)}, {"after", analysis_json(res.shown.after)}};
  j["residual_analysis_validation"] = analysis;
  j["plots"] = figures_json(figures);
  if (!in.model_out.empty()) j["model"] = in.model_out;
  write_json(report_path, j);
}

}  // namespace lpvid::cli
