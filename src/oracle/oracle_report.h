#pragma once
/// What `lpvid oracle` shows and writes about a run: the per-case table on
/// the terminal, the JSON report, and a JUnit XML file so that the outside
/// project's CI lists every case (refuted, bad_witness → failure; no
/// answer, tampered inputs → error; undecided → skipped; suboptimal →
/// failure only with --strict).

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "oracle/judge.h"
#include "oracle/task.h"

namespace lpvid {

struct CaseReport {
  std::string name;     ///< the case folder's name, e.g. "case-0003"
  std::string folder;   ///< its path
  TaskKind kind = TaskKind::kMinDmax;
  long n = 0;
  int nu = 0, ny = 0;
  std::string claim;    ///< the outside claim in words ("dmax = 0.031", "invalidated", …)
  Judgement judgement;
  std::string evidence_check;  ///< the verifier's first line on the evidence file ("lower_bound 0.0098…")
  std::optional<ClassReference> klass;  ///< identify: lpvid's class lower end (or why none)
  double outside_seconds = 0, lpvid_seconds = 0;
  int outside_exit = 0;
  std::string outside_log;
  /// The command's processes still running after it ended, killed by lpvid
  /// ("pid (name)"); any makes the case "tampered".
  std::vector<std::string> survivors;
};

/// The survivors as one text: "12 (sleep), 13 (sh)".
std::string survivor_list(const std::vector<std::string>& survivors);

struct OracleTotals {
  int confirmed = 0, refuted = 0, bad_witness = 0, suboptimal = 0, undecided = 0, error = 0, tampered = 0;
  int total() const { return confirmed + refuted + bad_witness + suboptimal + undecided + error + tampered; }
};
OracleTotals totals_of(const std::vector<CaseReport>& cases);

/// One line per case and a totals line.
std::string case_table(const std::vector<CaseReport>& cases);

nlohmann::ordered_json oracle_report_json(const std::vector<CaseReport>& cases, const std::string& command,
                                          double seconds, bool strict);

std::string junit_xml(const std::vector<CaseReport>& cases, double seconds, bool strict);

}  // namespace lpvid
