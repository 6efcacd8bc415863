#pragma once
/// `--sample-time S` and `--unit COLUMN=UNIT` for the commands that write a
/// model file from scratch (data/signal_info.h: descriptive only).

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "data/column_map.h"
#include "data/signal_info.h"

namespace lpvid::cli {

struct SignalInfoArgs {
  double sample_time = 0.0;
  std::vector<std::string> units;  ///< COLUMN=UNIT
};

void add_signal_info_options(CLI::App& app, SignalInfoArgs& a);

/// The SignalInfo the options describe, over `base` (options win). Throws
/// InputError for a non-positive sample time, a malformed --unit or a column
/// that `columns` does not hold.
SignalInfo signal_info_of(const SignalInfoArgs& a, const ColumnMap& columns, SignalInfo base = {});

}  // namespace lpvid::cli
