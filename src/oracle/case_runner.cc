#include "oracle/case_runner.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <future>
#include <map>
#include <optional>

#include "certify/certificate_files.h"
#include "certify/certify.h"
#include "core/file_io.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "model/load_problem.h"
#include "model/simulate.h"
#include "oracle/answer.h"
#include "oracle/judge.h"
#include "oracle/outside_command.h"
#include "oracle/reference.h"
#include "oracle/task.h"
#include "oracle/witness.h"
#include "solvers/external_solvers.h"
#include "toeplitz/uncertainty_toeplitz.h"
#include "verify/certificate/certificate_check.h"

namespace lpvid {
namespace {

namespace fs = std::filesystem;

double case_seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// lpvid's inputs of the task in `folder`, read as `lpvid invalidate --data
/// <folder>/data.csv --model <folder>/model.json` reads them, each file's
/// bytes from `held` (never from the file just written): one record, every
/// row, the model's x0.
LoadedProblem case_inputs(const OracleTask& task, const fs::path& folder, const WrittenFiles& held) {
  const RecordRequest record{(folder / task.data).string(), std::nullopt, "", {}};
  return load_problem((folder / task.model).string(), {record}, std::nullopt, bytes_held(held));
}

/// What `lpvid invalidate --quiet` certifies the task with: its objective
/// and the record's reference, every other option at its default.
CertifyOptions case_certify_options(const OracleTask& task, const LoadedProblem& in) {
  CertifyOptions co;
  co.objective = objective_of(task);
  co.objective.validate();
  co.records = in.records;
  return co;
}

std::string claim_words(const OracleTask& task, const OracleAnswer& a) {
  if (a.failed) return "failed";
  const auto text = [](const Rational& q) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", CGAL::to_double(q));
    return std::string(buf);
  };
  std::string s;
  switch (task.kind) {
    case TaskKind::kMinDmax: s = "dmax = " + text(*a.dmax); break;
    case TaskKind::kMinDelta: s = "delta = " + text(*a.delta); break;
    case TaskKind::kWeighted: s = "delta = " + text(*a.delta) + ", dmax = " + text(*a.dmax); break;
    case TaskKind::kDecide: s = a.verdict; break;
    case TaskKind::kIdentify: s = "dmax = " + text(*a.dmax) + " with theta"; break;
  }
  return a.witness ? s + " +witness" : s;
}

using CaseFiles = std::map<std::string, std::string>;

/// Writes every file into `folder` (emptied first), each one's bytes kept in `held`.
void write_case_files(const CaseFiles& files, const fs::path& folder, WrittenFiles& held) {
  std::error_code ec;
  fs::remove_all(folder, ec);
  fs::create_directories(folder, ec);
  if (!fs::is_directory(folder)) throw IoError("cannot create the case folder '" + folder.string() + "'");
  for (const auto& [name, text] : files) {
    const std::string path = (folder / name).string();
    write_text_file(path, text, "case file");
    held[path] = text;
  }
}

/// The files of `held` whose bytes on disk are not the held ones (a removed
/// or unreadable one included), as "a, b"; "" when none.
std::string changed_files(const WrittenFiles& held) {
  std::string changed;
  for (const auto& [path, text] : held) {
    bool same = false;
    try {
      same = read_text_file(path) == text;
    } catch (const std::runtime_error&) {
    }
    if (!same) changed += (changed.empty() ? "" : ", ") + path;
  }
  return changed;
}

/// The reason of a "tampered" case whose files changed.
std::string changed_reason(const std::string& changed, const std::string& when) {
  return "the case's files changed " + when + " (" + changed + "); its answer is not judged";
}

}  // namespace

CaseCopy read_case_copy(const std::string& folder_text) {
  const fs::path folder = fs::absolute(folder_text).lexically_normal();
  const std::string task_path = (folder / "task.json").string();
  OracleTask task = parse_task(read_text_file(task_path), task_path);
  CaseCopy copy;
  copy.name = folder.has_filename() ? folder.filename().string() : folder.parent_path().filename().string();
  copy.files["data.csv"] = read_text_file((folder / task.data).string());
  copy.files["model.json"] = read_text_file((folder / task.model).string());
  task.data = "data.csv";
  task.model = "model.json";
  copy.files["task.json"] = task_json(task);
  return copy;
}

