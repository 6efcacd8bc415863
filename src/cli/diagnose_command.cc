// lpvid diagnose: residual → missing effect → better model, before/after
// (docs/design.md §9, §11). See src/diagnose/effect_ranking.h for the method.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <tuple>

#include "core/progress_sink.h"
#include "core/file_io.h"
#include "cli/certificate_names.h"
#include "cli/commands.h"
#include "cli/diagnose_report.h"
#include "cli/refused_alias.h"
#include "cli/inputs.h"
#include "cli/report.h"
#include "core/input_error.h"
#include "core/parallel_for.h"
#include "data/csv_reader.h"
#include "data/fitting_precision.h"
#include "data/record_order.h"
#include "data/experiment_builder.h"
#include "diagnose/bound_windows.h"
#include "diagnose/diagnose.h"
#include "diagnose/fold_plan.h"
#include "diagnose/record_roles.h"
#include "model/model_file.h"
#include "solvers/external_solvers.h"
#include "solvers/solver_factory.h"
#include "cli/help_text.h"

namespace lpvid::cli {
namespace {

struct DiagnoseArgs {
  CommonOptions common;
  std::string validation_path;
  std::vector<std::string> validation_columns;  ///< replaces the model's u, y columns in order
  std::vector<std::string> validation_names;    ///< headerless validation file
  std::string validation_rows;
  double holdout = RolePlan{}.holdout;
  /// The test role: scored once, after the selection, never fitted or used to
  /// choose. Same column conventions as the validation options. Several test
  /// sets: --test given more than once (files with the same columns) or
  /// --test-columns given more than once (column sets of one file); each is
  /// scored and reported separately.
  std::vector<std::string> test_paths;
  std::vector<std::vector<std::string>> test_columns;
  std::vector<std::string> test_names;
  std::string test_rows;
  int max_effects = RankingOptions{}.max_effects;
  double min_gain = RankingOptions{}.min_gain;
  int degree = CandidateOptions{}.max_degree;
  int max_delay = CandidateOptions{}.max_delay;
  int init_samples = static_cast<int>(RankingOptions{}.init_samples);
  bool input_scheduling = true;
  int state_degree = CandidateOptions{}.state_degree;
  bool joint_dynamics = RankingOptions{}.joint_dynamics;
  std::vector<std::string> windows;
  long window_length = 0;
  int max_windows = 0;     ///< --max-windows: at most this many bound windows (0: all)
  bool lower_ends = false;  ///< --lower-ends: also certify each bound's lower end (dual certificates)
  std::string plots_dir;
  std::string model_out;
  int threads = static_cast<int>(default_thread_count());
  int folds = RankingOptions{}.folds;
  int warmup = -1;            ///< --warmup (test part and folds); -1: from --benchmark or the default
  std::string benchmark;      ///< --benchmark: sets the warm-up of docs/design.md §9.5
};

/// The test warm-up of docs/design.md §9.5 per benchmark (the nonlinear_benchmarks
/// loader, version 1.0.1): used for x0, left out of the RMS.
int benchmark_warmup(const std::string& name) {
  if (name == "cascaded-tanks" || name == "silverbox") return 50;
  if (name == "coupled-drives") return 10;
  throw InputError("--benchmark '" + name + "' is not known: cascaded-tanks, silverbox or coupled-drives (or give --warmup N)");
}

/// Column map of the validation data: est column name → validation name.
/// The records' roles as the options give them (diagnose/record_roles.h).
/// The estimation records of the command line: each --data with its --rows
/// (path, rows text), one entry per --data in order.
/// The samples of a record's window at the fits' precision, row by row (the
/// number of rows first): the key of the canonical record order. A cell that
/// is not a number counts as 0 here; reading the record names it later.
std::vector<double> record_key(const std::string& path, const std::string& rows,
                               const std::vector<std::string>& names) {
  const TextTable t = names.empty() ? read_table(path) : read_table(path, names);
  long b = 0, e = static_cast<long>(t.rows.size());
  if (!rows.empty()) std::tie(b, e) = parse_row_range(rows, "--rows");
  e = std::min<long>(e, static_cast<long>(t.rows.size()));
  std::vector<double> key{static_cast<double>(std::max<long>(e - b, 0))};
  for (long r = b; r < e; ++r)
    for (const std::string& cell : t.rows[static_cast<size_t>(r)]) {
      char* end = nullptr;
      const double v = std::strtod(cell.c_str(), &end);
      key.push_back(end != cell.c_str() && std::isfinite(v) ? at_fitting_precision(v) : 0.0);
    }
  return key;
}

std::vector<std::pair<std::string, std::string>> estimation_records(const DiagnoseArgs& a) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const RecordOption& r : data_records(a.common)) {
    if (!r.x0_text.empty())
      throw InputError("--x0 " + r.x0_text + ": diagnose identifies each record's initial state itself (no --x0)");
    out.emplace_back(r.path, r.rows_text);
  }
  if (out.size() < 2) return out;
  // several records in a canonical order: by their samples as the fits read
  // them (10 significant digits, data/fitting_precision.h), then the rows,
  // then the path. The order they are listed in then changes no fit and no
  // choice, and neither does a one-ulp change of a file (a hash of the bytes
  // would reorder the records on one ulp); the report lists them in this order
  std::vector<std::tuple<std::vector<double>, std::string, std::string>> keys;
  for (const auto& [path, rows] : out) keys.emplace_back(record_key(path, rows, a.common.names), rows, path);
  std::vector<std::pair<std::string, std::string>> sorted;
  for (size_t r : canonical_record_order(keys)) sorted.push_back(out[r]);
  return sorted;
}

