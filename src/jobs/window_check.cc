#include "jobs/window_check.h"

#include <filesystem>
#include <system_error>

#include "certify/certificate_files.h"
#include "certify/certify.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "core/stop_request.h"
#include "model/model_file.h"
#include "verify/certificate/certificate_check.h"

namespace lpvid::jobs {

namespace {

namespace fs = std::filesystem;

Rational squared_text(const std::string& text) {
  const Rational q = rational_from_text(text);
  return q * q;
}

/// "" when `have` is the planned value, else "<name> = have, the plan's is planned".
std::string differs(const char* name, const Rational& have, const Rational& planned) {
  if (have == planned) return "";
  return std::string(name) + " = " + rational_to_text(have) + ", the plan's is " + rational_to_text(planned);
}

std::string model_mismatch(const LpvModel<Rational>& planned, const LpvModel<Rational>& have) {
  if (write_model_json(have) == write_model_json(planned)) return "";
  if (std::string why = model_besides_x0_mismatch(planned, have); !why.empty()) return why;
  return "certifies the model with x0 = [" + exact_x0_text(have.x0) + "], the plan's x0 for this window is [" +
         exact_x0_text(planned.x0) + "]";
}

}  // namespace

std::string exact_x0_text(const Vec<Rational>& x0) {
  std::string s;
  for (Eigen::Index i = 0; i < x0.size(); ++i) s += (i ? " " : "") + rational_to_text(x0(i));
  return s;
}

std::string model_besides_x0_mismatch(const LpvModel<Rational>& planned, const LpvModel<Rational>& have) {
  LpvModel<Rational> a = planned, b = have;
  a.x0.resize(0);
  b.x0.resize(0);
  return write_model_json(a) == write_model_json(b) ? "" : "certifies another model than the planned one";
}

std::string certificate_claim_mismatch(const PlannedClaim& p, const Certificate& c) {
  // An allow-list, not a deny-list: a window's (or the joint job's)
  // certificate is the claim the plan's objective produces, "consistent", or
  // "invalidated" when the plan fixes both delta and dmax. Every other kind
  // (a lower end, not_a_witness, a class claim, a kind added later) is refused,
  // even when it holds: it does not say what the window is counted for.
  const bool invalidated = c.claim == CertificateClaim::kInvalidated;
  if (c.claim != CertificateClaim::kConsistent && !invalidated)
    return std::string("a \"") + to_string(c.claim) +
           "\" certificate in place of the window's certificate (the plan's objective " + objective_name(p.objective) +
           " produces only \"consistent\"" +
           (p.objective == BoundObjective::Kind::kFeasibility ? " or \"invalidated\")" : ")");
  if (invalidated && p.objective != BoundObjective::Kind::kFeasibility)
    return std::string("claims \"invalidated\", but the plan's objective ") + objective_name(p.objective) +
           " fixes only one of delta, dmax";
  std::string why;
  if (p.delta2) why = differs("delta^2", c.delta2, *p.delta2);
  if (why.empty() && p.dmax2) why = differs("dmax^2", c.dmax2, *p.dmax2);
  return why.empty() ? "" : std::string("claims \"") + to_string(c.claim) + "\" at " + why;
}

FileState file_state(const std::string& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (st.type() == fs::file_type::not_found) return {true, ""};
  if (ec) return {false, "unreadable: " + path + ": " + ec.message()};
  if (st.type() != fs::file_type::regular) return {false, "unreadable: " + path + ": not a regular file"};
  return {};
}

namespace {

DualClaim dual_claim_of(BoundObjective::Kind kind) {
  switch (kind) {
    case BoundObjective::Kind::kMinDelta: return DualClaim::kMinDelta2;
    case BoundObjective::Kind::kMinDmax: return DualClaim::kMinDmax2;
    case BoundObjective::Kind::kWeighted: return DualClaim::kWeighted;
    case BoundObjective::Kind::kFeasibility: break;
  }
  return DualClaim::kInvalidated;
}

const char* dual_claim_words(DualClaim d) {
  switch (d) {
    case DualClaim::kMinDelta2: return "delta^2 (objective min_delta)";
    case DualClaim::kMinDmax2: return "dmax^2 (objective min_dmax)";
    case DualClaim::kWeighted: return "lambda*delta^2 + (1-lambda)*dmax^2 (objective weighted)";
    case DualClaim::kInvalidated: break;
  }
  return "nothing (objective feasibility)";
}

/// The lower-end file against the plan's objective.
std::string lower_end_mismatch(const PlannedClaim& p, const Certificate& c) {
  if (p.objective == BoundObjective::Kind::kFeasibility)
    return "a lower-end file, but the plan fixes both delta and dmax (there is no lower end)";
  if (c.claim != CertificateClaim::kLowerBound)
    return std::string("the lower-end file claims \"") + to_string(c.claim) + "\", not a lower bound";
  const DualClaim want = dual_claim_of(p.objective);
  if (c.objective != want)
    return std::string("the lower-end file bounds ") + dual_claim_words(c.objective) + ", the plan's objective is " +
           dual_claim_words(want);
  std::string why;
  if (want == DualClaim::kMinDmax2) why = differs("delta^2", c.delta2, *p.delta2);
  if (want == DualClaim::kMinDelta2) why = differs("dmax^2", c.dmax2, *p.dmax2);
  if (want == DualClaim::kWeighted) why = differs("lambda", c.lambda, p.lambda);
  return why.empty() ? "" : "the lower end is certified at " + why;
}

/// Reads the file at `path` (which exists) and judges it: "" when it is
/// the planned claim and holds exactly, the reason otherwise.
std::string read_and_check(const PlannedClaim& p, const JobWindow& w, const LpvModel<Rational>& model,
                           const std::string& path, const DataTable& data, WindowFile file, Certificate& c) {
  try {
    c = read_certificate(path);
  } catch (const std::runtime_error& e) {
    return std::string("unreadable: ") + e.what();
  }
  if (std::string why = plan_mismatch(p, w, model, c, file); !why.empty()) return why;
  try {
    const CertificateVerdict v = check_certificate(c, data);
    return v.holds ? "" : "the exact check refused it: " + v.reason;
  } catch (const RunStopped&) {
    throw;  // a requested stop or the --timeout ends the run, not this window's check
  } catch (const std::runtime_error& e) {
    return std::string("cannot be checked: ") + e.what();
  }
}

/// The lower end beside a verified window's certificate, when there is one.
void judge_lower_end(const PlannedClaim& p, const JobWindow& w, const LpvModel<Rational>& model,
                     const std::string& certificate_path, const DataTable& data, WindowResult& r) {
  const std::string low = lower_certificate_path(certificate_path);
  const FileState state = file_state(low);
  if (state.missing) return;
  Certificate cl;
  const std::string why =
      state.problem.empty() ? read_and_check(p, w, model, low, data, WindowFile::kLowerEnd, cl) : state.problem;
  if (!why.empty()) {
    r.status = WindowStatus::kRefused;
    r.reason = "lower end: " + why;
    return;
  }
  r.has_lower = true;
  r.lower = cl.lower_bound;
}

}  // namespace

const char* objective_name(BoundObjective::Kind kind) {
  switch (kind) {
    case BoundObjective::Kind::kMinDmax: return "min_dmax";
    case BoundObjective::Kind::kMinDelta: return "min_delta";
    case BoundObjective::Kind::kFeasibility: return "feasibility";
    case BoundObjective::Kind::kWeighted: break;
  }
  return "weighted";
}

BoundObjective::Kind objective_kind_of(const std::string& name) {
  for (auto k : {BoundObjective::Kind::kMinDmax, BoundObjective::Kind::kMinDelta, BoundObjective::Kind::kFeasibility,
                 BoundObjective::Kind::kWeighted})
    if (name == objective_name(k)) return k;
  throw InputError("objective.kind: unknown objective '" + name + "' (min_dmax, min_delta, feasibility, weighted)");
}

PlannedClaim planned_claim(const JobPlan& plan) {
  PlannedClaim p;
  p.data_sha256 = plan.data_sha256;
  p.mode = toeplitz_mode_from_string(plan.toeplitz);
  p.objective = objective_kind_of(plan.objective);
  BoundObjective o;
  o.kind = p.objective;
  if (o.delta_fixed()) p.delta2 = squared_text(plan.delta_text);
  if (o.dmax_fixed()) p.dmax2 = squared_text(plan.dmax_text);
  // the jobs write λ as double_to_text of the option's double (0.5 by default)
  p.lambda = rational_from_text(plan.lambda_text.empty() ? double_to_text(BoundObjective{}.lambda) : plan.lambda_text);
  return p;
}

LpvModel<Rational> window_model(const LpvModel<Rational>& planned, const JobWindow& w) {
  LpvModel<Rational> m = planned;
  if (static_cast<Eigen::Index>(w.x0.size()) != m.x0.size())
    throw InputError("plan.json: windows[" + std::to_string(w.index) + "].x0: " + std::to_string(w.x0.size()) +
                     " values for a model of " + std::to_string(m.x0.size()) + " states");
  for (Eigen::Index i = 0; i < m.x0.size(); ++i) m.x0(i) = rational_from_text(w.x0[static_cast<size_t>(i)]);
  return m;
}

std::string plan_mismatch(const PlannedClaim& p, const JobWindow& w, const LpvModel<Rational>& model,
                          const Certificate& c, WindowFile file) {
  if (c.records.size() != 1)
    return "names " + std::to_string(c.records.size()) + " records, the plan's window is one record";
  const DataReference& d = c.records.front().data;
  if (d.sha256 != p.data_sha256) return "made from other data (sha256 " + d.sha256 + ")";
  if (d.row_begin != w.file_begin || d.row_end != w.file_end)
    return "certifies rows " + std::to_string(d.row_begin) + ":" + std::to_string(d.row_end) + ", not the window's " +
           std::to_string(w.file_begin) + ":" + std::to_string(w.file_end);
  if (c.mode != p.mode)
    return std::string("toeplitz mode ") + to_string(c.mode) + ", the plan's is " + to_string(p.mode);
  if (std::string why = model_mismatch(model, c.model); !why.empty()) return why;
  return file == WindowFile::kCertificate ? certificate_claim_mismatch(p, c) : lower_end_mismatch(p, c);
}

const char* to_string(WindowStatus s) {
  switch (s) {
    case WindowStatus::kVerified: return "verified";
    case WindowStatus::kInvalidated: return "invalidated";
    case WindowStatus::kMissing: return "missing";
    case WindowStatus::kRefused: break;
  }
  return "refused";
}

WindowResult judge_window(const PlannedClaim& p, const JobWindow& w, const LpvModel<Rational>& model,
                          const std::string& certificate_path, const DataTable& data) {
  WindowResult r;
  const FileState state = file_state(certificate_path);
  if (state.missing) {
    r.reason = "no certificate (the job did not run, failed, or found no verified bound; see " + w.report + ")";
    return r;
  }
  Certificate c;
  r.reason = state.problem.empty()
                 ? read_and_check(p, w, model, certificate_path, data, WindowFile::kCertificate, c)
                 : state.problem;
  if (!r.reason.empty()) {
    r.status = WindowStatus::kRefused;
    return r;
  }
  if (c.claim == CertificateClaim::kInvalidated) {
    r.status = WindowStatus::kInvalidated;
    return r;
  }
  r.status = WindowStatus::kVerified;
  r.delta2 = c.delta2;
  r.dmax2 = c.dmax2;
  BoundObjective o;
  o.kind = p.objective;
  o.lambda = nearest_double(p.lambda);
  r.upper = objective_at(o, c.delta2, c.dmax2);
  r.x0 = exact_x0_text(c.model.x0);
  judge_lower_end(p, w, model, certificate_path, data, r);
  return r;
}

}  // namespace lpvid::jobs
