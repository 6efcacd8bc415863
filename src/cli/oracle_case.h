#pragma once
/// One case of `lpvid oracle`: its folder (data.csv, model.json, task.json),
/// the outside command run on it, lpvid's own certification of the same
/// task, the exact check of the answer's witness, and the verdict
/// (oracle/judge.h) with its evidence re-checked from the file.

#include <string>

#include "oracle/oracle_report.h"

namespace lpvid::cli {

struct OracleCaseOptions {
  std::string command;          ///< the outside command template (oracle/outside_command.h)
  double case_timeout = 120;    ///< seconds for the outside command
  std::string solver = "csdp";  ///< lpvid's own solver
};

/// Runs and judges the case in `folder` (which holds task.json). Throws
/// InputError when the case itself is unreadable (a bad case is not an
/// outside error).
CaseReport run_oracle_case(const std::string& folder, const OracleCaseOptions& options);

}  // namespace lpvid::cli