RolePlan role_plan(const DiagnoseArgs& a, int warmup) {
  RolePlan plan;
  const auto records = estimation_records(a);
  plan.data_path = records[0].first;
  plan.names = a.common.names;
  if (!records[0].second.empty()) plan.rows = parse_row_range(records[0].second, "--rows");
  for (size_t k = 1; k < records.size(); ++k) {
    RecordSource s{records[k].first, a.common.names, {}, std::nullopt, records[k].second};
    if (!records[k].second.empty()) s.rows = parse_row_range(records[k].second, "--rows");
    plan.more_data.push_back(s);
  }
  const auto source = [](const std::string& path, const std::vector<std::string>& names,
                         const std::vector<std::string>& columns, const std::string& rows, const std::string& role) {
    RecordSource s{path, names, columns, std::nullopt, rows};
    if (!rows.empty()) s.rows = parse_row_range(rows, "--" + role + "-rows");
    return s;
  };
  const bool separate = !a.validation_path.empty() || !a.validation_columns.empty();
  plan.selection = separate ? SelectionRole::kSeparate : a.folds >= 2 ? SelectionRole::kFolds : SelectionRole::kHoldout;
  plan.folds = a.folds;
  plan.warmup = warmup;
  plan.holdout = a.holdout;
  if (separate) plan.separate = source(a.validation_path, a.validation_names, a.validation_columns, a.validation_rows, "validation");
  // the test sets: files x column sets, one of the two given once (or not at all)
  const size_t n_paths = a.test_paths.size(), n_cols = a.test_columns.size();
  if (n_paths > 1 && n_cols > 1)
    throw InputError("--test is given " + std::to_string(n_paths) + " times and --test-columns " +
                     std::to_string(n_cols) + " times: give several files with one column set, or one file with "
                     "several column sets");
  if (!a.test_rows.empty() && n_paths == 0 && n_cols == 0)
    throw InputError("--test-rows needs a test set (--test or --test-columns)");
  for (size_t t = 0; t < std::max(n_paths, n_cols); ++t)
    plan.tests.push_back(source(n_paths == 0 ? std::string() : a.test_paths[std::min(t, n_paths - 1)], a.test_names,
                                n_cols == 0 ? std::vector<std::string>() : a.test_columns[std::min(t, n_cols - 1)],
                                a.test_rows, "test"));
  return plan;
}

/// Progress lines (core/progress_sink.h: stderr) with the seconds since the start (none with --quiet).
std::function<void(const std::string&)> progress_printer(bool quiet) {
  const auto started = std::chrono::steady_clock::now();
  return [started, quiet](const std::string& status) {
    if (quiet) return;  // --quiet: no progress lines (errors and the report are still printed)
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    progress_printf("[diagnose %6.1f s] %s", s, status.c_str());
  };
}

/// Checks the numeric options; returns the warm-up (--warmup, --benchmark or --init-samples).
int checked_warmup(const DiagnoseArgs& a) {
  if (!(a.holdout > 0 && a.holdout < 1)) throw InputError("--holdout must be in (0, 1)");
  if (a.folds == 0 || a.folds < 1) throw InputError("--folds must be 1 (one held-out block) or at least 2");
  const int warmup = a.warmup > 0 ? a.warmup : (!a.benchmark.empty() ? benchmark_warmup(a.benchmark) : a.init_samples);
  if (!a.benchmark.empty() && a.warmup > 0 && a.warmup != benchmark_warmup(a.benchmark))
    throw InputError("--warmup " + std::to_string(a.warmup) + " contradicts --benchmark " + a.benchmark + " (" +
                     std::to_string(benchmark_warmup(a.benchmark)) + ")");
  if (!(a.min_gain >= 0 && a.min_gain < 1)) throw InputError("--min-gain must be in [0, 1)");
  return warmup;
}

