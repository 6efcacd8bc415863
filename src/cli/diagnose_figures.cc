// The figures of `lpvid diagnose` (cli/diagnose_report.h): the residual, its
// autocorrelation and the output fit on the shown rows, the estimation record
// with its selection blocks, the fitted static maps and each test record.
#include <algorithm>
#include <filesystem>

#include "cli/diagnose_report.h"
#include "plot/diagnose_plots.h"

namespace lpvid::cli {
namespace {

/// The legends' output names of the shown rows.
std::vector<std::string> shown_output_names(const DiagnoseReport& in) {
  const DiagnoseResult& res = *in.result;
  std::vector<std::string> names = in.validation_columns.y;
  if (names.size() != static_cast<size_t>(res.shown.data.ny())) {  // held-out rows of --data
    names.clear();
    for (const std::string& y : res.before_model.columns.y) names.push_back(y + (in.folds ? " (last fold)" : " (held out)"));
  }
  return names;
}

void draw_shown_rows(const DiagnoseReport& in, const std::string& d, DiagnoseFigures& out) {
  const DiagnoseResult& res = *in.result;
  const ShownRecord& shown = res.shown;
  const Mat<double> rb = shown.data.y - shown.y_before, ra = shown.data.y - shown.y_after;
  const std::vector<std::string> names = shown_output_names(in);
  // the rows' place in the file: the last fold block of the estimation rows (fold mode)
  const double first_row = shown.last_fold ? static_cast<double>(in.file_row_offset + shown.first) : 0.0;
  const SignalInfo& info = res.after_model.signal_info;
  const std::string unit = common_unit(info, res.before_model.columns.y);  // the residual is in the output's unit
  out.list.push_back({d + "residual.png", plot_residual(rb, ra, d + "residual.png", names, info, first_row, unit)});
  out.list.push_back({d + "autocorrelation.png", plot_residual_autocorrelation(rb, ra, d + "autocorrelation.png", names)});
  out.list.push_back({d + "output.png", plot_output_fit(shown.data.y, shown.y_before, shown.y_after, d + "output.png",
                                                        names, info, first_row, unit)});
}

/// The estimation record and its roles: the selection blocks shaded, the after model's free run.
void draw_record(const DiagnoseReport& in, const std::string& d, DiagnoseFigures& out) {
  const DiagnoseResult& res = *in.result;
  const RankingResult& r = res.rank;
  RecordPlot rp;
  rp.u = in.est->u;
  rp.y = in.est->y;
  rp.yhat_after = res.estimation_after;
  for (const FoldBlock& b : r.fold_blocks) rp.blocks.emplace_back(static_cast<long>(b.first), static_cast<long>(b.last));
  rp.input_columns = res.before_model.columns.u;
  rp.output_columns = res.before_model.columns.y;
  rp.info = res.after_model.signal_info;
  rp.first_row = in.file_row_offset;
  const std::string file = std::filesystem::path(in.command_line_data).filename().string();
  rp.title = "Estimation record " + file + " rows " + std::to_string(in.file_row_offset) + ":" +
             std::to_string(in.file_row_offset + in.est->n()) +
             (in.folds ? "; shaded: the " + std::to_string(r.fold_blocks.size()) + " blocks held out in turn to choose the effects"
                       : "; the effects were chosen on other rows (validation)") +
             (res.tests.empty() ? "" : "; test records: test*.png");
  out.list.push_back({d + "record.png", plot_record(rp, d + "record.png")});
}

/// The fitted static maps of the after model (model/static_blocks.h), over the estimation record's range.
void draw_static_maps(const DiagnoseResult& res, const std::string& d, DiagnoseFigures& out) {
  const StaticBlocks<double>& st = res.after_model.statics;
  const SignalInfo& info = res.after_model.signal_info;
  const std::string u = unit_suffix(common_unit(info, res.after_model.columns.u)),
                    y = unit_suffix(common_unit(info, res.after_model.columns.y));
  if (res.input_map_range) {
    const std::string path = d + "input_map.png";
    out.list.push_back({path, plot_static_map(st.input, res.input_map_range->lo, res.input_map_range->hi,
                                              "Fitted static input map u' = g_in(u) (" + std::string(to_string(st.input.kind)) + ")",
                                              "u, the measured input" + u, "u', what the LPV part sees" + u, path)});
  }
  if (res.output_map_range) {
    const std::string path = d + "output_map.png";
    out.list.push_back({path, plot_static_map(st.output, res.output_map_range->lo, res.output_map_range->hi,
                                              "Fitted static output map y = g_out(v) (" + std::string(to_string(st.output.kind)) +
                                                  "), over the range of v on the estimation record",
                                              "v = yhat + Phi, the LPV part's output (Phi: its scheduled basis terms)" + y,
                                              "y = g_out(v)" + y, path)});
  }
}

/// Each test record: input, output, the models' free runs and the certified d_max as a band.
void draw_tests(const DiagnoseReport& in, const std::string& d, DiagnoseFigures& out) {
  const DiagnoseResult& res = *in.result;
  if (!in.tests || res.tests.empty()) return;
  out.test_heading = true;
  // The largest certified d_max over the windows: it holds on each of them.
  const BoundsSummary after = res.bounds_summary(DiagnoseSide::kAfter);
  const bool all_verified = after.all_verified;
  const double dmax_after = after.dmax;
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
    if (t < in.test_columns.size()) {
      tp.input_names = in.test_columns[t].u;
      tp.output_names = in.test_columns[t].y;
    }
    tp.info = res.after_model.signal_info;
    tp.source = t < in.test_sources.size() ? in.test_sources[t] : e.source;
    const std::string path = d + (res.tests.size() > 1 ? "test" + std::to_string(t + 1) + ".png" : std::string("test.png"));
    out.list.push_back({path, plot_test_record(tp, path), true});
  }
}

}  // namespace

DiagnoseFigures draw_diagnose_figures(const DiagnoseReport& report) {
  DiagnoseFigures out;
  if (report.plots_dir.empty() || !report.result->shown.finite) return out;
  std::filesystem::create_directories(report.plots_dir);
  const std::string d = report.plots_dir + "/";
  out.drawn = true;
  draw_shown_rows(report, d, out);
  draw_record(report, d, out);
  draw_static_maps(*report.result, d, out);
  draw_tests(report, d, out);
  return out;
}

}  // namespace lpvid::cli
