#include "jobs/joint_check.h"

#include "core/number_text.h"
#include "core/stop_request.h"
#include "verify/certificate/certificate_check.h"

namespace lpvid::jobs {

namespace {

/// Why record k of the joint certificate is not window k of the plan.
std::string joint_record_mismatch(const PlannedClaim& p, const JobWindow& w, size_t k, const CertificateRecord& r) {
  const std::string at = "records[" + std::to_string(k) + "] ";
  if (r.data.sha256 != p.data_sha256) return at + "is made from other data (sha256 " + r.data.sha256 + ")";
  if (r.data.row_begin != w.file_begin || r.data.row_end != w.file_end)
    return at + "certifies rows " + std::to_string(r.data.row_begin) + ":" + std::to_string(r.data.row_end) +
           ", the plan's window " + std::to_string(k) + " is rows " + std::to_string(w.file_begin) + ":" +
           std::to_string(w.file_end);
  std::string planned;
  for (const std::string& v : w.x0) planned += (planned.empty() ? "" : " ") + rational_to_text(rational_from_text(v));
  const std::string have = exact_x0_text(r.x0);
  if (have != planned)
    return at + "starts from x0 = [" + have + "], the plan's x0 for window " + std::to_string(k) + " is [" + planned + "]";
  return "";
}

}  // namespace

std::string joint_mismatch(const PlannedClaim& p, const JobPlan& plan, const LpvModel<Rational>& model,
                           const Certificate& c) {
  if (c.records.size() < 2 || c.records.size() != plan.windows.size())
    return "names " + std::to_string(c.records.size()) + " record(s), the plan's joint claim has " +
           std::to_string(plan.windows.size()) + " (one per window)";
  for (size_t k = 0; k < c.records.size(); ++k)
    if (std::string why = joint_record_mismatch(p, plan.windows[k], k, c.records[k]); !why.empty()) return why;
  if (c.mode != p.mode) return std::string("toeplitz mode ") + to_string(c.mode) + ", the plan's is " + to_string(p.mode);
  if (std::string why = model_besides_x0_mismatch(model, c.model); !why.empty()) return why;
  return certificate_claim_mismatch(p, c);
}

WindowResult judge_joint(const PlannedClaim& p, const JobPlan& plan, const LpvModel<Rational>& model,
                         const std::string& certificate_path, const DataTable& data) {
  WindowResult r;
  const FileState state = file_state(certificate_path);
  if (state.missing) {
    r.reason = "no joint certificate (the job did not run, failed, or found no verified bound; see " + plan.joint->report + ")";
    return r;
  }
  r.status = WindowStatus::kRefused;
  if (!state.problem.empty()) {
    r.reason = state.problem;
    return r;
  }
  Certificate c;
  try {
    c = read_certificate(certificate_path);
    r.reason = joint_mismatch(p, plan, model, c);
    if (!r.reason.empty()) return r;
    const CertificateVerdict v = check_certificate(c, data);
    if (!v.holds) {
      r.reason = "the exact check refused it: " + v.reason;
      return r;
    }
  } catch (const RunStopped&) {
    throw;  // a requested stop or the --timeout ends the run, not this window's check
  } catch (const std::runtime_error& e) {
    r.reason = std::string("unreadable or cannot be checked: ") + e.what();
    return r;
  }
  r.status = c.claim == CertificateClaim::kInvalidated ? WindowStatus::kInvalidated : WindowStatus::kVerified;
  r.delta2 = c.delta2;
  r.dmax2 = c.dmax2;
  return r;
}

}  // namespace lpvid::jobs
