#include "cli/oracle_case.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <future>
#include <map>
#include <optional>

#include "cli/inputs.h"
#include "core/file_io.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "certify/certificate_files.h"
#include "identify/class_interval.h"
#include "identify/fix_and_certify.h"
#include "model/simulate.h"
#include "oracle/answer.h"
#include "oracle/judge.h"
#include "oracle/outside_command.h"
#include "oracle/task.h"
#include "solvers/external_solvers.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/certificate_file.h"

namespace lpvid::cli {
namespace {

namespace fs = std::filesystem;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The common options of `lpvid invalidate` for the task: lpvid certifies
/// exactly what that command would.
CommonOptions task_options(const OracleTask& task, const fs::path& folder, const std::string& solver) {
  CommonOptions c;
  c.command = "oracle";
  c.quiet = true;
  c.solver = solver;
  c.data_path = (folder / task.data).string();
  c.model_path = (folder / task.model).string();
  c.delta_text = task.delta;
  c.dmax_text = task.dmax;
  if (!task.lambda.empty()) c.lambda = double_from_text(task.lambda);
  return c;
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

/// The exact check of the witness at the claimed values (the task's fixed
/// values for the others). A failing witness leaves a "not_a_witness"
/// certificate in the folder (its bytes kept in `held`), checked again from the file.
WitnessResult check_witness(const OracleTask& task, const OracleAnswer& a, const LpvModel<Rational>& model,
                            const Inputs& in, const fs::path& folder, HeldFiles& held) {
  WitnessResult r;
  if (!a.witness) return r;
  Certificate c;
  set_data_reference(c, in.data);
  c.model = model;
  c.mode = ToeplitzMode::kSignal;
  const Rational delta = task.delta.empty() ? *a.delta : rational_from_text(task.delta);
  const Rational dmax = task.dmax.empty() ? *a.dmax : rational_from_text(task.dmax);
  c.delta2 = delta * delta;
  c.dmax2 = dmax * dmax;
  if (a.witness->taps_form) {
    c.form = CertificateForm::kDelta;
    c.taps = a.witness->taps;
    c.horizon = a.witness->horizon;
  } else {
    c.form = CertificateForm::kW;
    c.w = a.witness->w;
  }
  c.info["tool"] = "lpvid oracle";
  c.info["meaning"] = "the outside implementation's witness, judged at its claimed values";
  const CertificateVerdict holds = check_certificate(c, in.exp_q);
  if (holds.holds) {
    r.status = WitnessResult::kHolds;
    r.text = holds.details;
    return r;
  }
  c.claim = CertificateClaim::kNotAWitness;
  const CertificateVerdict fails = check_certificate(c, in.exp_q);
  if (!fails.holds) {
    r.status = WitnessResult::kMalformed;
    r.text = holds.reason;
    return r;
  }
  r.certificate = (folder / "witness.not_a_witness.json").string();
  write_certificate_at(c, r.certificate, &held);
  r.status = WitnessResult::kFails;
  r.text = holds.reason;
  return r;
}

/// identify: the class lower end of `id`'s class interval, its certificate
/// written to lpvid's folder (its bytes kept in `held`).
ClassReference class_reference(const ClassInterval& ci, const fs::path& folder, HeldFiles& held) {
  ClassReference k;
  const ClassBoundResult& b = ci.bound;
  if (!b.certified) {
    k.reason = b.reason;
    return k;
  }
  k.verified = true;
  k.lower = b.lower;
  k.certificate = (folder / "lpvid.class.json").string();
  write_certificate_at(*b.certificate, k.certificate, &held);
  k.whole_class = b.whole_class;
  k.center = b.certificate->region.center;
  k.radius = b.certificate->region.radius;
  k.free = b.certificate->region.free;
  return k;
}

/// identify: lpvid's own identification of the task (Theorem 3.1, iterated
/// relaxation, θ fixed and certified), the reference for "suboptimal", and
/// its class interval (identify/class_interval.h; in the convex case the
/// class optimum replaces lpvid's θ when it certifies lower), whose lower
/// end refutes claims below it. The certificates' bytes are kept in `held`.
void identify_reference(const Inputs& in, const CommonOptions& c, const fs::path& folder, SdpSolver& solver,
                        ReferenceResult& ref, HeldFiles& held) {
  IdentifyOptions opt;
  opt.objective = in.objective;
  opt.iterate = true;
  CertifyOptions co = certify_options(c, in);
  co.lower_end = false;
  IdentifiedModel id = identify_and_certify(in.model_q, in.model_d, in.exp_q, in.exp_d, opt, co, solver);
  if (!id.bounds.verified()) {
    ref.klass.reason = "lpvid's own identification was not certified";
    return;
  }
  ClassBoundOptions cbo;
  cbo.unknowns = opt.unknowns;
  ref.klass =
      class_reference(class_interval(id, in.model_q, in.model_d, in.exp_q, in.exp_d, co, cbo, solver), folder, held);
  ref.identified_verified = true;
  ref.identified = id.bounds.dmax2;
  ref.identified_certificate =
      write_certificates(id.bounds, (folder / "lpvid.identify.cert.json").string(), &held).certificate;
}

using CaseFiles = std::map<std::string, std::string>;

/// Writes every file into `folder` (emptied first), each one's bytes kept in `held`.
void write_case_files(const CaseFiles& files, const fs::path& folder, HeldFiles& held) {
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
std::string changed_files(const HeldFiles& held) {
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
std::optional<NotJudged> not_judged(const CommandRun& run, const HeldFiles& held, const std::string& out,
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
  CommonOptions c;
  Inputs in;
  HeldFiles held;
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
  s.c = task_options(s.task, mine, o.solver);
  s.in = load_inputs(s.c, s.held);  // the bytes in memory, not the files just written
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
                const ReferenceResult& identified, const OracleCaseOptions& o, const fs::path& mine) {
  CaseReport& rep = s.rep;
  const WitnessResult witness = check_witness(s.task, answer, judged, s.in, mine, s.held);
  ReferenceResult ref =
      reference_of(b, s.in.objective, write_certificates(b, (mine / "lpvid.cert.json").string(), &s.held));
  ref.identified_verified = identified.identified_verified;
  ref.identified = identified.identified;
  ref.identified_certificate = identified.identified_certificate;
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
  const Inputs& in = s.in;
  const std::string out = (theirs / "answer.json").string();
  const std::string command = substitute_placeholders(
      o.command, {{"data", (theirs / "data.csv").string()}, {"model", (theirs / "model.json").string()},
                  {"task", (theirs / "task.json").string()}, {"out", out}, {"dir", theirs.string()}});
  // The outside command runs while lpvid certifies the same task.
  auto outside = std::async(std::launch::async, run_shell_command, command, o.case_timeout, rep.outside_log);
  const auto started = std::chrono::steady_clock::now();
  auto solver = make_solver_for_cli(s.c.solver, "");
  const CertifyOptions co = certify_options(s.c, in);
  const bool identify = s.task.kind == TaskKind::kIdentify;
  ReferenceResult identified;
  CertifiedBounds b;
  if (identify) identify_reference(in, s.c, mine, *solver, identified, s.held);
  else b = certify_fixed(in.model_q, in.exp_q, in.mode, co, *solver);
  rep.lpvid_seconds = seconds_since(started);
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
    b = certify_fixed(judged, in.exp_q, in.mode, co, *solver);
    rep.lpvid_seconds += seconds_since(again);
  }
  judge_case(s, answer, judged, b, identified, o, mine);
  return rep;
}

}  // namespace lpvid::cli
