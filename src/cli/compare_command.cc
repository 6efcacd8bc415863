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
  std::string data, model, out, report, model_out, rows, x0;  ///< x0: "" (not given), model or fit
  std::vector<std::string> names;
  long warmup = 0;
};

std::string percent_text(double x) {
  if (!std::isfinite(x)) return x > 0 ? "inf" : "-inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  return buf;
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
  LpvModel<double> model = read_model_file<double>(a.model);
  if (!model.offset.basis.empty() && model.offset.values.empty())
    throw InputError(a.model + ": offset: the offset values are unknown; give \"values\" (or identify them first)");
  const TextTable table = a.names.empty() ? read_table(a.data) : read_table(a.data, a.names);
  Experiment<double> exp = make_experiment<double>(table, model.columns);
  long first = 0;
  if (!a.rows.empty()) {
    const auto [b, e] = parse_row_range(a.rows, "--rows");
    if (e > exp.n()) throw InputError("--rows " + a.rows + ": the data has only " + std::to_string(exp.n()) + " rows");
    exp = select_rows(exp, b, e);
    first = b;
  }
  if (a.warmup >= exp.n())
    throw InputError("--warmup " + std::to_string(a.warmup) + " leaves nothing to score in " + std::to_string(exp.n()) +
                     " rows");
  // x0: the model's, or fitted (multi-start, fit/output_error_fit.h) on the
  // warm-up rows, or on all compared rows without --warmup
  if (fit_x0) {
    const FitResult f = fit_initial_state(model, exp, a.warmup > 0 ? a.warmup : exp.n());
    if (!f.finite) throw InputError(a.model + ": no initial state keeps the simulation finite on these rows");
    model.x0 = f.model.x0;
  }
  const Simulation<double> sim = simulate(model, exp);
  const Eigen::Index skip = a.warmup;
  const Eigen::Index scored = exp.n() - skip;
  const OutputScores s = score_outputs(exp.y.bottomRows(scored), sim.output.bottomRows(scored));

  std::cout << "lpvid compare: " << a.model << " on " << a.data << " rows " << first + skip << ":" << first + exp.n()
            << " (" << scored << " samples";
  if (skip > 0) std::cout << "; x0 fitted on the " << skip << " rows before them";
  else std::cout << (fit_x0 ? "; x0 fitted on these rows" : "; x0 as in the model file");
  std::cout << ", free run)\n";
  std::printf("  %-16s %14s %10s\n", "output", "RMS(y - yhat)", "fit %");
  for (size_t i = 0; i < s.rms.size(); ++i)
    std::printf("  %-16s %14.6g %10s\n", model.columns.y[i].c_str(), s.rms[i], percent_text(s.fit_percent[i]).c_str());
  if (s.rms.size() > 1) std::printf("  %-16s %14.6g %10s\n", "all outputs", s.rms_all, percent_text(s.fit_percent_all).c_str());
  std::cout << "  (fit % = 100*(1 - ||y - yhat|| / ||y - mean(y)||): 100 perfect, 0 no better than the mean)\n";
  if (fit_x0) {
    std::cout << "  x0          ";
    for (Eigen::Index i = 0; i < model.x0.size(); ++i) std::cout << " " << double_to_text(model.x0(i));
    std::cout << "\n";
  }

  if (!a.out.empty()) {
    std::vector<TextColumn> cols;
    std::vector<std::string> row;
    for (Eigen::Index k = 0; k < exp.n(); ++k) row.push_back(std::to_string(first + k));
    cols.push_back({"row", row});
    const Mat<double> resid = exp.y - sim.output;
    for (Eigen::Index i = 0; i < exp.y.cols(); ++i) {
      const std::string& name = model.columns.y[static_cast<size_t>(i)];
      cols.push_back({name, column_text(exp.y, i)});
      cols.push_back({name + "_model", column_text(sim.output, i)});
      cols.push_back({name + "_residual", column_text(resid, i)});
    }
    write_csv(a.out, cols);
    std::cout << "  series      " << a.out << " (row, and per output: measured, model, residual)\n";
  }
  if (!a.model_out.empty()) {
    write_model_file(a.model_out, model);
    std::cout << "  model       " << a.model_out << " (the model with the fitted x0)\n";
  }
  nlohmann::ordered_json r;
  r["data"] = a.data;
  r["model"] = a.model;
  r["rows"] = {first + skip, first + exp.n()};
  r["warmup_rows"] = skip;
  r["x0"] = fit_x0 ? (skip > 0 ? "fitted on the warm-up rows" : "fitted on the compared rows") : "model file";
  r["x0_values"] = std::vector<double>(model.x0.data(), model.x0.data() + model.x0.size());
  nlohmann::ordered_json outs = nlohmann::ordered_json::array();
  for (size_t i = 0; i < s.rms.size(); ++i)
    outs.push_back({{"name", model.columns.y[i]}, {"rms", s.rms[i]}, {"fit_percent", s.fit_percent[i]}});
  r["outputs"] = outs;
  r["rms"] = s.rms_all;
  r["fit_percent"] = s.fit_percent_all;
  r["finite"] = s.finite;
  write_json(a.report, r);
  return s.finite ? kExitOk : kExitSolver;
}

}  // namespace

Runner add_compare_command(CLI::App& app) {
  auto a = std::make_shared<CompareArgs>();
  CLI::App* cmd =
      app.add_subcommand("compare", "A model's free-run output against measured data: RMS and fit % per output, CSV");
  cmd->add_option("--data", a->data, "data file")->required();
  cmd->add_option("--model", a->model, "model file")->required();
  cmd->add_option("--names", a->names, "column names for a headerless whitespace data file")->delimiter(',');
  cmd->add_option("--rows", a->rows, "window of data rows B:E (0-based, E exclusive); the state starts at B");
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
