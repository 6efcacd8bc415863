// lpvid compare: a model's free-run output against measured data (RMS and
// fit % per output, the rows compared, the initial state used), the figure
// a user checks before and after a change of the model.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/inputs.h"
#include "cli/report.h"
#include "core/file_io.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "data/csv_reader.h"
#include "data/csv_writer.h"
#include "data/experiment_builder.h"
#include "fit/output_error_fit.h"
#include "fit/output_score.h"
#include "model/model_file.h"
#include "model/simulate.h"

namespace lpvid::cli {
namespace {

struct CompareArgs {
  std::string model, out, report, model_out, x0;  ///< x0: "" (not given), model or fit
  std::vector<std::string> data_paths, rows_texts;             ///< every --data / --rows (several records)
  std::string data_rows_order;
  std::vector<std::string> names;
  long warmup = 0;
};

std::string percent_text(double x) {
  if (!std::isfinite(x)) return x > 0 ? "inf" : "-inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  return buf;
}

/// One record compared: its rows (first: the file row of its row 0), the
/// model with its own x0 (fitted or as in the file), the free run and scores.
struct ComparedRecord {
  std::string file;
  long first = 0;
  Eigen::Index skip = 0;
  Experiment<double> exp;
  LpvModel<double> model;
  Simulation<double> sim;
  OutputScores s;
};

ComparedRecord compare_record(const CompareArgs& a, const LpvModel<double>& model, const RecordOption& r, bool fit_x0) {
  ComparedRecord c{r.path, 0, a.warmup, {}, model, {}, {}};
  const TextTable table = a.names.empty() ? read_table(r.path) : read_table(r.path, a.names);
  c.exp = make_experiment<double>(table, model.columns);
  if (!r.rows_text.empty()) {
    const auto [b, e] = parse_row_range(r.rows_text, "--rows");
    if (e > c.exp.n())
      throw InputError("--rows " + r.rows_text + ": " + (a.data_paths.size() > 1 ? r.path + " has" : std::string("the data has")) +
                       " only " + std::to_string(c.exp.n()) + " rows");
    c.exp = select_rows(c.exp, b, e);
    c.first = b;
  }
  if (a.warmup >= c.exp.n())
    throw InputError("--warmup " + std::to_string(a.warmup) + " leaves nothing to score in " + std::to_string(c.exp.n()) +
                     " rows" + (a.data_paths.size() > 1 ? " of " + r.path : ""));
  // x0: the model's, or fitted (multi-start, fit/output_error_fit.h) on the
  // warm-up rows, or on all compared rows without --warmup
  if (fit_x0) {
    const FitResult f = fit_initial_state(c.model, c.exp, a.warmup > 0 ? a.warmup : c.exp.n());
    if (!f.finite) throw InputError(a.model + ": no initial state keeps the simulation finite on the rows of " + r.path);
    c.model.x0 = f.model.x0;
  }
  c.sim = simulate(c.model, c.exp);
  const Eigen::Index scored = c.exp.n() - c.skip;
  c.s = score_outputs(c.exp.y.bottomRows(scored), c.sim.output.bottomRows(scored));
  return c;
}

void print_scores(const OutputScores& s, const std::vector<std::string>& names) {
  std::printf("  %-16s %14s %10s\n", "output", "RMS(y - yhat)", "fit %");
  for (size_t i = 0; i < s.rms.size(); ++i)
    std::printf("  %-16s %14.6g %10s\n", names[i].c_str(), s.rms[i], percent_text(s.fit_percent[i]).c_str());
  if (s.rms.size() > 1) std::printf("  %-16s %14.6g %10s\n", "all outputs", s.rms_all, percent_text(s.fit_percent_all).c_str());
}

void print_record(const CompareArgs& a, const ComparedRecord& c, bool fit_x0) {
  const Eigen::Index scored = c.exp.n() - c.skip;
  std::cout << "lpvid compare: " << a.model << " on " << c.file << " rows " << c.first + c.skip << ":" << c.first + c.exp.n()
            << " (" << scored << " samples";
  if (c.skip > 0) std::cout << "; x0 fitted on the " << c.skip << " rows before them";
  else std::cout << (fit_x0 ? "; x0 fitted on these rows" : "; x0 as in the model file");
  std::cout << ", free run)\n";
  print_scores(c.s, c.model.columns.y);
  std::cout << "  (fit % = 100*(1 - ||y - yhat|| / ||y - mean(y)||): 100 perfect, 0 no better than the mean)\n";
  if (fit_x0) {
    std::cout << "  x0          ";
    for (Eigen::Index i = 0; i < c.model.x0.size(); ++i) std::cout << " " << double_to_text(c.model.x0(i));
    std::cout << "\n";
  }
}

void write_series(const std::string& path, const ComparedRecord& c) {
  std::vector<TextColumn> cols;
  std::vector<std::string> row;
  for (Eigen::Index k = 0; k < c.exp.n(); ++k) row.push_back(std::to_string(c.first + k));
  cols.push_back({"row", row});
  const Mat<double> resid = c.exp.y - c.sim.output;
  for (Eigen::Index i = 0; i < c.exp.y.cols(); ++i) {
    const std::string& name = c.model.columns.y[static_cast<size_t>(i)];
    cols.push_back({name, column_text(c.exp.y, i)});
    cols.push_back({name + "_model", column_text(c.sim.output, i)});
    cols.push_back({name + "_residual", column_text(resid, i)});
  }
  write_csv(path, cols);
}

/// The report fields of one record (the whole report for one --data).
nlohmann::ordered_json record_json(const CompareArgs& a, const ComparedRecord& c, bool fit_x0) {
  nlohmann::ordered_json r;
  r["data"] = c.file;
  r["model"] = a.model;
  r["rows"] = {c.first + c.skip, c.first + c.exp.n()};
  r["warmup_rows"] = c.skip;
  r["x0"] = fit_x0 ? (c.skip > 0 ? "fitted on the warm-up rows" : "fitted on the compared rows") : "model file";
  r["x0_values"] = std::vector<double>(c.model.x0.data(), c.model.x0.data() + c.model.x0.size());
  nlohmann::ordered_json outs = nlohmann::ordered_json::array();
  for (size_t i = 0; i < c.s.rms.size(); ++i)
    outs.push_back({{"name", c.model.columns.y[i]}, {"rms", c.s.rms[i]}, {"fit_percent", c.s.fit_percent[i]}});
  r["outputs"] = outs;
  r["rms"] = c.s.rms_all;
  r["fit_percent"] = c.s.fit_percent_all;
  r["finite"] = c.s.finite;
  return r;
}

/// Several records: each compared on its own (its own x0), then every scored
/// sample of every record pooled.
int compare_records(const CompareArgs& a, const LpvModel<double>& model, const std::vector<RecordOption>& recs, bool fit_x0) {
  if (!a.out.empty() || !a.model_out.empty())
    throw InputError("--out and --model-out take one --data (one record); give the records one at a time");
  std::vector<ComparedRecord> done;
  for (const RecordOption& r : recs) done.push_back(compare_record(a, model, r, fit_x0));
  Eigen::Index n = 0;
  for (const ComparedRecord& c : done) n += c.exp.n() - c.skip;
  Mat<double> y(n, model.ny), yhat(n, model.ny);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  Eigen::Index at = 0;
  for (const ComparedRecord& c : done) {
    const Eigen::Index scored = c.exp.n() - c.skip;
    y.middleRows(at, scored) = c.exp.y.bottomRows(scored);
    yhat.middleRows(at, scored) = c.sim.output.bottomRows(scored);
    at += scored;
    print_record(a, c, fit_x0);
    list.push_back(record_json(a, c, fit_x0));
  }
  const OutputScores s = score_outputs(y, yhat);
  std::cout << "pooled: " << done.size() << " records, " << n << " samples (each record from its own x0)\n";
  print_scores(s, model.columns.y);
  nlohmann::ordered_json r;
  r["data"] = a.data_paths;
  r["model"] = a.model;
  r["samples"] = n;
  r["rms"] = s.rms_all;
  r["fit_percent"] = s.fit_percent_all;
  r["finite"] = s.finite;
  r["records"] = list;
  write_json(a.report, r);
  return s.finite ? kExitOk : kExitSolver;
}

int run_compare(const CompareArgs& a) {
  check_output_file(a.out, "--out");
  check_output_file(a.report, "--report");
  check_output_file(a.model_out, "--model-out");
  if (a.warmup < 0) throw InputError("--warmup must be >= 0");
  const bool fit_x0 = a.x0 == "fit" || a.warmup > 0;
  if (a.x0 == "model" && a.warmup > 0)
    throw InputError("--warmup fits x0 on the first rows: it cannot go with --x0 model (leave --x0 out)");
  if (!a.model_out.empty() && !fit_x0) throw InputError("--model-out writes the fitted x0: give --x0 fit or --warmup");
  const LpvModel<double> model = read_model_file<double>(a.model);
  if (!model.offset.basis.empty() && model.offset.values.empty())
    throw InputError(a.model + ": offset: the offset values are unknown; give \"values\" (or identify them first)");
  const std::vector<RecordOption> recs = pair_data_and_rows(a.data_paths, a.rows_texts, a.data_rows_order);
  if (recs.size() > 1) return compare_records(a, model, recs, fit_x0);
  const ComparedRecord c = compare_record(a, model, recs.front(), fit_x0);
  print_record(a, c, fit_x0);
  if (!a.out.empty()) {
    write_series(a.out, c);
    std::cout << "  series      " << a.out << " (row, and per output: measured, model, residual)\n";
  }
  if (!a.model_out.empty()) {
    write_model_file(a.model_out, c.model);
    std::cout << "  model       " << a.model_out << " (the model with the fitted x0)\n";
  }
  write_json(a.report, record_json(a, c, fit_x0));
  return c.s.finite ? kExitOk : kExitSolver;
}

}  // namespace

Runner add_compare_command(CLI::App& app) {
  auto a = std::make_shared<CompareArgs>();
  CLI::App* cmd =
      app.add_subcommand("compare", "A model's free-run output against measured data: RMS and fit % per output, CSV");
  add_data_and_rows(*cmd, a->data_paths, a->rows_texts, a->data_rows_order,
                    "data file; repeat for several records (each compared from its own x0, then pooled)",
                    "window of data rows B:E (0-based, E exclusive) of the --data before it; the state starts at B");
  cmd->add_option("--model", a->model, "model file")->required();
  cmd->add_option("--names", a->names, "column names for a headerless whitespace data file (every record)")->delimiter(',');
  cmd->add_option("--x0", a->x0, "initial state: model (as in the model file; default) or fit (least squares, multi-start)")
      ->check(CLI::IsMember({"model", "fit"}));
  cmd->add_option("--warmup", a->warmup,
                  "fit x0 on the first K compared rows and score only the rows after them (a benchmark protocol)");
  cmd->add_option("--out", a->out, "CSV: row, and per output the measured, model and residual series");
  cmd->add_option("--report", a->report, "JSON report");
  cmd->add_option("--model-out", a->model_out, "write the model with the fitted x0");
  return [cmd, a] { return cmd->parsed() ? run_compare(*a) : -1; };
}

}  // namespace lpvid::cli
