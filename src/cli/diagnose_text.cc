// The readable report of `lpvid diagnose` on stdout (cli/diagnose_report.h).
#include <algorithm>
#include <cstdio>
#include <iostream>

#include "cli/diagnose_report.h"
#include "core/decimal_rounding.h"
#include "diagnose/residual_analysis.h"

namespace lpvid::cli {
namespace {

std::string num(double x, int digits = 4) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

/// The header line of the test role: every test set with its size.
std::string test_roles_text(const DiagnoseReport& in) {
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

std::string folds_text(const FoldFigures& f) {
  std::string t;
  for (size_t j = 0; j < f.sse.size(); ++j) t += (j ? " " : "") + num(f.rms(j), 3);
  return t;
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

/// Whiteness and input correlation of a validation residual, one line.
void print_analysis(const std::string& title, const ResidualAnalysis& a, const ColumnMap& names) {
  std::cout << "  " << title << ": RMS " << num(a.rms.overall);
  for (const AutocorrelationTest& t : a.whiteness.outputs)
    std::cout << "; autocorrelation: " << t.outside_99 << " of " << a.whiteness.max_lag
              << " lags outside the 99% band, Ljung-Box Q = " << num(t.q) << " (white if <= " << num(t.q_threshold)
              << "): " << (t.white ? "white" : "NOT white");
  for (const CrossCorrelation& c : a.input_correlation.pairs)
    std::cout << "; with " << signal_column(names, SignalRole::kInput, c.input) << ": max " << num(c.max_abs, 3) << " at lag " << c.max_lag_at
              << (c.significant ? " (significant)" : "");
  std::cout << "\n";
}

/// "0:256, 256:512, …" in data-file rows.
/// "rows 0:256, 256:512, …" (one record) or "a.csv rows 0:200, …, b.csv
/// rows 200:400" (several: each block in its own file's rows).
std::string fold_rows_text(const DiagnoseReport& in) {
  std::string t;
  const std::vector<DataReference> files = fold_files(in);
  for (size_t j = 0; j < in.result->rank.fold_blocks.size(); ++j) {
    const FoldBlock& b = in.result->rank.fold_blocks[j];
    t += (t.empty() ? "" : ", ");
    if (files.empty())
      t += std::to_string(in.file_row_offset + b.first) + ":" + std::to_string(in.file_row_offset + b.last);
    else
      t += files[j].file + " rows " + std::to_string(files[j].row_begin) + ":" + std::to_string(files[j].row_end);
  }
  return (files.empty() ? "rows " : "") + t;
}

std::string bound_line(const WindowBounds& w) {
  const CertifiedBounds& b = w.bounds;
  if (!b.verified()) return "not verified (" + b.reason + ")";
  return "delta <= " + upper_sqrt_text(b.delta2, 4) + ", dmax <= " + upper_sqrt_text(b.dmax2, 4) + " (verified, file rows " +
         std::to_string(w.file_begin) + ":" + std::to_string(w.file_end) + ")" + uninformative_mark(w);
}

void print_header(const DiagnoseReport& in) {
  const DiagnoseResult& res = *in.result;
  const RankingResult& r = res.rank;
  std::cout << "lpvid diagnose\n"
            << "  estimation  " << (in.estimation.empty() ? in.command_line_data : in.estimation) << " ("
            << in.est->n() << " samples)\n"
            << (in.folds ? "  selection   " + std::to_string(r.fold_blocks.size()) +
                               (in.records.size() > 1 ? " blocked folds within the estimation records, " : " blocked folds of the estimation record, ") +
                               fold_rows_text(in) +
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
}

/// "; est share below the 0.1 % floor: not accepted" for a candidate under
/// kMinEstimationShare, empty otherwise.
std::string floor_text(const ScoredCandidate& c) {
  if (c.estimation_share >= kMinEstimationShare) return "";
  return "; est share below the " + num(100 * kMinEstimationShare, 3) + " % floor: not accepted";
}

/// The physics-first line (diagnose/physical_alternative.h).
void print_physical_alternative(const RankingRound& rr) {
  const PhysicalAlternative& p = *rr.physical;
  const std::string ph = std::to_string(p.physical + 1), bb = std::to_string(p.black_box + 1);
  std::cout << "  physics first: rank " << ph << " (" << rr.ranked[static_cast<size_t>(p.physical)].kind << ") and rank " << bb
            << " (" << rr.ranked[static_cast<size_t>(p.black_box)].kind
            << ") are indistinguishable on these data: held-out RMS per fold, rank " << ph << " minus rank " << bb << ":";
  for (double d : p.differences) std::cout << " " << num(d, 3);
  std::cout << "; mean " << num(p.mean, 3) << " <= its standard error " << num(p.standard_error, 3) << "; "
            << (p.taken ? "the physical form, rank " + ph + ", is taken"
                        : "rank " + ph + " does not pass the acceptance rule, so rank " + bb + " stays")
            << "\n";
}

void print_round(const DiagnoseReport& in, size_t i) {
  const RankingRound& rr = in.result->rank.rounds[i];
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
  for (size_t k = 0; k < rr.ranked.size(); ++k) {
    const ScoredCandidate& c = rr.ranked[k];
    char line[320];
    std::snprintf(line, sizeof line, "  %-4zu  %-17s  %-9s  %-9s  %-9s  %-9s  %-6d  %s%s\n", k + 1, c.kind.c_str(),
                  num(c.rms_validation).c_str(), (num(100 * c.explained, 3) + "%").c_str(),
                  num(c.rms_estimation).c_str(), (num(100 * c.estimation_share, 3) + "%").c_str(), c.effect_parameters,
                  c.label.c_str(), static_cast<int>(k) == rr.chosen ? "   <- chosen" : "");
    std::cout << line;
    if (!c.reading.empty()) std::cout << "        fitted: " << c.reading << "\n";
    if (in.folds)
      std::cout << "        folds " << folds_text(c.folds) << "  (wins " << c.folds_won << " of " << c.folds.sse.size()
                << (c.joint ? "; A, B re-fitted" : "") << start_choice_text(c.start) << floor_text(c) << ")\n";
    else if (!floor_text(c).empty())
      std::cout << "        (" << floor_text(c).substr(2) << ")\n";
  }
  if (rr.tie) {
    std::cout << "  tie: ranks";
    for (int k : rr.tie->tied) std::cout << " " << k + 1;
    std::cout << " are within " << num(100 * kEffectTieTolerance, 3) << "% of each other's held-out RMS (largest difference "
              << num(100 * rr.tie->margin, 3) << "%): the data does not tell them apart; rank " << rr.chosen + 1
              << " is taken by the tie rule (" << rr.tie->rule << ")\n";
  }
  if (rr.physical) print_physical_alternative(rr);
  if (rr.chosen < 0)
    std::cout << "  -> none: no candidate " << (in.folds ? "passes the rule above against " : "lowers the validation RMS by the required share (and explains the share floor of the estimation residual) below ")
              << num(rr.reference_validation) << "\n";
}

/// A figure padded to the table's column width.
std::string column(double x) { return num(x) + std::string(16 - std::min<size_t>(15, num(x).size()), ' '); }

void print_summary_table(const DiagnoseReport& in) {
  const DiagnoseResult& res = *in.result;
  const RankingResult& r = res.rank;
  std::cout << "\neffects added: ";
  if (r.chosen.empty()) std::cout << "none";
  for (size_t i = 0; i < r.chosen.size(); ++i)
    std::cout << (i ? ", " : "") << r.chosen[i].label
              << (r.chosen[i].reading.empty() ? "" : " (fitted: " + r.chosen[i].reading + ")");
  std::cout << "\n\n              RMS estimation  " << (in.folds ? "RMS held-out  " : "RMS validation") << "  bounds\n"
            << "  before      " << column(r.before_estimation) << column(r.before_validation)
            << bound_line(res.before.front()) << "\n"
            << "  after       " << column(r.after_estimation) << column(r.after_validation)
            << bound_line(res.after.front()) << "\n";
  if (in.folds)
    std::cout << "  held-out RMS per fold: before " << folds_text(r.before_folds) << "; after " << folds_text(r.after_folds)
              << (r.chosen.empty() ? " (no effect passed: the starting model is kept)"
                                   : " (every effect added passed the rule against the model before it)")
              << "\n";
}

void print_windows(const DiagnoseResult& res) {
  std::string rows;
  for (const WindowBounds& w : res.before) rows += (rows.empty() ? "" : ", ") + std::to_string(w.begin) + ":" + std::to_string(w.end);
  std::cout << "  bounds on " << res.before.size() << " window" << (res.before.size() == 1 ? "" : "s")
            << " of estimation rows " << rows << " (Theorem 2.1 on each window's rows alone; window 1 above)\n";
  for (size_t i = 1; i < res.before.size(); ++i)
    std::cout << "  window " << i + 1 << " (estimation rows " << res.before[i].begin << ":" << res.before[i].end << ")\n"
              << "              before: " << bound_line(res.before[i]) << "\n"
              << "              after:  " << bound_line(res.after[i]) << "\n";
  const int uninformative =
      res.bounds_summary(DiagnoseSide::kBefore).uninformative + res.bounds_summary(DiagnoseSide::kAfter).uninformative;
  if (uninformative > 0)
    std::cout << "  " << uninformative << " of " << 2 * res.before.size()
              << " verified bounds are uninformative: dmax >= the RMS of the measured output's deviation "
                 "from its mean on the window, which the constant model y = mean already meets\n";
  const SignalScales& sc = res.before.front().bounds.scales;
  if (sc.applied)
    std::cout << "  objective on scaled signals: y / " << sc.y_scale_text() << ", z / " << sc.z_scale_text()
              << " (window 1; lambda = " << num(sc.lambda_scaled) << " there is " << num(sc.lambda_original, 6)
              << " in the data's units; bounds above in the data's units)\n";
  const DataReference& thm31_rows = res.before_id.rows;
  std::cout << "  Theorem 3.1 again on " << (thm31_rows.file.empty() ? std::string("file") : thm31_rows.file) << " rows "
            << res.before.front().file_begin << ":" << res.before.front().file_end
            << " (the first window only; the output map re-identified with x0 free, alternating method):\n"
            << "    before    " << identification_line(res.before_id) << "\n"
            << "    after     " << identification_line(res.after_id) << "\n";
}

void print_certificates(const DiagnoseResult& res, bool named) {
  if (!named) {
    std::cout << "  certificates: no file written (name them with --certificate FILE or --report FILE)\n";
    return;
  }
  std::vector<std::string> written;  // only files that exist: an unverified bound has none
  for (const auto* side : {&res.before, &res.after})
    for (const WindowBounds& w : *side)
      if (!w.certificate.empty()) written.push_back(w.certificate);
  const size_t all_bounds = res.before.size() + res.after.size();
  if (written.empty()) {
    std::cout << "  certificates: none written (no bound was verified; the reasons are above)\n";
    return;
  }
  std::cout << "  certificates " << written.front();
  if (written.size() > 1) std::cout << ", " << written[1];
  if (written.size() > 2) std::cout << " (and " << written.size() - 2 << " more)";
  if (written.size() < all_bounds)
    std::cout << "; " << all_bounds - written.size() << " of " << all_bounds
              << " bounds were not verified and have no certificate";
  std::cout << " (check: lpvid-verify certificate FILE)\n";
}

/// Test record t against the estimation record's range, signal by signal:
/// the signals outside it one line each, then the ones inside.
void print_test_range(const DiagnoseReport& in, size_t t) {
  const TestScore& ts = in.result->tests[t];
  const ColumnMap names = t < in.test_columns.size() ? in.test_columns[t] : ColumnMap{};
  const ColumnMap& est = in.result->before_model.columns;
  std::string inside;
  bool any_outside = false;
  for (const SignalExcursion& e : ts.excursions) {
    if (e.outside() == 0) {
      inside += (inside.empty() ? "" : ", ") + signal_column(names, e.role, e.column) +
                (e.role == SignalRole::kScheduling ? " (scheduling)" : "");
      continue;
    }
    std::cout << (any_outside ? "         " : "  range: ") << "OUTSIDE the estimation range: "
              << excursion_text(e, names, est) << "\n";
    any_outside = true;
  }
  if (!inside.empty())
    std::cout << (any_outside ? "         " : "  range: ") << "inside the estimation range: " << inside << "\n";
}

/// The test role: scored once per test set, for the models chosen above; then the pooled score.
void print_tests(const DiagnoseReport& in) {
  const DiagnoseResult& res = *in.result;
  for (size_t t = 0; t < res.tests.size(); ++t) {
    const TestScore& ts = res.tests[t];
    const FreeRunScore &tb = ts.before, &ta = ts.after;
    std::cout << "\ntest" << (res.tests.size() > 1 ? " " + std::to_string(t + 1) + " of " + std::to_string(res.tests.size()) : "")
              << " (" << (t < in.test_sources.size() ? in.test_sources[t] : "") << ", " << ts.samples
              << " samples): scored once, after the selection;"
              << " no fit and no choice used it\n"
              << "  rule: " << test_rule_text(tb) << "\n"
              << "  before: RMS " << num(tb.rms) << ", fit " << num(tb.fit_percent, 4) << " %   after: RMS " << num(ta.rms)
              << ", fit " << num(ta.fit_percent, 4) << " %\n";
    print_test_range(in, t);
    if (ts.after_worse())
      std::cout << "  AFTER IS WORSE than before on this test record (RMS " << num(ta.rms) << " > " << num(tb.rms)
                << "); stated here, not used to choose\n";
  }
  if (res.tests.size() < 2) return;
  const FreeRunScore &b = res.pooled_before, &a = res.pooled_after;
  std::cout << "\ntests pooled (" << res.tests.size() << " sets, " << a.scored
            << " scored samples, each set from its own warm-up): before: RMS " << num(b.rms) << ", fit "
            << num(b.fit_percent, 4) << " %   after: RMS " << num(a.rms) << ", fit " << num(a.fit_percent, 4) << " %\n";
}

void print_residual_analysis(const DiagnoseReport& in) {
  std::cout << (in.folds ? "\nresidual on the last fold's rows (" + in.validation +
                               "; free run, x0 from its first samples; the final models were fitted on these rows too)\n"
                         : std::string("\nvalidation residual (free run)\n"));
  if (!in.result->shown.finite) return;
  const ColumnMap& names = in.validation_columns.u.empty() ? in.result->before_model.columns : in.validation_columns;
  print_analysis("before", in.result->shown.before, names);
  print_analysis("after ", in.result->shown.after, names);
}

void print_figures(const DiagnoseReport& in, const DiagnoseFigures& figures) {
  if (!figures.drawn) return;
  std::cout << (in.folds ? "\nplots (the last fold's rows)\n" : "\nplots (validation data)\n");
  bool heading = false;
  const auto test_heading = [&] {
    if (!heading) std::cout << "plots (test records, scored once at the end)\n";
    heading = true;
  };
  for (const DrawnFigure& f : figures.list) {
    if (f.test_record) test_heading();
    const PlotOutcome& o = f.outcome;
    std::cout << "  " << (o.ok ? f.path + (o.svg.empty() ? "" : " (+ .svg)") : "not written: " + o.message) << "\n";
  }
  if (figures.test_heading) test_heading();
}

/// Several estimation records: each record's free-run figures, then the pooled line.
void print_records(const DiagnoseReport& in) {
  if (in.records.size() < 2) return;
  std::cout << "\nestimation records (free run of the fitted models, each record from its own fitted initial state)\n";
  const auto line = [](const EstimationRecordScore& s) {
    return "before: RMS " + num(s.before.rms_all) + ", fit " + num(s.before.fit_percent_all, 4) + " %   after: RMS " +
           num(s.after.rms_all) + ", fit " + num(s.after.fit_percent_all, 4) + " %\n";
  };
  for (size_t k = 0; k < in.records.size() && k < in.result->estimation_records.records.size(); ++k)
    std::cout << "  record " << k + 1 << " (" << in.records[k].text << ", " << in.result->estimation_records.records[k].samples
              << " samples): " << line(in.result->estimation_records.records[k]);
  std::cout << "  pooled (" << in.result->estimation_records.pooled.samples << " samples): " << line(in.result->estimation_records.pooled);
}

}  // namespace

void print_diagnose_text(const DiagnoseReport& report, const DiagnoseFigures& figures) {
  print_header(report);
  for (size_t i = 0; i < report.result->rank.rounds.size(); ++i) print_round(report, i);
  print_summary_table(report);
  print_windows(*report.result);
  print_certificates(*report.result, report.certificates_named);
  print_tests(report);
  print_residual_analysis(report);
  print_figures(report, figures);
  print_records(report);
}

}  // namespace lpvid::cli
