// lpvid compare: models' free-run (or k-step-ahead) output against measured
// data (RMS and fit % per output, the rows compared, the initial state
// used), the figure a user checks before and after a change of the model.
// Several --model give one table; --u/--y/--rho map the models' columns to
// the data's in memory (cli/compare_columns.h). The command reads the models
// and the records, makes one call, compare_models (fit/compare_models.h),
// and renders its result: the text, the JSON report, the series CSV, the
// figure and the model with its fitted x0.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/refused_alias.h"
#include "cli/compare_columns.h"
#include "cli/compare_output.h"
#include "cli/inputs.h"
#include "cli/report.h"
#include "cli/signal_info_options.h"
#include "core/file_io.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "core/text_printf.h"
#include "data/csv_reader.h"
#include "fit/compare_models.h"
#include "model/model_file.h"

namespace lpvid::cli {
namespace {

struct CompareArgs {
  std::vector<std::string> models;                ///< every --model, in order
  std::string out, report, model_out, x0, plots_dir;   ///< x0: "" (not given), model or fit; plots_dir: --plots
  std::vector<std::string> data_paths, rows_texts;  ///< every --data / --rows (several records)
  std::string data_rows_order;
  std::vector<std::string> names;
  long warmup = 0;
  long predict = 0;         ///< --predict K: k-step-ahead (0: free run)
  long predict_window = 0;  ///< --predict-window M (0: the model's order)
  ColumnMappingArgs columns;
  SignalInfoArgs signal_info;
};

std::string percent_text(double x) {
  if (!std::isfinite(x)) return x > 0 ? "inf" : "-inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  return buf;
}

TextTable read_record(const CompareArgs& a, const RecordOption& r) {
  try {
    return a.names.empty() ? read_table(r.path) : read_table(r.path, a.names);
  } catch (const InputError& e) {
    if (!a.columns.given() || !a.names.empty()) throw;
    throw InputError(std::string(e.what()) + "; --u/--y/--rho name columns of a header: give --names for a headerless file");
  }
}

/// Each --data read, its columns checked against --u/--y/--rho, with its --rows.
std::vector<CompareRecord> read_records(const CompareArgs& a, const std::vector<RecordOption>& recs) {
  std::vector<CompareRecord> out;
  for (const RecordOption& r : recs) {
    CompareRecord c{r.path, read_record(a, r), std::nullopt, r.rows_text};
    check_mapped_columns(a.columns, c.table.header, r.path);
    if (!r.rows_text.empty()) c.rows = parse_row_range(r.rows_text, "--rows");
    out.push_back(std::move(c));
  }
  return out;
}

CompareOptions compare_options(const CompareArgs& a, bool fit_x0) {
  CompareOptions o;
  o.fit_x0 = fit_x0;
  o.warmup = a.warmup;
  o.predict = a.predict;
  o.predict_window = a.predict_window;
  return o;
}

std::string prediction_text(const CompareArgs& a, const ModelComparison& m) {
  if (a.predict == 0) return "free run";
  return std::to_string(a.predict) + "-step-ahead prediction, state re-fitted on " + std::to_string(m.state_window) +
         " output samples ending " + std::to_string(a.predict) + " rows before each";
}

void print_scores(const OutputScores& s, const std::vector<std::string>& names) {
  std::cout << text_printf("  %-16s %14s %10s\n", "output", "RMS(y - yhat)", "fit %");
  for (size_t i = 0; i < s.rms.size(); ++i)
    std::cout << text_printf("  %-16s %14.6g %10s\n", names[i].c_str(), s.rms[i], percent_text(s.fit_percent[i]).c_str());
  if (s.rms.size() > 1) std::cout << text_printf("  %-16s %14.6g %10s\n", "all outputs", s.rms_all, percent_text(s.fit_percent_all).c_str());
}

void print_record(const CompareArgs& a, const ModelComparison& m, const RecordComparison& c, bool fit_x0) {
  const Eigen::Index scored = c.exp.n() - c.skip;
  std::cout << "lpvid compare: " << m.file << " on " << c.file << " rows " << c.first + c.skip << ":" << c.first + c.exp.n()
            << " (" << scored << " samples";
  if (c.skip > 0) std::cout << "; x0 fitted on the " << c.skip << " rows before them";
  else std::cout << (fit_x0 ? "; x0 fitted on these rows" : "; x0 as in the model file");
  std::cout << ", " << prediction_text(a, m) << ")\n";
  print_scores(c.scores, c.model.columns.y);
  std::cout << "  (fit % = 100*(1 - ||y - yhat|| / ||y - mean(y)||): 100 perfect, 0 no better than the mean)\n";
  if (fit_x0) {
    std::cout << "  x0          ";
    for (Eigen::Index i = 0; i < c.model.x0.size(); ++i) std::cout << " " << double_to_text(c.model.x0(i));
    std::cout << "\n";
  }
}

/// The prediction and column fields of a model's report.
void add_model_fields(nlohmann::ordered_json& r, const CompareArgs& a, const ModelComparison& m) {
  r["prediction"] = a.predict > 0 ? "k_step" : "free_run";
  r["predict_steps"] = a.predict;
  if (a.predict > 0) r["state_window"] = m.state_window;
  const ColumnMap& columns = m.model.columns;
  r["columns"] = {{"u", columns.u}, {"y", columns.y}, {"rho", columns.rho}};
}

/// The report fields of one record (the whole report for one --data).
nlohmann::ordered_json record_json(const CompareArgs& a, const ModelComparison& m, const RecordComparison& c, bool fit_x0) {
  nlohmann::ordered_json r;
  r["data"] = c.file;
  r["model"] = m.file;
  r["rows"] = {c.first + c.skip, c.first + c.exp.n()};
  r["warmup_rows"] = c.skip;
  r["x0"] = fit_x0 ? (c.skip > 0 ? "fitted on the warm-up rows" : "fitted on the compared rows") : "model file";
  r["x0_values"] = std::vector<double>(c.model.x0.data(), c.model.x0.data() + c.model.x0.size());
  nlohmann::ordered_json outs = nlohmann::ordered_json::array();
  for (size_t i = 0; i < c.scores.rms.size(); ++i)
    outs.push_back({{"name", c.model.columns.y[i]}, {"rms", c.scores.rms[i]}, {"fit_percent", c.scores.fit_percent[i]}});
  r["outputs"] = outs;
  r["rms"] = c.scores.rms_all;
  r["fit_percent"] = c.scores.fit_percent_all;
  r["finite"] = c.scores.finite;
  add_model_fields(r, a, m);
  return r;
}
/// One model's report: the one-record report, or the pooled report with
/// its records.
nlohmann::ordered_json model_json(const CompareArgs& a, const ModelComparison& m, bool fit_x0) {
  if (m.records.size() == 1) return record_json(a, m, m.records.front(), fit_x0);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const RecordComparison& c : m.records) list.push_back(record_json(a, m, c, fit_x0));
  nlohmann::ordered_json r;
  r["data"] = a.data_paths;
  r["model"] = m.file;
  r["samples"] = m.samples;
  r["rms"] = m.pooled.rms_all;
  r["fit_percent"] = m.pooled.fit_percent_all;
  r["finite"] = m.pooled.finite;
  r["records"] = list;
  add_model_fields(r, a, m);
  return r;
}

void print_model(const CompareArgs& a, const ModelComparison& m, bool fit_x0) {
  for (const RecordComparison& c : m.records) print_record(a, m, c, fit_x0);
  if (m.records.size() == 1) return;
  std::cout << "pooled: " << m.records.size() << " records, " << m.samples << " samples (each record from its own x0)\n";
  print_scores(m.pooled, m.model.columns.y);
}

/// The table of several models: one row per model, RMS and fit % per output.
void print_table(const std::vector<ModelComparison>& ms, const std::vector<std::string>& names) {
  const std::vector<std::string>& outs = ms.front().model.columns.y;
  std::cout << text_printf("\n  %-24s", "model");
  for (const std::string& o : outs) std::cout << text_printf(" %14s %8s", ("RMS " + o).c_str(), "fit %");
  if (outs.size() > 1) std::cout << text_printf(" %14s %8s", "RMS all", "fit %");
  std::cout << "\n";
  for (size_t k = 0; k < ms.size(); ++k) {
    const ModelComparison& m = ms[k];
    std::cout << text_printf("  %-24s", names[k].c_str());
    for (size_t i = 0; i < outs.size(); ++i)
      std::cout << text_printf(" %14.6g %8s", m.pooled.rms[i], percent_text(m.pooled.fit_percent[i]).c_str());
    if (outs.size() > 1) std::cout << text_printf(" %14.6g %8s", m.pooled.rms_all, percent_text(m.pooled.fit_percent_all).c_str());
    std::cout << "\n";
  }
}

/// The sample time and units: the options over the first model's.
SignalInfo compare_signal_info(const CompareArgs& a, const std::vector<LpvModel<double>>& models) {
  SignalInfo base = models.front().signal_info;
  for (const LpvModel<double>& m : models) {
    if (base.sample_time == 0) base.sample_time = m.signal_info.sample_time;
    for (const auto& [col, unit] : m.signal_info.units)
      if (base.unit_of(col).empty()) base.units.emplace_back(col, unit);
  }
  return signal_info_of(a.signal_info, models.front().columns, base);
}

void check_options(const CompareArgs& a, bool fit_x0, size_t records) {
  check_output_file(a.out, "--out");
  check_output_file(a.report, "--report");
  check_output_file(a.model_out, "--model-out");
  check_output_directory(a.plots_dir, "--plots");
  if (a.warmup < 0) throw InputError("--warmup must be >= 0");
  if (a.predict_window > 0 && a.predict == 0) throw InputError("--predict-window goes with --predict K");
  if (a.x0 == "model" && a.warmup > 0)
    throw InputError("--warmup fits x0 on the first rows: it cannot go with --x0 model (leave --x0 out)");
  if (!a.model_out.empty() && !fit_x0) throw InputError("--model-out writes the fitted x0: give --x0 fit or --warmup");
  if (!a.model_out.empty() && a.models.size() > 1) throw InputError("--model-out takes one --model");
  if (records > 1 && (!a.out.empty() || !a.model_out.empty() || !a.plots_dir.empty()))
    throw InputError("--out, --plots and --model-out take one --data (one record); give the records one at a time");
}

std::vector<LpvModel<double>> read_models(const CompareArgs& a) {
  std::vector<LpvModel<double>> out;
  for (const std::string& path : a.models) {
    const LpvModel<double> model = read_model_file<double>(path);
    if (!model.offset.basis.empty() && model.offset.values.empty())
      throw InputError(path + ": offset: the offset values are unknown; give \"values\" (or identify them first)");
    out.push_back(map_model_columns(model, a.columns, path));
    if (out.back().columns.y != out.front().columns.y)
      throw InputError("--model " + path + " reads the outputs " + out.back().columns.y.front() + "... but --model " +
                       a.models.front() + " reads " + out.front().columns.y.front() +
                       "...: the models must score the same output columns (map them with --y)");
  }
  return out;
}

/// --out, --plots, --model-out of one record.
void write_record_files(const CompareArgs& a, const std::vector<ModelComparison>& ms,
                        const std::vector<std::string>& names, const SignalInfo& info, nlohmann::ordered_json& report) {
  const RecordComparison& c0 = ms.front().records.front();
  const ComparedRows rows{c0.first, c0.skip, c0.exp.y, c0.model.columns.y, info};
  std::vector<ComparedSeries> series;
  for (size_t k = 0; k < ms.size(); ++k) series.push_back({names[k], ms[k].records.front().yhat});
  if (!a.out.empty()) {
    write_compare_series(a.out, rows, series);
    std::cout << "  series      " << a.out << " (row" << (info.sample_time > 0 ? ", time_s" : "")
              << ", scored, and per output: measured, model, residual)\n";
    report["series"] = a.out;
  }
  const std::string png = a.plots_dir.empty() ? "" : (std::filesystem::path(a.plots_dir) / "compare.png").string();
  if (!a.plots_dir.empty()) std::filesystem::create_directories(a.plots_dir);
  const std::string plotted = plot_compare(png, rows, series, "lpvid compare on " + std::filesystem::path(c0.file).filename().string() + " (" + prediction_text(a, ms.front()) + ")");
  if (!plotted.empty()) {
    std::cout << "  plot        " << plotted << "\n";
    report["plot"] = plotted.rfind("no plot", 0) == 0 ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(png);
  }
  if (!a.model_out.empty()) {
    write_model_file(a.model_out, c0.model);
    std::cout << "  model       " << a.model_out << " (the model with the fitted x0)\n";
  }
}

/// The report: one model's, or the table of several (printed) and their
/// reports as a "models" list.
nlohmann::ordered_json compare_report(const CompareArgs& a, const std::vector<ModelComparison>& ms,
                                      const std::vector<std::string>& names, const std::vector<RecordOption>& recs,
                                      bool fit_x0) {
  if (ms.size() == 1) return model_json(a, ms.front(), fit_x0);
  print_table(ms, names);
  nlohmann::ordered_json report;
  report["data"] = recs.size() == 1 ? nlohmann::ordered_json(recs.front().path) : nlohmann::ordered_json(a.data_paths);
  report["warmup_rows"] = a.warmup;
  report["prediction"] = a.predict > 0 ? "k_step" : "free_run";
  report["predict_steps"] = a.predict;
  report["models"] = nlohmann::ordered_json::array();
  for (size_t k = 0; k < ms.size(); ++k) {
    nlohmann::ordered_json j = model_json(a, ms[k], fit_x0);
    j["name"] = names[k];
    report["models"].push_back(j);
  }
  return report;
}

int run_compare(const CompareArgs& a) {
  const bool fit_x0 = a.x0 == "fit" || a.warmup > 0;
  const std::vector<RecordOption> recs = pair_data_and_rows(a.data_paths, a.rows_texts, a.data_rows_order);
  check_options(a, fit_x0, recs.size());
  const std::vector<LpvModel<double>> models = read_models(a);
  const SignalInfo info = compare_signal_info(a, models);
  const std::vector<std::string> names = model_names(a.models);
  const CompareResult result = compare_models(models, a.models, read_records(a, recs), compare_options(a, fit_x0));
  // the models compared before one that could not be are shown before its error
  for (const ModelComparison& m : result.models) print_model(a, m, fit_x0);
  if (result.failure) std::rethrow_exception(result.failure);
  const std::vector<ModelComparison>& ms = result.models;
  nlohmann::ordered_json report = compare_report(a, ms, names, recs, fit_x0);
  if (info.sample_time > 0) report["sample_time"] = info.sample_time;
  if (!info.units.empty())
    for (const auto& [col, unit] : info.units) report["units"][col] = unit;
  if (recs.size() == 1) write_record_files(a, ms, names, info, report);
  write_json(a.report, report);
  const bool finite = std::all_of(ms.begin(), ms.end(), [](const ModelComparison& m) { return m.pooled.finite; });
  return finite ? kExitOk : kExitSolver;
}

}  // namespace

