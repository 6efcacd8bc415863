// lpvid oracle: judges an outside implementation's answers against lpvid's
// certified ones, case by case (oracle/judge.h for the rules).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "core/progress_sink.h"
#include "cli/commands.h"
#include "oracle/case_runner.h"
#include "cli/random_cases.h"
#include "cli/report.h"
#include "core/file_io.h"
#include "core/input_error.h"
#include "oracle/oracle_report.h"

namespace lpvid::cli {
namespace {

namespace fs = std::filesystem;

struct OracleArgs {
  int cases = 20;
  uint64_t seed = 1;
  std::string cases_dir, report, junit;
  double run_timeout = 0;
  bool strict = false, quiet = false, no_class_bound = false;
  OracleCaseOptions run;
  RandomCaseFlags random;
};

/// The given cases (every sub-folder of --cases-dir with a task.json, in
/// name order; lpvid's copies of an earlier run, "<case>.lpvid", left out),
/// each read into memory now, before any outside command runs.
std::vector<CaseCopy> given_cases(const std::string& cases_dir) {
  if (!fs::is_directory(cases_dir)) throw InputError("--cases-dir: '" + cases_dir + "' is not a folder");
  std::vector<std::string> folders;
  for (const auto& e : fs::directory_iterator(cases_dir))
    if (e.is_directory() && e.path().extension() != ".lpvid" && fs::is_regular_file(e.path() / "task.json"))
      folders.push_back(e.path().string());
  std::sort(folders.begin(), folders.end());
  if (folders.empty()) throw InputError("--cases-dir: no sub-folder of '" + cases_dir + "' holds a task.json");
  std::vector<CaseCopy> out;
  for (const std::string& f : folders) out.push_back(read_case_copy(f));
  return out;
}

/// Random case i (0-based), made in memory just before it runs; the
/// generating system (truth.json) goes to lpvid's copy only.
std::string random_case_name(size_t i) {
  char name[32];
  std::snprintf(name, sizeof name, "case-%04zu", i + 1);
  return name;
}

CaseCopy random_case(const OracleArgs& a, const RandomTaskOptions& options, size_t i) {
  CaseCopy copy;
  copy.name = random_case_name(i);
  copy.files = case_folder_files(random_oracle_case(a.seed + static_cast<uint64_t>(i), options));
  copy.lpvid_only["truth.json"] = copy.files.at("truth.json");
  copy.files.erase("truth.json");
  return copy;
}

int run_oracle(const OracleArgs& a) {
  check_output_file(a.report, "report");
  check_output_file(a.junit, "JUnit report");
  const auto started = std::chrono::steady_clock::now();
  const auto elapsed = [&started] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
  const JudgeTolerance& tol = a.run.tolerance;
  if (!(tol.relative >= 0) || !std::isfinite(tol.relative)) throw InputError("--tolerance: must be a number >= 0");
  if (!(tol.absolute >= 0) || !std::isfinite(tol.absolute)) throw InputError("--abs-tolerance: must be a number >= 0");
  const bool given = !a.cases_dir.empty();
  if (!given && a.cases < 1) throw InputError("--cases: at least 1");
  const std::vector<CaseCopy> copies = given ? given_cases(a.cases_dir) : std::vector<CaseCopy>();
  const RandomTaskOptions options = given ? RandomTaskOptions() : random_task_options(a.random);
  const size_t count = given ? copies.size() : static_cast<size_t>(a.cases);
  std::vector<CaseReport> reports;
  for (size_t i = 0; i < count; ++i) {
    if (a.run_timeout > 0 && elapsed() > a.run_timeout) {
      CaseReport skipped;
      skipped.name = given ? copies[i].name : random_case_name(i);
      skipped.folder = (fs::path(a.run.work) / skipped.name).string();
      skipped.claim = "-";
      skipped.judgement.verdict = OracleVerdict::kError;
      skipped.judgement.reason = "not run: the run time limit (--timeout) was reached";
      reports.push_back(skipped);
      continue;
    }
    reports.push_back(run_oracle_case(given ? copies[i] : random_case(a, options, i), a.run));
    const CaseReport& r = reports.back();
    if (!a.quiet)
      progress_printf("[oracle %7.1f s] case %zu/%zu %s (%s, n=%ld, %dx%d): %s%s%s", elapsed(), i + 1, count,
                   r.name.c_str(), to_string(r.kind), r.n, r.ny, r.nu, to_string(r.judgement.verdict),
                   r.judgement.evidence.empty() || r.judgement.verdict != OracleVerdict::kRefuted ? "" : ", certificate ",
                   r.judgement.verdict == OracleVerdict::kRefuted ? r.judgement.evidence.c_str() : "");
  }
  const double seconds = elapsed();
  std::cout << case_table(reports);
  for (const CaseReport& r : reports) {
    if (r.judgement.verdict != OracleVerdict::kConfirmed)
      std::cout << "  " << r.name << " " << to_string(r.judgement.verdict) << ": " << r.judgement.reason
                << (r.evidence_check.empty() ? "" : " [lpvid-verify: " + r.evidence_check + "]") << "\n";
    if (!r.survivors.empty())
      std::cout << "  " << r.name << " survivors killed after the command ended: " << survivor_list(r.survivors) << "\n";
  }
  std::cout << "time " << seconds << " s; each refutation names a certificate that 'lpvid-verify certificate' accepts\n";
  write_json(a.report, oracle_report_json(reports, a.run.command, seconds, a.strict));
  if (!a.junit.empty()) write_text_file(a.junit, junit_xml(reports, seconds, a.strict), "JUnit report");
  const OracleTotals t = totals_of(reports);
  if (t.refuted + t.bad_witness > 0) return kExitInvalidated;
  if (t.error + t.tampered > 0 || (a.strict && t.suboptimal > 0)) return kExitSolver;
  return kExitOk;
}

}  // namespace

Runner add_oracle_command(CLI::App& app) {
  auto a = std::make_shared<OracleArgs>();
  CLI::App* cmd = app.add_subcommand(
      "oracle",
      "Judge an outside implementation: run it on random (or given) cases and confirm, refute (with a certificate), "
      "or call suboptimal each answer");
  cmd->add_option("--command", a->run.command,
                  "the outside command; {data}, {model}, {task}, {out} (and {dir}) become the case's paths, e.g. "
                  "\"python3 my_impl.py {data} {model} {task} {out}\"")
      ->required();
  cmd->add_option("--cases", a->cases, "number of random cases (20)");
  cmd->add_option("--seed", a->seed, "seed of the first random case; case i uses seed + i - 1 (1)");
  cmd->add_option("--cases-dir", a->cases_dir, "judge the given cases instead: every sub-folder holding a task.json");
  cmd->add_option("--work", a->run.work,
                  "folder for the cases' copies: <case>/ the command's (answer, log), <case>.lpvid/ lpvid's (certificates) "
                  "(oracle-run)");
  cmd->add_option("--report", a->report, "JSON report to write");
  cmd->add_option("--junit", a->junit, "JUnit XML file to write (one testcase per case)");
  cmd->add_option("--case-timeout", a->run.case_timeout, "seconds the outside command may take per case (120)");
  cmd->add_option("--timeout", a->run_timeout, "seconds for the whole run; later cases are not started (0: none)");
  cmd->add_option("--solver", a->run.solver, "lpvid's own SDP solver (csdp)");
  cmd->add_option("--abs-tolerance", a->run.tolerance.absolute,
                  "absolute slack on the objective before an answer is 'suboptimal', beside --tolerance (1e-9)");
  cmd->add_flag("--strict", a->strict, "suboptimal answers fail the run too (exit 3, JUnit failures)");
  cmd->add_flag("--no-class-bound", a->no_class_bound,
                "identify cases: skip lpvid's class interval (the costly part at MIMO scale); a claim is then judged "
                "only as the fixed model with its own theta, so a claim below every model of the class is not refuted "
                "by a class certificate");
  cmd->add_flag("--quiet", a->quiet, "no progress lines on stderr");
  add_random_case_flags(*cmd, a->random);
  cmd->callback([cmd, a] {
    if (!a->cases_dir.empty())
      for (const char* name : {"--cases", "--seed", "--siso", "--lti", "--min-n", "--max-n", "--leading-zeros", "--max-delay",
                               "--static-blocks", "--kinds"})
        if (cmd->count(name) > 0)
          throw CLI::ValidationError(name, "shapes random cases; with --cases-dir the given task files decide");
  });
  return [cmd, a] {
    if (!cmd->parsed()) return -1;
    a->run.tolerance.relative = a->random.tolerance;  // --tolerance judges; it is also written to the tasks
    a->run.class_bound = !a->no_class_bound;
    return run_oracle(*a);
  };
}

}  // namespace lpvid::cli