namespace {

/// Why the outside command's answer cannot be judged (and the verdict
/// that says so); no reason when it can.
struct NotJudged {
  std::string reason;
  OracleVerdict verdict = OracleVerdict::kError;
};
std::optional<NotJudged> not_judged(const CommandRun& run, const WrittenFiles& held, const std::string& out,
                                    const OracleCaseOptions& o, const std::string& log) {
  const std::string changed = changed_files(held);
  if (!changed.empty()) return NotJudged{changed_reason(changed, "while the command ran"), OracleVerdict::kTampered};
  const std::string killed = survivor_list(run.survivors);
  if (!run.started) return NotJudged{"the command did not start: " + run.error};
  if (run.timed_out)
    return NotJudged{"the command ran past the case time limit of " + double_to_text(o.case_timeout) + " s" +
                     (killed.empty() ? "" : "; killed after it: " + killed)};
  if (!killed.empty())
    return NotJudged{"the command left " + std::to_string(run.survivors.size()) +
                         " process(es) running after it ended, killed: " + killed + "; its answer is not judged",
                     OracleVerdict::kTampered};
  if (run.exit_code != 0)
    return NotJudged{"the command exited with code " + std::to_string(run.exit_code) + " (log " + log + ")"};
  if (!fs::is_regular_file(out)) return NotJudged{"the command wrote no answer at " + out};
  return std::nullopt;
}

/// The evidence of a verdict (a refutation's, a confirmation's, …) is
/// checked once more, from its file, by the verifier: not a repeat of the
/// in-memory check, it guards the file actually written (its relative data
/// path, its sha256 against the bytes lpvid held).
void recheck_evidence(CaseReport& rep) {
  if (rep.judgement.evidence.empty()) return;
  CertificateVerdict v;
  try {
    v = check_certificate_file(rep.judgement.evidence);
  } catch (const std::exception& e) {
    v.holds = false;
    v.reason = e.what();
  }
  rep.evidence_check = v.holds ? v.claim_text : "invalid: " + v.reason;
  if (!v.holds) {
    rep.judgement.verdict = OracleVerdict::kUndecided;
    rep.judgement.reason = "lpvid's evidence did not pass the verifier (" + v.reason + "); not counted: " + rep.judgement.reason;
  }
}

/// The case's copies written (lpvid's in `mine`, the command's in
/// `theirs`, both fresh), its task as the command sees it, lpvid's inputs
/// parsed from the bytes in memory, the bytes of every file lpvid wrote, and
/// the report's header.
struct CaseSetup {
  CaseFiles files;
  OracleTask task;
  LoadedProblem in;
  CertifyOptions certify;
  WrittenFiles held;
  CaseReport rep;
};
CaseSetup set_up_case(const CaseCopy& copy, const OracleCaseOptions& o, const fs::path& mine, const fs::path& theirs) {
  CaseSetup s;
  // the task as the command sees it names the run's tolerance (the judge
  // takes it from the command line, never from this file)
  s.files = copy.files;
  s.task = parse_task(s.files.at("task.json"), (mine / "task.json").string());
  s.task.tolerance = o.tolerance.relative;
  s.files["task.json"] = task_json(s.task);
  CaseFiles mine_files = s.files;
  mine_files.insert(copy.lpvid_only.begin(), copy.lpvid_only.end());
  write_case_files(mine_files, mine, s.held);
  s.in = case_inputs(s.task, mine, s.held);  // the bytes in memory, not the files just written
  s.certify = case_certify_options(s.task, s.in);
  s.rep.name = copy.name;
  s.rep.folder = theirs.string();
  s.rep.kind = s.task.kind;
  s.rep.n = static_cast<long>(s.in.exp_q.n());
  s.rep.nu = s.in.model_q.nu;
  s.rep.ny = s.in.model_q.ny;
  // the command's copy, created just before it runs
  write_case_files(s.files, theirs, s.held);
  s.rep.outside_log = (theirs / "outside.log").string();
  return s;
}

/// The answer at `out` read and parsed, or why the case is not judged.
std::optional<NotJudged> read_answer(const CommandRun& run, const CaseSetup& s, const std::string& out,
                                     const OracleCaseOptions& o, OracleAnswer& answer) {
  if (std::optional<NotJudged> problem = not_judged(run, s.held, out, o, s.rep.outside_log)) return problem;
  try {
    answer = parse_answer(read_text_file(out), out, s.task, s.in.model_q);
  } catch (const InputError& e) {
    return NotJudged{std::string("malformed answer: ") + e.what()};
  }
  return std::nullopt;
}

/// The verdict on the answer: the witness checked, lpvid's certificates
/// written (bytes kept), the judgement, its evidence re-checked from the
/// file, and last every file lpvid holds compared with the disk.
void judge_case(CaseSetup& s, const OracleAnswer& answer, const LpvModel<Rational>& judged, const CertifiedBounds& b,
                const IdentifiedReference& identified, const OracleCaseOptions& o, const fs::path& mine) {
  CaseReport& rep = s.rep;
  const WitnessResult witness =
      judge_witness(s.task, answer, judged, s.in.records.front(), s.in.exp_q, mine.string(), s.held);
  ReferenceResult ref =
      reference_of(b, s.certify.objective, write_certificates(b, (mine / "lpvid.cert.json").string(), &s.held));
  ref.identified_verified = identified.verified;
  ref.identified = identified.dmax2;
  ref.identified_certificate = identified.certificate;
  ref.klass = identified.klass;
  if (s.task.kind == TaskKind::kIdentify) rep.klass = ref.klass;
  rep.judgement = judge(s.task, answer, ref, witness, o.tolerance);
  recheck_evidence(rep);
  const std::string changed = changed_files(s.held);
  if (changed.empty()) return;
  rep.judgement.verdict = OracleVerdict::kTampered;
  rep.judgement.reason = changed_reason(changed, "before the verdict was given");
  rep.judgement.evidence.clear();  // a file it names may be one that changed
  rep.evidence_check.clear();
}

}  // namespace

