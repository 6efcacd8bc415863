#pragma once
/// The report of `lpvid diagnose` (effects, before, after, plots): one typed
/// value, DiagnoseReport, made from the library's DiagnoseResult and the
/// names of the files and rows, and three renderers of it, each in its own
/// file: the readable text on stdout (diagnose_text.cc), the JSON report
/// (diagnose_json.cc) and the figures (diagnose_figures.cc). The figures are
/// drawn first because the text and the JSON list the files written.

#include <string>
#include <vector>

#include "data/experiment.h"
#include "diagnose/diagnose.h"
#include "diagnose/record_roles.h"
#include "fit/output_score.h"
#include "plot/gnuplot.h"

namespace lpvid::cli {

struct DiagnoseReport {
  std::string command_line_data, validation, plots_dir, model_out, solver;
  std::string estimation;  ///< file and rows of the fit role
  std::vector<std::string> test_sources;  ///< each test set's file, columns and rows (as result.tests)
  std::vector<ColumnMap> test_columns;    ///< each test set's column names (as result.tests)
  const DiagnoseResult* result = nullptr;  ///< everything computed; the rest here is what the files and rows are called
  const Experiment<double>* est = nullptr;  ///< the estimation record (plotted)
  const std::vector<Experiment<double>>* tests = nullptr;  ///< the test records (as result.tests), for their plots
  /// Fold mode: the residual analysis and plots are on the estimation
  /// record's last fold block (result->shown).
  bool folds = false;
  bool certificates_named = true;  ///< false: the user named no certificate or report file, none was written
  Eigen::Index fold_warmup = 0, test_warmup = 0;
  std::string estimation_rows_text;  ///< "file rows a:b" of the estimation record (fold mode)
  long file_row_offset = 0;
  ColumnMap validation_columns;  ///< the validation data's column names (empty: rows of --data, named by the model)
  /// The estimation records (two or more: the report's per-record lines and
  /// its `records` list with result->estimation_records; one: nothing added).
  std::vector<EstimationRecord> records;
};

/// How a test set is scored: "free run; x0 from the first N samples (warm-up), …".
std::string test_rule_text(const FreeRunScore& score);

/// A signal's column name in a record named by `names`: u1, y1, rho1, …
/// when its role's list does not name it.
std::string signal_column(const ColumnMap& names, SignalRole role, Eigen::Index column);

/// "input", "output", "scheduling".
const char* to_string(SignalRole role);

/// One signal of a test record against the estimation record, in words:
/// "yVal 2.164 to 10 (estimation yEst 2.912 to 10): 77 of 1024 samples
/// outside (7.52 %, 77 below), the farthest 0.105 of the estimation range's
/// width beyond it", or "…: inside".
std::string excursion_text(const SignalExcursion& e, const ColumnMap& test_names, const ColumnMap& estimation_names);

/// Several estimation records: where each fold's held-out block is in its
/// file (one per RankingResult::fold_blocks; a block never crosses a seam).
/// One record: empty (the blocks are file_row_offset + their rows).
std::vector<DataReference> fold_files(const DiagnoseReport& in);

/// One figure written (or not) and where the text lists it.
struct DrawnFigure {
  std::string path;
  PlotOutcome outcome;
  bool test_record = false;  ///< listed under "plots (test records …)"
};

struct DiagnoseFigures {
  bool drawn = false;          ///< --plots was given and the shown residual is finite
  bool test_heading = false;   ///< the test-record figures were attempted
  std::vector<DrawnFigure> list;
};

/// Draws the figures into report.plots_dir (nothing when it is empty).
DiagnoseFigures draw_diagnose_figures(const DiagnoseReport& report);

/// Prints the readable report on stdout.
void print_diagnose_text(const DiagnoseReport& report, const DiagnoseFigures& figures);

/// Writes the JSON report (nothing when report_path is empty).
void write_diagnose_json(const DiagnoseReport& report, const DiagnoseFigures& figures, const std::string& report_path);

}  // namespace lpvid::cli