/// The bound windows of the estimation data (--window ranges or --window-length tiles).
std::vector<std::pair<Eigen::Index, Eigen::Index>> bound_windows(const DiagnoseArgs& a, Eigen::Index rows) {
  std::vector<std::pair<Eigen::Index, Eigen::Index>> windows;
  for (const std::string& w : a.windows) {
    const auto [b, e] = parse_row_range(w, "--window");
    windows.emplace_back(b, e);
  }
  if (a.window_length > 0) {
    if (!windows.empty()) throw InputError("--window and --window-length exclude each other");
    windows = tile_windows(rows, a.window_length, std::min<Eigen::Index>(kDefaultMinLastWindow, a.window_length / 4));
  }
  return windows;
}

/// The library's options from the command line; certificates: the stem of the window certificates.
DiagnoseOptions diagnose_options(const DiagnoseArgs& a, const Inputs& in, const RoleRecords& roles, int warmup,
                                 bool by_folds, const std::string& certificates,
                                 const std::function<void(const std::string&)>& progress) {
  DiagnoseOptions o;
  o.ranking.max_effects = a.max_effects;
  o.ranking.min_gain = a.min_gain;
  o.ranking.init_samples = a.init_samples;
  o.ranking.candidates.max_degree = a.degree;
  o.ranking.candidates.max_delay = a.max_delay;
  o.ranking.candidates.state_degree = a.state_degree;
  o.ranking.joint_dynamics = a.joint_dynamics;
  o.ranking.folds = by_folds ? a.folds : 1;
  o.ranking.fold_warmup = warmup;
  o.ranking.threads = static_cast<unsigned>(a.threads);
  o.ranking.progress = progress;
  o.test_warmup = warmup;
  o.windows = bound_windows(a, roles.est.exp_q.n());
  o.max_windows = static_cast<size_t>(a.max_windows);
  o.certify = diagnose_policy(certify_options(a.common, in));
  o.certify.records.clear();  // the bytes est_q was parsed from, each record's rows as read (after any holdout)
  for (const EstimationRecord& r : roles.records) o.certify.records.push_back(r.data);
  o.certify.lower_end = a.lower_ends;
  o.on_bound = [certificates](WindowBounds& w, size_t window, size_t windows, bool after) {
    write_window_certificate(w, certificates, window, windows, after);
  };
  // --write-sdpa numbers the programs it writes in solve order: sequential then.
  o.threads = a.common.write_sdpa.empty() ? static_cast<unsigned>(a.threads) : 1u;
  o.make_solver = [solver = a.common.solver, sdpa = a.common.write_sdpa] { return make_solver_for_cli(solver, sdpa); };
  return o;
}

/// The report of the result: what the files, rows and roles are called.
DiagnoseReport diagnose_report(const DiagnoseArgs& a, const RoleRecords& roles, const DiagnoseResult& result,
                               const std::vector<Experiment<double>>& tests, bool by_folds, int warmup) {
  DiagnoseReport ri;
  ri.result = &result;
  // several records: the first in the canonical order (estimation_records)
  ri.command_line_data = roles.records.size() > 1 ? roles.records.front().data.file : a.common.data_path;
  ri.validation = roles.selection.text;
  ri.estimation = roles.estimation_text;
  for (const RoleRecord& t : roles.tests) {
    ri.test_sources.push_back(t.text);
    ri.test_columns.push_back(t.columns);
  }
  ri.est = &roles.est.exp_d;
  ri.tests = &tests;
  ri.folds = by_folds;
  ri.fold_warmup = warmup;
  ri.test_warmup = warmup;
  ri.file_row_offset = roles.records.front().data.row_begin;
  ri.validation_columns = roles.selection.columns;
  ri.records = roles.records;
  ri.plots_dir = a.plots_dir;
  ri.model_out = a.model_out;
  ri.solver = a.common.solver;
  ri.certificates_named = !named_certificate_path(a.common).empty();
  return ri;
}