CaseReport run_oracle_case(const CaseCopy& copy, const OracleCaseOptions& o) {
  const fs::path work = fs::absolute(o.work).lexically_normal();
  const fs::path mine = work / (copy.name + ".lpvid"), theirs = work / copy.name;
  CaseSetup s = set_up_case(copy, o, mine, theirs);
  CaseReport& rep = s.rep;
  const LoadedProblem& in = s.in;
  const std::string out = (theirs / "answer.json").string();
  const std::string command = substitute_placeholders(
      o.command, {{"data", (theirs / "data.csv").string()}, {"model", (theirs / "model.json").string()},
                  {"task", (theirs / "task.json").string()}, {"out", out}, {"dir", theirs.string()}});
  // The outside command runs while lpvid certifies the same task.
  auto outside = std::async(std::launch::async, run_shell_command, command, o.case_timeout, rep.outside_log);
  const auto started = std::chrono::steady_clock::now();
  auto solver = make_solver_for_cli(o.solver, "");
  const CertifyOptions& co = s.certify;
  const bool identify = s.task.kind == TaskKind::kIdentify;
  IdentifiedReference identified;
  CertifiedBounds b;
  if (identify)
    identified = identify_reference(in, co, *solver, mine.string(), s.held, o.class_bound);
  else
    b = certify_fixed(in.model_q, in.exp_q, ToeplitzMode::kSignal, co, *solver);
  rep.lpvid_seconds = case_seconds_since(started);
  const CommandRun run = outside.get();
  rep.outside_seconds = run.seconds;
  rep.outside_exit = run.exit_code;
  rep.survivors = run.survivors;
  OracleAnswer answer;
  if (std::optional<NotJudged> problem = read_answer(run, s, out, o, answer)) {
    rep.claim = "-";
    rep.judgement.verdict = problem->verdict;
    rep.judgement.reason = problem->reason;
    return rep;
  }
  rep.claim = claim_words(s.task, answer);
  // identify: the claim is judged on the model with the claimed θ folded in
  const LpvModel<Rational> judged = identify && !answer.failed ? fold_correction(in.model_q, answer.theta) : in.model_q;
  if (identify && !answer.failed) {
    const auto again = std::chrono::steady_clock::now();
    b = certify_fixed(judged, in.exp_q, ToeplitzMode::kSignal, co, *solver);
    rep.lpvid_seconds += case_seconds_since(again);
  }
  judge_case(s, answer, judged, b, identified, o, mine);
  return rep;
}

}  // namespace lpvid
