#pragma once
/// The report of `lpvid diagnose` (docs/design.md §11.4: effects, before, after, plots):
/// printed in a readable form and written as JSON.

#include "diagnose/record_roles.h"
#include <string>
#include <vector>

#include "data/experiment.h"
#include "diagnose/diagnose.h"

namespace lpvid::cli {

struct DiagnoseReportInputs {
  std::string command_line_data, validation, plots_dir, model_out, solver;
  std::string estimation;  ///< file and rows of the fit role
  std::vector<std::string> test_sources;  ///< each test set's file, columns and rows (as result.tests)
  const DiagnoseResult* result = nullptr;  ///< everything computed; the rest here is what the files and rows are called
  const Experiment<double>* est = nullptr;  ///< the estimation record (plotted)
  const std::vector<Experiment<double>>* tests = nullptr;  ///< the test records (as result.tests), for their plots
  /// Fold mode: the residual analysis and plots are on the estimation
  /// record's last fold block (result->shown).
  bool folds = false;
  Eigen::Index fold_warmup = 0, test_warmup = 0;
  std::string estimation_rows_text;  ///< "file rows a:b" of the estimation record (fold mode)
  long file_row_offset = 0;
  std::vector<std::string> validation_outputs;  ///< the validation data's output column names (plot legends)
  /// The estimation records (two or more: the report's per-record lines and
  /// its `records` list; one: nothing added).
  std::vector<EstimationRecord> records;
};

/// Prints the report, makes the plots (if plots_dir is set) and writes the
/// JSON report (if report_path is set).
void print_and_write_diagnose_report(const DiagnoseReportInputs& in, const std::string& report_path);

}  // namespace lpvid::cli