int run_diagnose(DiagnoseArgs& a) {
  check_output_file(a.model_out, "model");
  check_output_directory(a.plots_dir, "plots");
  const auto progress = progress_printer(a.common.quiet);
  progress("reading the data and the model");
  const int warmup = checked_warmup(a);
  const Inputs in = load_inputs(a.common);
  const LpvModel<double> declared = a.input_scheduling ? with_input_scheduling(in.model_d) : in.model_d;
  // the records in their roles: estimation (fit), selection, tests
  const RolePlan plan = role_plan(a, warmup);
  const RoleRecords roles = load_role_records(plan, declared, in.model_d);
  const bool by_folds = plan.selection == SelectionRole::kFolds;
  std::vector<Experiment<double>> tests;
  for (const RoleRecord& t : roles.tests) tests.push_back(t.exp);
  const std::string certificates = named_certificate_path(a.common);  // "": no file
  const DiagnoseOptions o = diagnose_options(a, in, roles, warmup, by_folds, certificates, progress);
  auto solver = o.make_solver();
  const Experiment<double> no_selection;  // fold mode: the folds come from the estimation record
  progress("data read (" + std::to_string(roles.est.exp_d.n()) + " estimation rows); fitting the declared model" +
           (by_folds ? " on the whole record and on each fold's training rows" : ""));
  // the one library call: verified bounds before and after, on the bound windows of the estimation data
  // (its two views, each read from the text, copied side by side)
  DiagnoseResult result = diagnose(declared, roles.est,
                                   by_folds ? no_selection : roles.selection.exp, tests, o, *solver);
  write_diagnose_certificates(result, certificates);  // the Theorem 3.1 windows
  if (!a.model_out.empty()) write_model_file(a.model_out, result.after.front().model);
  // the renderers: figures first (the text and the JSON list them), then the text, then the JSON
  const DiagnoseReport report = diagnose_report(a, roles, result, tests, by_folds, warmup);
  const DiagnoseFigures figures = draw_diagnose_figures(report);
  print_diagnose_text(report, figures);
  write_diagnose_json(report, figures, a.common.report_path);
  return exit_code(result.outcome());
}


/// The records in their roles: validation (selection) and test options.
void add_diagnose_role_options(CLI::App& cmd, DiagnoseArgs& a) {
  auto* validation =
      cmd.add_option("--validation", a.validation_path, "validation data file (default: hold out the end of --data)");
  cmd.add_option("--validation-columns", a.validation_columns,
                 "validation column names replacing the model's u then y columns, e.g. uVal,yVal (same file if "
                 "--validation is not given)")
      ->delimiter(',');
  cmd.add_option("--validation-names", a.validation_names, "column names of a headerless validation file")
      ->delimiter(',')
      ->needs(validation);
  cmd.add_option("--validation-rows", a.validation_rows, "rows B:E of the validation data");
  cmd.add_option("--folds", a.folds,
                 "blocked folds of the estimation record that rank and accept the effects when no --validation is "
                 "given (default 4: each candidate is fitted on 3 blocks and scored on the 4th, in turn); 1: hold out "
                 "the last --holdout share once instead")
      ->check(CLI::Range(1, 20));
  cmd.add_option("--holdout", a.holdout,
                 "with --folds 1: fraction of --data held out for validation when none is given (" +
                     double_to_text(a.holdout) + ")")
      ->excludes(validation);
  cmd.add_option("--warmup", a.warmup,
                 "samples at the start of the test part (and of each fold) used for the initial state and left out "
                 "of the RMS and fit % (default: --init-samples, 5)")
      ->check(CLI::Range(1, 100000));
  cmd.add_option("--benchmark", a.benchmark,
                 "the benchmark's warm-up (the nonlinear_benchmarks loader since 1.0.1): cascaded-tanks 50, silverbox 50, "
                 "coupled-drives 10");
  auto* test = cmd.add_option("--test", a.test_paths,
                 "test data file, scored once after the selection and never used to fit or choose (default: --data "
                 "when --test-columns is given); may be given more than once, each file scored separately")
      ->take_all();
  cmd.add_option("--test-columns", a.test_columns,
                 "test column names replacing the model's u then y columns, e.g. uVal,yVal; may be given more than "
                 "once (several column sets of one file, each scored separately)")
      ->delimiter(',');
  cmd.add_option("--test-names", a.test_names, "column names of a headerless test file")->delimiter(',')->needs(test);
  cmd.add_option("--test-rows", a.test_rows, "rows B:E of the test data");
}

