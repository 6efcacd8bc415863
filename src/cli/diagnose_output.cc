#include "cli/diagnose_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "cli/report.h"
#include "core/decimal_rounding.h"
#include "fit/output_error_fit.h"
#include "fit/output_score.h"
#include "plot/diagnose_plots.h"
#include "diagnose/residual_analysis.h"
#include "model/simulate.h"

namespace lpvid::cli {
namespace {

using ojson = nlohmann::ordered_json;

std::string num(double x, int digits = 4) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

ojson finite_or_null(double x) { return std::isfinite(x) ? ojson(x) : ojson(nullptr); }

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

/// Over all windows: δ, d_max are the largest of the per-window bounds (each
/// window satisfies them on its own rows; nothing is claimed across windows).
ojson side_json(double rms_est, double rms_val, const std::vector<WindowBounds>& ws) {
  ojson j = ojson::object();
  j["rms_estimation"] = finite_or_null(rms_est);
  j["rms_validation"] = finite_or_null(rms_val);
  bool all = !ws.empty();
  double delta = 0, dmax = 0;
  int uninformative = 0;
  ojson list = ojson::array();
  for (const WindowBounds& w : ws) {
    const CertifiedBounds& b = w.bounds;
    all = all && b.verified();
    delta = std::max(delta, b.delta);
    dmax = std::max(dmax, b.dmax);
    ojson e = {{"estimation_rows", {w.begin, w.end}}, {"file_rows", {w.file_begin, w.file_end}},
               {"delta", b.verified() ? ojson(b.delta) : ojson(nullptr)}, {"dmax", b.verified() ? ojson(b.dmax) : ojson(nullptr)},
               {"verified", b.verified()}, {"certificate", w.certificate.empty() ? ojson(nullptr) : ojson(w.certificate)}};
    if (!b.verified()) e["reason"] = b.reason;
    if (!b.fallback.empty()) e["fallback"] = b.fallback;
    e["rms_output"] = finite_or_null(w.rms_output);
    e["rms_output_variation"] = finite_or_null(w.rms_variation);
    e["informative"] = w.informative;
    e["note"] = w.note;
    if (b.scales.applied) e["scaling"] = scaling_json(b);
    uninformative += b.verified() && !w.informative ? 1 : 0;
    list.push_back(std::move(e));
  }
  j["delta"] = all ? ojson(delta) : ojson(nullptr);
  j["dmax"] = all ? ojson(dmax) : ojson(nullptr);
  j["verified"] = all;
  j["uninformative_windows"] = uninformative;
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
  j["note"] = id.bounds.note + "; Theorem 3.1 is run on the first bound window only";
  j["certificate"] = id.bounds.certificate.empty() ? ojson(nullptr) : ojson(id.bounds.certificate);
  return j;
}

/// The header line of the test role: every test set with its size.
std::string test_roles_text(const DiagnoseReportInputs& in) {
  const auto& tests = in.result->tests;
  std::string t;
  for (size_t i = 0; i < tests.size(); ++i) {
    if (i) t += "; ";
    if (tests.size() > 1) t += std::to_string(i + 1) + ": ";
    t += (i < in.test_sources.size() ? in.test_sources[i] : std::string("?")) + " (" + std::to_string(tests[i].samples) +
         " samples)";
  }
  return t + (tests.size() > 1 ? "; each scored once, separately, at the end" : "; scored once, at the end");
}

/// The text flag of a verified but vacuous bound (window_bounds.h).
std::string uninformative_mark(const WindowBounds& w) {
  return w.informative ? "" : "  UNINFORMATIVE: dmax >= RMS of y about its mean there (" + num(w.rms_variation) + ")";
}

std::string identification_line(const WindowIdentification& id) {
  if (!id.applicable) return "not applicable: " + id.why_not;
  if (!id.failed.empty()) return id.failed + " (the results above stand)";
  const CertifiedBounds& b = id.bounds.bounds;
  std::string basis;
  for (const auto& f : id.basis) basis += (basis.empty() ? "" : ", ") + f;
  if (!b.verified()) return "not verified (" + b.reason + ")";
  return "delta <= " + upper_sqrt_text(b.delta2, 4) + ", dmax <= " + upper_sqrt_text(b.dmax2, 4) + " (verified; basis {" + basis + "})" +
         uninformative_mark(id.bounds);
}

/// Held-out RMS of each fold (null when not finite); null in one-split mode.
ojson folds_json(const FoldFigures& f) {
  if (f.empty()) return nullptr;
  ojson a = ojson::array();
  for (size_t j = 0; j < f.sse.size(); ++j) a.push_back(finite_or_null(f.rms(j)));
  return a;
}

std::string folds_text(const FoldFigures& f) {
  std::string t;
  for (size_t j = 0; j < f.sse.size(); ++j) t += (j ? " " : "") + num(f.rms(j), 3);
  return t;
}

/// A grid family's start chosen by the held-out folds (null: no choice).
ojson start_choice_json(const StartChoice& s) {
  if (s.chosen < 0) return nullptr;
  return {{"start", s.chosen + 1},
          {"starts", s.starts},
          {"held_out_rms", finite_or_null(s.held_out)},
          {"start_of_lowest_estimation_rms", s.lowest_estimation + 1},
          {"its_held_out_rms", finite_or_null(s.held_out_of_lowest_estimation)}};
}

std::string start_choice_text(const StartChoice& s) {
  if (s.chosen < 0) return "";
  std::string t = "; model from start " + std::to_string(s.chosen + 1) + " of " + std::to_string(s.starts) +
                  ": the lowest estimation MSE + held-out MSE of its fits (held-out RMS " + num(s.held_out, 4) + ")";
  if (s.lowest_estimation != s.chosen)
    t += "; the lowest estimation RMS would have taken start " + std::to_string(s.lowest_estimation + 1) + " (held-out RMS " +
         num(s.held_out_of_lowest_estimation, 4) + ")";
  return t;
}

ojson candidate_json(const ScoredCandidate& c) {
  return {{"kind", c.kind},
          {"label", c.label},
          {"fitted_as", c.reading.empty() ? ojson(nullptr) : ojson(c.reading)},
          {"effect_parameters", c.effect_parameters},
          {"rms_estimation", finite_or_null(c.rms_estimation)},
          {"rms_validation", finite_or_null(c.rms_validation)},
          {"explained_validation", finite_or_null(c.explained)},
          {"score", finite_or_null(c.score)},
          {"joint_refit_of_A_B", c.joint},
          {"held_out_folds", folds_json(c.folds)},
          {"folds_won", c.folds.empty() ? ojson(nullptr) : ojson(c.folds_won)},
          {"start_chosen_by_folds", start_choice_json(c.start)},
          {"parameters", c.parameters}};
}

/// Whiteness and input correlation of a validation residual (printed + JSON).
ojson analysis_json(const std::string& title, const ResidualAnalysis& a) {
  ojson j = ojson::object();
  j["rms"] = a.rms.overall;
  j["max_lag"] = a.whiteness.max_lag;
  j["band_99"] = a.whiteness.band_99;
  ojson outs = ojson::array();
  std::cout << "  " << title << ": RMS " << num(a.rms.overall);
  for (const AutocorrelationTest& t : a.whiteness.outputs) {
    outs.push_back({{"lags_outside_99", t.outside_99}, {"ljung_box_q", t.q}, {"q_threshold_99", t.q_threshold},
                    {"white", t.white}});
    std::cout << "; autocorrelation: " << t.outside_99 << " of " << a.whiteness.max_lag
              << " lags outside the 99% band, Ljung-Box Q = " << num(t.q) << " (white if <= " << num(t.q_threshold)
              << "): " << (t.white ? "white" : "NOT white");
  }
  j["autocorrelation"] = outs;
  ojson cross = ojson::array();
  for (const CrossCorrelation& c : a.input_correlation.pairs) {
    cross.push_back({{"output", c.output + 1}, {"input", c.input + 1}, {"max_abs", c.max_abs}, {"at_lag", c.max_lag_at},
                     {"significant", c.significant}});
    std::cout << "; with u" << c.input + 1 << ": max " << num(c.max_abs, 3) << " at lag " << c.max_lag_at
              << (c.significant ? " (significant)" : "");
  }
  std::cout << "\n";
  j["input_correlation"] = cross;
  return j;
}

/// "0:256, 256:512, …" in data-file rows.
std::string fold_rows_text(const RankingResult& r, long offset) {
  std::string t;
  for (const FoldBlock& b : r.fold_blocks)
    t += (t.empty() ? "" : ", ") + std::to_string(offset + b.first) + ":" + std::to_string(offset + b.last);
  return t;
}

std::string bound_line(const WindowBounds& w) {
  const CertifiedBounds& b = w.bounds;
  if (!b.verified()) return "not verified (" + b.reason + ")";
  return "delta <= " + upper_sqrt_text(b.delta2, 4) + ", dmax <= " + upper_sqrt_text(b.dmax2, 4) + " (verified, file rows " +
         std::to_string(w.file_begin) + ":" + std::to_string(w.file_end) + ")" + uninformative_mark(w);
}

}  // namespace

namespace {

/// Several test sets: the pooled score (DiagnoseResult::pooled_before/after), printed; null for fewer.
ojson pooled_tests_json(const DiagnoseResult& res) {
  if (res.tests.size() < 2) return nullptr;
  const FreeRunScore &b = res.pooled_before, &a = res.pooled_after;
  std::cout << "\ntests pooled (" << res.tests.size() << " sets, " << a.scored
            << " scored samples, each set from its own warm-up): before: RMS " << num(b.rms) << ", fit "
            << num(b.fit_percent, 4) << " %   after: RMS " << num(a.rms) << ", fit " << num(a.fit_percent, 4) << " %\n";
  return {{"sets", res.tests.size()},
          {"scored_samples", a.scored},
          {"rms_before", finite_or_null(b.rms)},
          {"rms_after", finite_or_null(a.rms)},
          {"fit_percent_before", finite_or_null(b.fit_percent)},
          {"fit_percent_after", finite_or_null(a.fit_percent)}};
}

/// Several estimation records: each record's free-run figures of the models
/// before and after (simulated record by record from the fitted x0), printed
/// and as the report's `records` list, then the pooled line.
ojson estimation_records_json(const DiagnoseReportInputs& in) {
  const DiagnoseResult& res = *in.result;
  const Experiment<double>& est = *in.est;
  const Mat<double> yb = simulate(res.before_model, est).output, ya = simulate(res.after_model, est).output;
  ojson out = ojson::array();
  std::cout << "\nestimation records (free run of the fitted models, each record from its start)\n";
  Eigen::Index first = 0;
  for (size_t k = 0; k < in.records.size(); ++k) {
    const EstimationRecord& r = in.records[k];
    const Eigen::Index m = k < est.records.size() ? est.records[k] : est.n();
    const Mat<double> y = est.y.middleRows(first, m);
    const OutputScores b = score_outputs(y, yb.middleRows(first, m)), a = score_outputs(y, ya.middleRows(first, m));
    std::cout << "  record " << k + 1 << " (" << r.text << ", " << m << " samples): before: RMS " << num(b.rms_all)
              << ", fit " << num(b.fit_percent_all, 4) << " %   after: RMS " << num(a.rms_all) << ", fit "
              << num(a.fit_percent_all, 4) << " %\n";
    out.push_back({{"file", r.data.file},
                   {"rows", {r.data.row_begin, r.data.row_end}},
                   {"sha256", r.data.sha256},
                   {"samples", m},
                   {"rms_before", finite_or_null(b.rms_all)},
                   {"rms_after", finite_or_null(a.rms_all)},
                   {"fit_percent_before", finite_or_null(b.fit_percent_all)},
                   {"fit_percent_after", finite_or_null(a.fit_percent_all)}});
    first += m;
  }
  const OutputScores b = score_outputs(est.y, yb), a = score_outputs(est.y, ya);
  std::cout << "  pooled (" << est.n() << " samples): before: RMS " << num(b.rms_all) << ", fit " << num(b.fit_percent_all, 4)
            << " %   after: RMS " << num(a.rms_all) << ", fit " << num(a.fit_percent_all, 4) << " %\n";
  return out;
}

}  // namespace

void print_and_write_diagnose_report(const DiagnoseReportInputs& in, const std::string& report_path) {
  const DiagnoseResult& res = *in.result;
  const RankingResult& r = res.rank;
  std::cout << "lpvid diagnose\n"
            << "  estimation  " << (in.estimation.empty() ? in.command_line_data : in.estimation) << " ("
            << in.est->n() << " samples)\n"
            << (in.folds ? "  selection   " + std::to_string(r.fold_blocks.size()) +
                               " blocked folds of the estimation record, rows " + fold_rows_text(r, in.file_row_offset) +
                               ": each candidate is fitted " + std::to_string(r.fold_blocks.size()) +
                               " times, each on the longer contiguous stretch beside one block, and scored on that block (x0 from its first " +
                               std::to_string(in.fold_warmup) + " samples, RMS over the rest)\n  rule        " +
                               acceptance_rule_text(r.fold_blocks.size(), r.min_gain) +
                               "; the model kept is the one fitted on all estimation rows\n"
                         : "  validation  " + in.validation + " (" + std::to_string(res.shown.data.n()) +
                               " samples; selection: ranks the effects; x0 fitted on the first " +
                               std::to_string(res.shown.init_samples) + ", then free-run simulation)\n")
            << "  test        "
            << (res.tests.empty() ? std::string("none given (--test / --test-columns): the validation figure chose the model")
                                  : test_roles_text(in))
            << "\n";
  ojson rounds = ojson::array();
  for (size_t i = 0; i < r.rounds.size(); ++i) {
    const RankingRound& rr = r.rounds[i];
    const char* what = in.folds ? "held-out RMS (all folds)" : "validation RMS";
    std::cout << "\nround " << i + 1 << ": " << what << " of the current model " << num(rr.current_validation)
              << ", re-fitted without a new effect " << num(rr.refit_validation) << "\n";
    if (in.folds)
      std::cout << "  reference per fold: " << folds_text(rr.reference_folds) << "\n"
                << "  held-out: RMS over the held-out folds; folds: per fold, and how many the candidate wins against the "
                   "reference\n";
    std::cout << "  explained: share of the " << (in.folds ? "held-out" : "validation")
              << " residual energy removed; est share: share of the estimation residual\n  energy that the candidate's "
                 "added output signal explains (least-squares projection)\n"
              << "  rank  kind               " << (in.folds ? "held-out" : "val RMS ")
              << "   explained  est RMS    est share  params  candidate\n";
    ojson cands = ojson::array();
    const std::vector<double>& shares = res.estimation_shares[i];
    for (size_t k = 0; k < rr.ranked.size(); ++k) {
      const ScoredCandidate& c = rr.ranked[k];
      char line[320];
      std::snprintf(line, sizeof line, "  %-4zu  %-17s  %-9s  %-9s  %-9s  %-9s  %-6d  %s%s\n", k + 1, c.kind.c_str(),
                    num(c.rms_validation).c_str(), (num(100 * c.explained, 3) + "%").c_str(),
                    num(c.rms_estimation).c_str(), (num(100 * shares[k], 3) + "%").c_str(), c.effect_parameters,
                    c.label.c_str(), static_cast<int>(k) == rr.chosen ? "   <- chosen" : "");
      std::cout << line;
      if (!c.reading.empty()) std::cout << "        fitted: " << c.reading << "\n";
      if (in.folds)
        std::cout << "        folds " << folds_text(c.folds) << "  (wins " << c.folds_won << " of " << c.folds.sse.size()
                  << (c.joint ? "; A, B re-fitted" : "") << start_choice_text(c.start) << ")\n";
      ojson cj = candidate_json(c);
      cj["share_of_estimation_residual"] = shares[k];
      cands.push_back(cj);
    }
    if (rr.chosen < 0)
      std::cout << "  -> none: no candidate " << (in.folds ? "passes the rule above against " : "lowers the validation RMS by the required share below ")
                << num(rr.reference_validation) << "\n";
    rounds.push_back({{"reference_validation", rr.reference_validation},
                      {"reference_held_out_folds", folds_json(rr.reference_folds)},
                      {"chosen", rr.chosen >= 0 ? ojson(rr.ranked[static_cast<size_t>(rr.chosen)].kind) : ojson("none")},
                      {"candidates", cands}});
  }
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

  std::cout << "\neffects added: ";
  if (r.chosen.empty()) std::cout << "none";
  for (size_t i = 0; i < r.chosen.size(); ++i)
    std::cout << (i ? ", " : "") << r.chosen[i].label
              << (r.chosen[i].reading.empty() ? "" : " (fitted: " + r.chosen[i].reading + ")");
  std::cout << "\n\n              RMS estimation  " << (in.folds ? "RMS held-out  " : "RMS validation") << "  bounds\n"
            << "  before      " << num(r.before_estimation) << std::string(16 - std::min<size_t>(15, num(r.before_estimation).size()), ' ')
            << num(r.before_validation) << std::string(16 - std::min<size_t>(15, num(r.before_validation).size()), ' ')
            << bound_line(res.before.front()) << "\n"
            << "  after       " << num(r.after_estimation) << std::string(16 - std::min<size_t>(15, num(r.after_estimation).size()), ' ')
            << num(r.after_validation) << std::string(16 - std::min<size_t>(15, num(r.after_validation).size()), ' ')
            << bound_line(res.after.front()) << "\n";
  if (in.folds)
    std::cout << "  held-out RMS per fold: before " << folds_text(r.before_folds) << "; after " << folds_text(r.after_folds)
              << (r.chosen.empty() ? " (no effect passed: the starting model is kept)"
                                   : " (every effect added passed the rule against the model before it)")
              << "\n";
  std::string rows;
  for (const WindowBounds& w : res.before) rows += (rows.empty() ? "" : ", ") + std::to_string(w.begin) + ":" + std::to_string(w.end);
  std::cout << "  bounds on " << res.before.size() << " window" << (res.before.size() == 1 ? "" : "s")
            << " of estimation rows " << rows << " (Theorem 2.1 on each window's rows alone; window 1 above)\n";
  for (size_t i = 1; i < res.before.size(); ++i)
    std::cout << "  window " << i + 1 << " (estimation rows " << res.before[i].begin << ":" << res.before[i].end << ")\n"
              << "              before: " << bound_line(res.before[i]) << "\n"
              << "              after:  " << bound_line(res.after[i]) << "\n";
  int uninformative = 0;
  for (const auto* side : {&res.before, &res.after})
    for (const WindowBounds& w : *side) uninformative += w.bounds.verified() && !w.informative ? 1 : 0;
  if (uninformative > 0)
    std::cout << "  " << uninformative << " of " << 2 * res.before.size()
              << " verified bounds are uninformative: dmax >= the RMS of the measured output's deviation "
                 "from its mean on the window, which the constant model y = mean already meets\n";
  const SignalScales& sc = res.before.front().bounds.scales;
  if (sc.applied)
    std::cout << "  objective on scaled signals: y / " << sc.y_scale_text() << ", z / " << sc.z_scale_text()
              << " (window 1; lambda = " << num(sc.lambda_scaled) << " there is " << num(sc.lambda_original, 6)
              << " in the data's units; bounds above in the data's units)\n";
  std::cout << "  Theorem 3.1 again on file rows " << res.before.front().file_begin << ":" << res.before.front().file_end
            << " (the first window only; the output map re-identified with x0 free, alternating method):\n"
            << "    before    " << identification_line(res.before_id) << "\n"
            << "    after     " << identification_line(res.after_id) << "\n";
  std::vector<std::string> written;  // only files that exist: an unverified bound has none
  for (const auto* side : {&res.before, &res.after})
    for (const WindowBounds& w : *side)
      if (!w.certificate.empty()) written.push_back(w.certificate);
  const size_t all_bounds = res.before.size() + res.after.size();
  if (written.empty()) {
    std::cout << "  certificates: none written (no bound was verified; the reasons are above)\n";
  } else {
    std::cout << "  certificates " << written.front();
    if (written.size() > 1) std::cout << ", " << written[1];
    if (written.size() > 2) std::cout << " (and " << written.size() - 2 << " more)";
    if (written.size() < all_bounds)
      std::cout << "; " << all_bounds - written.size() << " of " << all_bounds
                << " bounds were not verified and have no certificate";
    std::cout << " (check: lpvid-verify certificate FILE)\n";
  }

  // The test role: scored once per test set, now, for the models chosen above.
  ojson tests = ojson::array();
  for (size_t t = 0; t < res.tests.size(); ++t) {
    const TestScore& ts = res.tests[t];
    const std::string source = t < in.test_sources.size() ? in.test_sources[t] : "";
    const FreeRunScore &tb = ts.before, &ta = ts.after;
    const std::string rule = "free run; x0 from the first " + std::to_string(tb.warmup) +
                             " samples (warm-up), RMS and fit % over the remaining " + std::to_string(tb.scored);
    std::cout << "\ntest" << (res.tests.size() > 1 ? " " + std::to_string(t + 1) + " of " + std::to_string(res.tests.size()) : "")
              << " (" << source << ", " << ts.samples << " samples): scored once, after the selection;"
              << " no fit and no choice used it\n"
              << "  rule: " << rule << "\n"
              << "  before: RMS " << num(tb.rms) << ", fit " << num(tb.fit_percent, 4) << " %   after: RMS " << num(ta.rms)
              << ", fit " << num(ta.fit_percent, 4) << " %\n";
    tests.push_back({{"source", source},
                     {"samples", ts.samples},
                     {"rule", rule},
                     {"warmup_samples", tb.warmup},
                     {"scored_samples", tb.scored},
                     {"rms_before", finite_or_null(tb.rms)},
                     {"rms_after", finite_or_null(ta.rms)},
                     {"fit_percent_before", finite_or_null(tb.fit_percent)},
                     {"fit_percent_after", finite_or_null(ta.fit_percent)},
                     {"note", "scored once, after the effects were selected on the validation (selection) data; the "
                              "models were fitted on the estimation rows only"}});
  }
  // "test": the first test set (the field of earlier reports), "tests": all of them
  const ojson test = tests.empty() ? ojson(nullptr) : tests.front();
  const ojson tests_pooled = pooled_tests_json(res);

  // residual analysis and plots on the validation data (free run)
  const ShownRecord& shown = res.shown;
  const Mat<double>&yb = shown.y_before, &ya = shown.y_after;
  const Mat<double> rb = shown.data.y - yb, ra = shown.data.y - ya;
  std::cout << (in.folds ? "\nresidual on the last fold's rows (" + in.validation +
                               "; free run, x0 from its first samples; the final models were fitted on these rows too)\n"
                         : std::string("\nvalidation residual (free run)\n"));
  ojson analysis = ojson::object();
  if (shown.finite) {
    analysis["before"] = analysis_json("before", shown.before);
    analysis["after"] = analysis_json("after ", shown.after);
  }
  ojson plots = ojson::array();
  if (!in.plots_dir.empty() && shown.finite) {
    std::filesystem::create_directories(in.plots_dir);
    const std::string d = in.plots_dir + "/";
    std::vector<std::string> names = in.validation_outputs;
    if (names.size() != static_cast<size_t>(shown.data.ny())) {  // held-out rows of --data
      names.clear();
      for (const std::string& y : res.before_model.columns.y) names.push_back(y + (in.folds ? " (last fold)" : " (held out)"));
    }
    // the rows' place in the file: the last fold block of the estimation rows (fold mode)
    const double first_row =
        shown.last_fold ? static_cast<double>(in.file_row_offset + shown.first) : 0.0;
    const SignalInfo& info = res.after_model.signal_info;
    const std::vector<std::pair<std::string, PlotOutcome>> made = {
        {d + "residual.png", plot_residual(rb, ra, d + "residual.png", names, info, first_row)},
        {d + "autocorrelation.png", plot_residual_autocorrelation(rb, ra, d + "autocorrelation.png", names)},
        {d + "output.png", plot_output_fit(shown.data.y, yb, ya, d + "output.png", names, info, first_row)}};
    std::cout << (in.folds ? "\nplots (the last fold's rows)\n" : "\nplots (validation data)\n");
    const auto list = [&](const std::string& path, const PlotOutcome& o) {
      std::cout << "  " << (o.ok ? path + (o.svg.empty() ? "" : " (+ .svg)") : "not written: " + o.message) << "\n";
      plots.push_back({{"png", o.ok ? ojson(path) : ojson(nullptr)},
                       {"svg", o.svg.empty() ? ojson(nullptr) : ojson(o.svg)},
                       {"csv", plot_csv_path(path)},
                       {"message", o.message}});
    };
    for (const auto& [path, o] : made) list(path, o);
    // the estimation record and its roles: the selection blocks shaded, the after model's free run
    {
      RecordPlot rp;
      rp.u = in.est->u;
      rp.y = in.est->y;
      rp.yhat_after = res.estimation_after;
      for (const FoldBlock& b : r.fold_blocks) rp.blocks.emplace_back(static_cast<long>(b.first), static_cast<long>(b.last));
      rp.input_columns = res.before_model.columns.u;
      rp.output_columns = res.before_model.columns.y;
      rp.info = info;
      rp.first_row = in.file_row_offset;
      const std::string file = std::filesystem::path(in.command_line_data).filename().string();
      rp.title = "Estimation record " + file + " rows " + std::to_string(in.file_row_offset) + ":" +
                 std::to_string(in.file_row_offset + in.est->n()) +
                 (in.folds ? "; shaded: the " + std::to_string(r.fold_blocks.size()) + " blocks held out in turn to choose the effects"
                           : "; the effects were chosen on other rows (validation)") +
                 (res.tests.empty() ? "" : "; test records: test*.png");
      const std::string path = d + "record.png";
      list(path, plot_record(rp, path));
    }
    // the fitted static maps of the after model (model/static_blocks.h), over the estimation record's range
    const StaticBlocks<double>& st = res.after_model.statics;
    if (res.input_map_range) {
      const std::string path = d + "input_map.png";
      list(path, plot_static_map(st.input, res.input_map_range->lo, res.input_map_range->hi,
                                 "Fitted static input map u' = g_in(u) (" + std::string(to_string(st.input.kind)) + ")",
                                 "u, the measured input", "u', what the LPV part sees", path));
    }
    if (res.output_map_range) {
      const std::string path = d + "output_map.png";
      list(path, plot_static_map(st.output, res.output_map_range->lo, res.output_map_range->hi,
                                 "Fitted static output map y = g_out(v) (" + std::string(to_string(st.output.kind)) +
                                     "), over the range of v on the estimation record",
                                 "v = yhat + Phi, the LPV part's output", "y = g_out(v)", path));
    }
    // each test record: input, output, the models' free runs and the certified d_max as a band
    if (in.tests && !res.tests.empty()) {
      std::cout << "plots (test records, scored once at the end)\n";
      double dmax_after = 0;  // the largest certified d_max over the windows: it holds on each of them
      bool all_verified = !res.after.empty();
      for (const WindowBounds& w : res.after) {
        all_verified = all_verified && w.bounds.verified();
        dmax_after = std::max(dmax_after, w.bounds.dmax);
      }
      for (size_t t = 0; t < res.tests.size() && t < in.tests->size(); ++t) {
        const Experiment<double>& e = (*in.tests)[t];
        TestRecordPlot tp;
        tp.u = e.u;
        tp.y = e.y;
        tp.warmup = res.tests[t].before.warmup;
        tp.yhat_before = res.tests[t].y_before;
        tp.yhat_after = res.tests[t].y_after;
        if (!tp.yhat_before.allFinite() || !tp.yhat_after.allFinite()) continue;
        tp.dmax_after = all_verified ? dmax_after : 0.0;
        tp.input_columns = res.before_model.columns.u;
        tp.output_columns = res.before_model.columns.y;
        tp.info = res.after_model.signal_info;
        tp.source = t < in.test_sources.size() ? in.test_sources[t] : e.source;
        const std::string path = d + (res.tests.size() > 1 ? "test" + std::to_string(t + 1) + ".png" : std::string("test.png"));
        list(path, plot_test_record(tp, path));
      }
    }
  }

  ojson j = ojson::object();
  const bool verified = res.verified();
  j["status"] = verified ? "ok" : "not verified";
  j["command"] = "diagnose";
  j["estimation"] = {{"file", in.command_line_data}, {"rows", in.estimation}, {"samples", in.est->n()}};
  if (in.folds) {
    ojson blocks = ojson::array();
    for (const FoldBlock& b : r.fold_blocks) blocks.push_back({in.file_row_offset + b.first, in.file_row_offset + b.last});
    j["selection"] = {{"method", "blocked folds of the estimation record"},
                      {"folds", r.fold_blocks.size()},
                      {"file_rows", blocks},
                      {"warmup_samples", in.fold_warmup},
                      {"rule", acceptance_rule_text(r.fold_blocks.size(), r.min_gain)},
                      {"before_held_out_folds", folds_json(r.before_folds)},
                      {"after_held_out_folds", folds_json(r.after_folds)}};
  } else {
    j["validation"] = {{"source", in.validation}, {"samples", res.shown.data.n()}, {"init_samples", res.shown.init_samples},
                       {"role", "selection: ranks the candidate effects"}};
  }
  j["test"] = test;
  j["tests"] = tests;
  if (!tests_pooled.is_null()) j["tests_pooled"] = tests_pooled;
  if (in.records.size() > 1) j["records"] = estimation_records_json(in);
  j["effects"] = effects;
  j["before"] = side_json(r.before_estimation, r.before_validation, res.before);
  j["after"] = side_json(r.after_estimation, r.after_validation, res.after);
  j["before"]["theorem_3_1"] = identification_json(res.before_id);
  j["after"]["theorem_3_1"] = identification_json(res.after_id);
  j["noise_normalisation"] = "RMS: ||d||_2 <= dmax*sqrt(n*ny)";
  j["toeplitz_mode"] = "signal";
  j["solver"] = in.solver;
  j["relaxation"] = "delta, dmax: Theorem 2.1 for the least-squares model (output error on the whole estimation "
                    "record) on each window; theorem_3_1: the output map identified again on the first window by the "
                    "alternating method";
  j["verified"] = verified;
  j["rounds"] = rounds;
  j["residual_analysis_validation"] = analysis;
  j["plots"] = plots;
  if (!in.model_out.empty()) j["model"] = in.model_out;
  write_json(report_path, j);
}

}  // namespace lpvid::cli
