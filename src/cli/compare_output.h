#pragma once
/// What `lpvid compare` writes for one record: the series CSV (row, time_s
/// when the sample time is known, scored flag, per output the measured
/// series and each model's output and residual) and the figure (measured
/// output and each model's output, one colour per model, the warm-up rows
/// drawn apart).

#include <string>
#include <vector>

#include "core/scalar.h"
#include "data/signal_info.h"

namespace lpvid::cli {

/// One model's output on the record (n × ny) and the name it goes by.
struct ComparedSeries {
  std::string name;  ///< the model file's stem, unique among the models
  Mat<double> yhat;
};

/// The record: its file rows (first = the file row of row 0), the warm-up
/// rows (not scored), the measured outputs and their data column names.
struct ComparedRows {
  long first = 0;
  long warmup = 0;
  Mat<double> y;
  std::vector<std::string> outputs;
  SignalInfo info;
};

/// Writes the CSV. One model: columns <out>_model and <out>_residual (as
/// before several models); several: <name>.yhat.<out> and <name>.residual.<out>.
void write_compare_series(const std::string& path, const ComparedRows& r, const std::vector<ComparedSeries>& models);

/// Draws the figure with gnuplot (a missing gnuplot is not an error): the
/// line printed, "" when no path was asked.
std::string plot_compare(const std::string& path, const ComparedRows& r, const std::vector<ComparedSeries>& models,
                         const std::string& title);

/// Stems of the model paths, made unique ("m", "m_2", ...).
std::vector<std::string> model_names(const std::vector<std::string>& paths);

}  // namespace lpvid::cli
