#pragma once
/// The options that shape random cases, shared by `lpvid generate random`
/// and `lpvid oracle`, and the writer of a case folder:
///   data.csv    u, y, ρ under the model's column names (exact decimal text)
///   model.json  the model under test (lpvid-model/1)
///   truth.json  the system that generated the data (Δ and noise aside)
///   task.json   the task (oracle/task.h)

#include <map>
#include <string>

#include <CLI/CLI.hpp>

#include "oracle/random_task.h"

namespace lpvid::cli {

struct RandomCaseFlags {
  bool siso = false, lti = false, static_blocks = false;
  int min_n = 20, max_n = 200;
  int leading_zeros = 0, max_delay = 0;
  std::string kinds = "min_dmax,min_delta,weighted,decide";  ///< identify on request (slower)
  double tolerance = 0.01;
};

/// Registers the flags on a subcommand.
void add_random_case_flags(CLI::App& cmd, RandomCaseFlags& f);

/// The generator's options from the flags (throws InputError for bad values).
RandomTaskOptions random_task_options(const RandomCaseFlags& f);

/// The four files of the case, by name, as bytes.
std::map<std::string, std::string> case_folder_files(const GeneratedCase& c);

/// Writes the four files of the case into `folder` (created if needed).
void write_case_folder(const std::string& folder, const GeneratedCase& c);

}  // namespace lpvid::cli