/// The candidate effects and their selection.
void add_diagnose_search_options(CLI::App& cmd, DiagnoseArgs& a) {
  cmd.add_option("--max-effects", a.max_effects, with_default("effects to add at most", a.max_effects))->check(CLI::Range(0, 20));
  cmd.add_option("--min-gain", a.min_gain, with_default("relative validation-RMS reduction an effect must reach", a.min_gain));
  cmd.add_option("--degree", a.degree, with_default("largest degree of basis-term monomials", a.degree))->check(CLI::Range(1, 6));
  cmd.add_option("--max-input-delay", a.max_delay, with_default("largest input delay tried", a.max_delay))->check(CLI::Range(0, 100));
  cmd.add_option("--state-degree", a.state_degree,
                 "candidates x1^1..x1^D in A, scheduled on the model's own state (model column \"@x1\"; 0: none; default 3)")
      ->check(CLI::Range(0, 6));
  cmd.add_flag("!--fixed-dynamics", a.joint_dynamics,
               "keep A, B as declared in every candidate fit (default: each candidate is also fitted with A, B "
               "re-fitted jointly, and the selection rows pick the better of the two)");
  cmd.add_option("--init-samples", a.init_samples,
                 "selection samples used to fit the initial state, every sample still scored (default " +
                     std::to_string(a.init_samples) + "); unlike "
                 "--warmup, they are not left out of the RMS")
      ->check(CLI::Range(1, 100000));
  cmd.add_flag("!--no-input-scheduling", a.input_scheduling,
               "do not try basis terms scheduled on the measured inputs (rho = u)");
  add_renamed_option(cmd, "--max-delay", "--max-input-delay",
                     "generate and oracle's --max-delay is the number of Delta's zero taps");
  // Given after the command, the input limit --max-degree would silently be taken for --degree's meaning.
  add_refused_option(cmd, "--max-degree",
                     "is the input limit on a model's polynomial degree, not the candidates' degree: give it before the "
                     "command (lpvid --max-degree N diagnose ...), or --degree D for the candidate monomials");
}

/// The bound windows, the solver's parallelism and the outputs.
void add_diagnose_window_options(CLI::App& cmd, DiagnoseArgs& a) {
  cmd.add_option("--window", a.windows,
                 "estimation rows B:E on which the bounds are certified, several separated by commas "
                 "(default: the whole estimation record in windows of 200 rows, a last one under 50 rows merged)")
      ->delimiter(',');
  cmd.add_option("--window-length", a.window_length,
                 "certify consecutive windows of this length covering the whole estimation record (a last one "
                 "shorter than min(50, L/4) rows merged)")
      ->check(CLI::Range(10L, 100000L));
  cmd.add_option("--max-windows", a.max_windows,
                 "certify at most N bound windows, spread evenly over the estimation record (default: all)")
      ->check(CLI::Range(1, 1000000));
  cmd.add_flag("--lower-ends", a.lower_ends,
               "also certify the lower end of every bound (a dual certificate per window); the report states the "
               "upper ends, which need none");
  cmd.add_option("--threads", a.threads,
                 "bound windows certified at once (default: the number of hardware threads); results do not depend "
                 "on it")
      ->check(CLI::Range(1, 1024));
  cmd.add_option("--plots", a.plots_dir, "directory for the PNG plots and their CSV data");
  cmd.add_option("--model-out", a.model_out, "write the model after diagnosis (exact, as certified)");
}

/// Options that would be ignored are refused instead (when the parse ends).
void refuse_ignored_diagnose_options(const CLI::App& cmd, const DiagnoseArgs& a) {
  if (cmd.count("--test-rows") > 0 && cmd.count("--test") == 0 && cmd.count("--test-columns") == 0)
    throw CLI::ValidationError("--test-rows", "needs a test set (--test or --test-columns)");
  if (cmd.count("--holdout") > 0 && a.folds != 1)
    throw CLI::ValidationError("--holdout", "is used with --folds 1 only (the default folds score every block in turn)");
  if (cmd.count("--validation-rows") > 0 && a.validation_path.empty() && a.validation_columns.empty())
    throw CLI::ValidationError("--validation-rows", "needs --validation or --validation-columns");
}

}  // namespace

Runner add_diagnose_command(CLI::App& app) {
  auto a = std::make_shared<DiagnoseArgs>();
  CLI::App* cmd = app.add_subcommand(
      "diagnose", "Residual -> missing effect -> re-fitted model, with before/after RMS and verified bounds");
  add_common_options(*cmd, a->common, true);
  add_diagnose_role_options(*cmd, *a);
  add_diagnose_search_options(*cmd, *a);
  add_diagnose_window_options(*cmd, *a);
  cmd->callback([cmd, a] { refuse_ignored_diagnose_options(*cmd, *a); });
  return [cmd, a] { return cmd->parsed() ? run_diagnose(*a) : -1; };
}

}  // namespace lpvid::cli