Runner add_compare_command(CLI::App& app) {
  auto a = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "Models' free-run (or k-step-ahead) output against measured data: RMS and fit % per output, CSV, plot");
  add_data_and_rows(*cmd, a->data_paths, a->rows_texts, a->data_rows_order,
                    "data file; repeat for several records (each compared from its own x0, then pooled)",
                    "window of data rows B:E (0-based, E exclusive) of the --data before it; the state starts at B");
  cmd->add_option("--model", a->models, "model file; repeat to compare several models on the same rows (one table)")
      ->required();
  cmd->add_option("--u", a->columns.u,
                  "data column(s) playing the model's input columns, in the model's order (the model file is not "
                  "edited; scheduling columns on an input follow it)")
      ->delimiter(',');
  cmd->add_option("--y", a->columns.y, "data column(s) playing the model's output columns, in the model's order")
      ->delimiter(',');
  cmd->add_option("--rho", a->columns.rho,
                  "data column(s) playing the model's scheduling columns read from data (not the @x state forms), "
                  "in the model's order")
      ->delimiter(',');
  cmd->add_option("--names", a->names, "column names for a headerless whitespace data file (every record)")->delimiter(',');
  cmd->add_option("--x0", a->x0, "initial state: model (as in the model file; default) or fit (least squares, multi-start)")
      ->check(CLI::IsMember({"model", "fit"}));
  cmd->add_option("--warmup", a->warmup,
                  "fit x0 on the first K compared rows and score only the rows after them (a benchmark protocol)");
  cmd->add_option("--predict", a->predict,
                  "K >= 1: k-step-ahead prediction instead of the free run: for each row t the state is re-fitted "
                  "(least squares, no observer) on the measured outputs of the --predict-window rows ending at t-K, "
                  "then the model runs K steps on the measured inputs")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--predict-window", a->predict_window,
                  "output rows the state of each k-step prediction is fitted on (default: the model's order)")
      ->check(CLI::PositiveNumber);
  add_signal_info_options(*cmd, a->signal_info);
  cmd->add_option("--out", a->out,
                  "CSV: row, time_s (with a sample time), scored (0 for warm-up rows), and per output the measured, "
                  "model and residual series (several models: <model>.yhat.<output>, <model>.residual.<output>)");
  cmd->add_option("--plots", a->plots_dir,
                  "directory for the figure DIR/compare.png (gnuplot; with its CSV data and .plot.json): measured "
                  "output and each model's, warm-up rows in grey");
  add_renamed_option(*cmd, "--plot", "--plots DIR", "a directory, as in diagnose; the figure is DIR/compare.png");
  cmd->add_option("--report", a->report, "JSON report (several models: a \"models\" list of one-model reports)");
  cmd->add_option("--model-out", a->model_out, "write the model with the fitted x0 (one --model)");
  return [cmd, a] { return cmd->parsed() ? run_compare(*a) : -1; };
}

}  // namespace lpvid::cli
