#pragma once
/// One case of `lpvid oracle`: lpvid's own copy of its inputs, the outside
/// command run on a fresh copy, lpvid's own certification of the same task
/// (an identify task: its reference, oracle/reference.h), the exact check of
/// the answer's witness (oracle/witness.h), and the verdict (oracle/judge.h)
/// with its evidence re-checked from the file.
///
/// The command under test never touches what it is judged on. lpvid holds
/// every case in memory (CaseCopy) before any command runs; just before a
/// case's command starts, lpvid writes, each folder emptied first,
///   <work>/<case>.lpvid/  lpvid's copy (task.json, data.csv, model.json,
///                         truth.json of a random case), its certificates
///                         and any not_a_witness file;
///   <work>/<case>/        the command's copy ({dir}, {data}, {model},
///                         {task}), where it writes {out};
/// lpvid certifies from the bytes in memory (a file is written for the
/// certificates to name, never read back to compute), keeps the bytes of
/// every file it writes, and judges on them: when the command has ended and
/// again when the verdict is found, every such file is compared byte for
/// byte with the memory, and a difference makes the case "tampered" (an
/// error of the command, never a verdict on its answer). So does a process
/// of the command still running after it ended (killed, and named in the
/// report: outside_command.h). The evidence of every verdict that names a
/// certificate is checked once more from its file by the verifier.

#include <map>
#include <string>

#include "oracle/judge.h"
#include "oracle/oracle_report.h"

namespace lpvid {

/// lpvid's copy of a case: its name and the bytes of task.json, data.csv and
/// model.json (the task naming "data.csv" and "model.json"), and files only
/// lpvid's copy gets (a random case's truth.json).
struct CaseCopy {
  std::string name;
  std::map<std::string, std::string> files;
  std::map<std::string, std::string> lpvid_only;
};

/// Reads the case in `folder`: task.json and the data and model it names.
/// Throws InputError when the case itself is unreadable (a bad case is not
/// an outside error).
CaseCopy read_case_copy(const std::string& folder);

struct OracleCaseOptions {
  std::string command;          ///< the outside command template (oracle/outside_command.h)
  std::string work = "oracle-run";  ///< the folder of both copies of every case
  double case_timeout = 120;    ///< seconds for the outside command
  std::string solver = "csdp";  ///< lpvid's own solver
  JudgeTolerance tolerance;     ///< from the command line only
  /// identify cases: compute lpvid's class interval (--no-class-bound: no;
  /// claims are then judged as the fixed model with their θ only).
  bool class_bound = true;
};

/// Runs and judges one case (copies written as above).
CaseReport run_oracle_case(const CaseCopy& copy, const OracleCaseOptions& options);

}  // namespace lpvid
