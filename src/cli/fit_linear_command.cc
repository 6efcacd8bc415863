// lpvid fit-linear: the linear starting model of diagnose (docs/design.md §9): ARX,
// then output-error refinement (fit/linear_fit.h), written as an
// lpvid-model/1 file with "scheduling": [].
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "core/file_io.h"
#include "cli/commands.h"
#include "cli/refused_alias.h"
#include "cli/signal_info_options.h"
#include "cli/inputs.h"
#include "cli/report.h"
#include "core/input_error.h"
#include "data/fitting_precision.h"
#include "data/csv_reader.h"
#include "data/experiment_builder.h"
#include "fit/linear_fit.h"
#include "fit/output_error_fit.h"
#include "model/model_file.h"
#include "model/simulate.h"
#include "core/rms.h"
#include "cli/help_text.h"

namespace lpvid::cli {
namespace {

struct FitLinearArgs {
  std::vector<std::string> data, rows;  ///< --data (repeatable: several records), --rows (one per --data)
  std::string out, report, order = "auto";
  std::vector<std::string> names, u{"u"}, y{"y"};
  std::string val_data, val_rows;
  std::vector<std::string> val_names, val_columns;  ///< --validation-columns: inputs then the output
  int max_order = 5;       ///< --max-order for --order auto
  int init_samples = static_cast<int>(kValidationInitSamples);  ///< --init-samples: x0 of validation data from its first samples (benchmark rule)
  bool offset = false;     ///< --offset: fit a constant output offset
  SignalInfoArgs signal_info;  ///< --sample-time, --unit
};

/// Reads a data file (optionally headerless with `names`) and a row window,
/// at the fits' precision (data/fitting_precision.h: the order chosen and the
/// model fitted do not move when the file's numbers move by one ulp).
Experiment<double> load(const std::string& path, const std::vector<std::string>& names, const std::string& rows,
                        const ColumnMap& cols) {
  const TextTable table = names.empty() ? read_table(path) : read_table(path, names);
  Experiment<double> e = at_fitting_precision(make_experiment<double>(table, cols));
  if (rows.empty()) return e;
  const auto [b, end] = parse_row_range(rows, "--rows");
  if (end > e.n()) throw InputError("--rows " + rows + ": " + path + " has only " + std::to_string(e.n()) + " rows");
  return select_rows(e, b, end);
}

int parse_order(const std::string& text) {
  if (text == "auto") return 0;
  try {
    size_t used = 0;
    const int n = std::stoi(text, &used);
    if (used == text.size()) return n < 1 ? -1 : n;
  } catch (const std::exception&) {
  }
  throw InputError("--order: expected a positive integer or 'auto', got '" + text + "'");
}

/// The validation record of the options, if any: --validation (default the
/// estimation file) with --validation-rows and --validation-columns.
std::optional<Experiment<double>> load_validation(const FitLinearArgs& a) {
  if (a.val_data.empty() && a.val_rows.empty() && a.val_columns.empty()) return std::nullopt;
  ColumnMap vcols{a.u, a.y, {}};
  if (!a.val_columns.empty()) {  // checked at parsing: one name per --u column, then one per --y column
    vcols.u.assign(a.val_columns.begin(), a.val_columns.begin() + static_cast<std::ptrdiff_t>(a.u.size()));
    vcols.y.assign(a.val_columns.begin() + static_cast<std::ptrdiff_t>(a.u.size()), a.val_columns.end());
  }
  if (a.val_data.empty() && a.data.size() > 1)
    throw InputError("--validation-rows/--validation-columns with several --data: name the validation file with --validation");
  const std::string& path = a.val_data.empty() ? a.data.front() : a.val_data;
  const auto& names = a.val_data.empty() ? a.names : a.val_names;
  return load(path, names, a.val_rows, vcols);
}

/// --order auto: the order chosen on selection data, not on the rows it was
/// fitted on (a higher order always fits those better): the validation data
/// given (the benchmark's held-out estimation rows in the demo), else the
/// last third of the estimation rows, fitted on the first two thirds. Never
/// on test data: fit-linear has no test role. Prints the scores, fills the report.
OrderChoice choose_order_printed(const FitLinearArgs& a, const Experiment<double>& est,
                                 const std::optional<Experiment<double>>& val, const ColumnMap& cols,
                                 nlohmann::ordered_json& report) {
  // without validation data: the first two thirds of each record fit, the last third scores
  std::vector<Experiment<double>> fit_parts, held_parts;
  std::string cuts;
  Eigen::Index first = 0;
  for (const Eigen::Index len : est.record_lengths()) {
    const Eigen::Index cut = len * 2 / 3;
    fit_parts.push_back(select_rows(est, first, first + cut));
    held_parts.push_back(select_rows(est, first + cut, first + len));
    cuts += (cuts.empty() ? "" : ", ") + std::to_string(cut) + ":" + std::to_string(len);
    first += len;
  }
  const Experiment<double> fit_rows = val ? est : stack_records(fit_parts);
  const Experiment<double> held_out = val ? *val : stack_records(held_parts);
  const OrderChoice choice = choose_order(fit_rows, held_out, cols, a.max_order, a.offset, a.init_samples);
  const bool several = est.record_count() > 1;
  const std::string scored_on = val ? "the validation (selection) data"
                                    : (several ? "the last third of each record, rows " : "estimation rows ") + cuts;
  std::cout << "  order  rms_estimation  rms_held_out  (fit on "
            << (val ? "all estimation rows" : several ? "the first two thirds of each record" : "estimation rows 0:" + std::to_string(est.n() * 2 / 3))
            << ", free run scored on " << scored_on << (several ? ", each record from its own x0" : "")
            << "; order n is also started from order n-1's fit)\n";
  double best = choice.scores.front().rms_validation;
  for (const OrderScore& s : choice.scores) best = std::min(best, s.rms_validation);
  for (const OrderScore& s : choice.scores) {
    std::cout << "  " << std::setw(5) << s.order << "  " << std::setw(14) << s.rms_estimation << "  "
              << std::setw(12) << s.rms_validation << (s.order == choice.order ? "  <- chosen" : "") << "\n";
    report["order_scores"].push_back(
        {{"order", s.order}, {"rms_estimation", s.rms_estimation}, {"rms_held_out", s.rms_validation}});
  }
  std::ostringstream rule;
  rule << "the smallest order whose held-out free-run RMS is within " << kOrderSlack * 100 << "% of the best ("
       << std::setprecision(4) << best << ")";
  const std::string why = rule.str();
  std::cout << "  chosen: order " << choice.order << ", " << why << "\n";
  report["order_rule"] = why;
  report["order_scored_on"] = scored_on;
  return choice;
}

/// Prints and reports the final fit, its validation score and the model file.
void report_fit(const FitLinearArgs& a, const LinearFit& fit, int order, const std::optional<Experiment<double>>& val,
                const SignalInfo& signal_info, nlohmann::ordered_json& report) {
  std::cout << std::setprecision(6) << "order " << order << "\nrms_estimation " << fit.rms_estimation
            << "  (ARX start " << fit.rms_arx << ", " << fit.iterations << " LM steps, spectral radius "
            << fit.spectral_radius << ")\n";
  report["order"] = order;
  report["offset"] = a.offset;
  report["rms_estimation"] = fit.rms_estimation;
  report["rms_arx"] = fit.rms_arx;
  report["spectral_radius"] = fit.spectral_radius;
  report["iterations"] = fit.iterations;
  if (val) {
    const double r = validation_rms(fit.model, *val, a.init_samples);
    std::cout << "rms_validation " << r << "  (free run, x0 from the first " << a.init_samples << " samples)\n";
    report["rms_validation"] = r;
    report["init_samples"] = a.init_samples;
  }
  if (!a.out.empty()) {
    LpvModel<double> model = fit.model;
    model.signal_info = signal_info;
    write_model_file(a.out, model);
    std::cout << "model " << a.out << "\n";
    report["model"] = a.out;
  }
}

/// Several records: each record's estimation RMS from its own fitted x0
/// (the model file keeps the first record's).
void report_records(const FitLinearArgs& a, const LinearFit& fit, const Experiment<double>& est,
                    nlohmann::ordered_json& report) {
  if (est.record_count() < 2) return;
  Experiment<double> with_x0 = est;
  with_x0.record_x0 = fit.record_x0;
  const Mat<double> residual = est.y - simulate_output(fit.model, with_x0);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  Eigen::Index first = 0;
  const std::vector<Eigen::Index> lengths = est.record_lengths();
  for (size_t r = 0; r < lengths.size(); ++r) {
    const double rr = rms(Vec<double>(residual.middleRows(first, lengths[r]).reshaped()));  // every output
    std::cout << "  record " << r + 1 << " (" << a.data[r] << "): rms_estimation " << rr << " from its own x0\n";
    nlohmann::ordered_json x0 = nlohmann::ordered_json::array();
    for (Eigen::Index i = 0; i < fit.record_x0[r].size(); ++i) x0.push_back(fit.record_x0[r](i));
    list.push_back({{"file", a.data[r]},
                    {"rows", a.rows.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(a.rows[r])},
                    {"samples", lengths[r]},
                    {"rms_estimation", rr},
                    {"x0", x0}});
    first += lengths[r];
  }
  report["records"] = list;
  report["model_x0"] = "the first record's (the model file holds one x0)";
}

int run_fit_linear(const FitLinearArgs& a) {
  check_output_file(a.out, "model");
  int order = parse_order(a.order);
  if (order < 0) throw InputError("--order: must be >= 1 (or 'auto'), got '" + a.order + "'");
  const ColumnMap cols{a.u, a.y, {}};
  const SignalInfo signal_info = signal_info_of(a.signal_info, cols);  // checked before any work
  if (!a.rows.empty() && a.rows.size() != a.data.size())
    throw InputError("--rows: give one per --data (" + std::to_string(a.data.size()) + " here), got " +
                     std::to_string(a.rows.size()));
  std::vector<Experiment<double>> records;
  std::cout << "lpvid fit-linear\n";
  for (size_t r = 0; r < a.data.size(); ++r) {
    const std::string rows = a.rows.empty() ? "" : a.rows[r];
    records.push_back(load(a.data[r], a.names, rows, cols));
    std::cout << "  data        " << a.data[r] << (rows.empty() ? "" : " rows " + rows) << "  (u: " << a.u.front()
              << (a.u.size() > 1 ? ",…" : "") << ", y: " << a.y.front() << ", " << records.back().n() << " samples"
              << (a.data.size() > 1 ? "; record " + std::to_string(r + 1) + " of " + std::to_string(a.data.size()) +
                                          ", its own x0"
                                    : "")
              << ")\n";
  }
  const Experiment<double> est = stack_records(records);
  const std::optional<Experiment<double>> val = load_validation(a);
  std::cout << "  order       " << a.order << "\n  offset      " << (a.offset ? "yes" : "no")
            << "\n  init        x0 of validation data from its first " << a.init_samples << " samples\n";

  nlohmann::ordered_json report;
  report["command"] = "fit-linear";
  std::optional<LinearFit> chosen;
  if (order == 0) {
    const OrderChoice choice = choose_order_printed(a, est, val, cols, report);
    order = choice.order;
    chosen = choice.fit;
  }
  // The scored fit when it was fitted on all estimation rows; else a fit on
  // all of them, also started from the scored fit's denominator.
  LinearFitOptions fo{order, a.offset, {}, {}};
  if (chosen) fo.nested_denominator = chosen->form.a;
  const LinearFit fit = chosen && val ? *chosen : fit_linear(est, cols, fo);
  report_fit(a, fit, order, val, signal_info, report);
  report_records(a, fit, est, report);
  write_json(a.report, report);
  return kExitOk;
}

/// Options this command would ignore, refused when the parse ends.
void refuse_ignored_fit_options(const CLI::App& cmd, const FitLinearArgs& a) {
  if (cmd.count("--max-order") > 0 && a.order != "auto")
    throw CLI::ValidationError("--max-order", "is the largest order tried by --order auto; with --order " + a.order +
                                                  " it would be ignored (leave it out, or give --order auto)");
  const size_t want = a.u.size() + a.y.size();
  if (!a.val_columns.empty() && a.val_columns.size() != want)
    throw CLI::ValidationError(
        "--validation-columns",
        "names the validation record's input column(s) then its output column(s), one per --u and --y column (" +
            std::to_string(want) + " here), got " + std::to_string(a.val_columns.size()));
}

}  // namespace

Runner add_fit_linear_command(CLI::App& app) {
  auto a = std::make_shared<FitLinearArgs>();
  CLI::App* cmd = app.add_subcommand("fit-linear", "Fit an LTI starting model (ARX + output error) to data");
  cmd->add_option("--data", a->data,
                  "estimation data file; repeat for several records of one system (one model, each record its own x0, "
                  "the order chosen on all of them)")
      ->required();
  cmd->add_option("--names", a->names, "column names for a headerless data file")->delimiter(',');
  cmd->add_option("--rows", a->rows, "window of estimation rows B:E (0-based, E exclusive); one per --data");
  cmd->add_option("--u", a->u, "input column(s) (default u)")->delimiter(',');
  cmd->add_option("--y", a->y, "output column (default y)")->delimiter(',');
  cmd->add_option("--order", a->order, "model order N >= 1, or auto (default)");
  cmd->add_option("--max-order", a->max_order, with_default("largest order tried by --order auto", a->max_order));
  cmd->add_flag("--offset", a->offset, "fit a constant output offset (model \"offset\" with basis 1)");
  cmd->add_option("--model-out", a->out, "model file to write (lpvid-model/1)");
  cmd->add_option("--report", a->report, "JSON report");
  add_signal_info_options(*cmd, a->signal_info);
  cmd->add_option("--validation", a->val_data, "validation data file (default: the estimation file)");
  cmd->add_option("--validation-names", a->val_names, "column names for a headerless validation file")
      ->delimiter(',');
  cmd->add_option("--validation-rows", a->val_rows, "window of validation rows B:E");
  cmd->add_option("--validation-columns", a->val_columns,
                  "validation column names replacing --u then --y, e.g. uVal,yVal (default: --u, --y; the estimation "
                  "file if --validation is not given)")
      ->delimiter(',');
  cmd->add_option("--init-samples", a->init_samples,
                  "validation x0 fitted on this many first samples, every sample still scored (default 5, the benchmark "
                  "rule; 0: x0 = 0); unlike a --warmup, they are not left out of the RMS")
      ->check(CLI::Range(0, 100000));
  add_renamed_option(*cmd, "--out", "--model-out", "--out is a data CSV in compare, simulate and generate");
  add_renamed_option(*cmd, "--validation-data", "--validation", "one name, as in diagnose");
  for (const char* half : {"--validation-u", "--validation-y"})
    add_renamed_option(*cmd, half, "--validation-columns U...,Y", "inputs then output in one option, as in diagnose");
  cmd->callback([cmd, a] { refuse_ignored_fit_options(*cmd, *a); });
  return [cmd, a] { return cmd->parsed() ? run_fit_linear(*a) : -1; };
}

}  // namespace lpvid::cli
