#include "jobs/merge.h"

#include <filesystem>

#include "core/file_io.h"
#include "core/sha256.h"
#include "data/csv_reader.h"
#include "jobs/joint_check.h"
#include "model/model_file.h"

namespace lpvid::jobs {

const char* to_string(MergeVerdict v) {
  switch (v) {
    case MergeVerdict::kConsistent: return "consistent";
    case MergeVerdict::kInvalidated: return "invalidated";
    case MergeVerdict::kNotVerified: return "not_verified";
    case MergeVerdict::kDataChanged: return "data_changed";
    case MergeVerdict::kModelChanged: return "model_changed";
  }
  return "?";
}

void StatusCounts::add(WindowStatus s) {
  switch (s) {
    case WindowStatus::kVerified: ++verified; break;
    case WindowStatus::kInvalidated: ++invalidated; break;
    case WindowStatus::kMissing: ++missing; break;
    case WindowStatus::kRefused: ++refused; break;
  }
}

MergeVerdict merge_verdict(const std::vector<MergedWindow>& windows, const std::optional<WindowResult>& joint) {
  StatusCounts all;
  for (const MergedWindow& m : windows) all.add(m.r.status);
  if (joint) all.add(joint->status);
  if (all.invalidated > 0) return MergeVerdict::kInvalidated;
  if (all.missing + all.refused > 0) return MergeVerdict::kNotVerified;
  return MergeVerdict::kConsistent;
}

VerifiedSummary verified_summary(const std::vector<MergedWindow>& windows) {
  VerifiedSummary s;
  Rational weighted_dmax2;
  for (const MergedWindow& m : windows) {
    if (m.r.status != WindowStatus::kVerified) continue;
    const long n = m.w.file_end - m.w.file_begin;
    s.samples += n;
    weighted_dmax2 += Rational(n) * m.r.dmax2;
    if (m.r.upper > s.worst_upper) s.worst_upper = m.r.upper;
    if (m.r.dmax2 > s.worst_dmax2) s.worst_dmax2 = m.r.dmax2;
    if (m.r.delta2 > s.worst_delta2) s.worst_delta2 = m.r.delta2;
    if (m.r.has_lower) {
      if (!s.any_lower || m.r.lower > s.best_lower) s.best_lower = m.r.lower;
      s.any_lower = true;
    }
  }
  // Σ_k ‖d_k‖² ≤ Σ_k n_k·ny·d_k²: the noise over the verified windows has RMS² ≤ this
  if (s.samples > 0) s.record_dmax2 = weighted_dmax2 / Rational(s.samples);
  return s;
}

MergeResult merge_jobs(const std::string& dir_text, const std::function<void(size_t, size_t)>& progress) {
  MergeResult m;
  m.plan = read_plan(dir_text);
  const JobPlan& plan = m.plan;
  // the data file read once: hashed, and parsed (only if unchanged) for every window's exact check
  const std::string bytes = read_text_file(plan.data_path);
  DataTable data;
  data.reference.file = plan.data_path;
  data.reference.sha256 = sha256_hex(bytes);
  data.reference.names = plan.data_names;
  if (data.reference.sha256 != plan.data_sha256) {
    m.verdict = MergeVerdict::kDataChanged;
    m.changed = plan.data_path + ": the data changed since the plan was made (sha256 differs)";
    return m;
  }
  if (sha256_hex(read_text_file(plan.model_path)) != plan.model_sha256) {
    m.verdict = MergeVerdict::kModelChanged;
    m.changed = plan.model_path + ": the model changed since the plan was made (sha256 differs)";
    return m;
  }
  data.table = plan.data_names.empty() ? parse_table(bytes, plan.data_path) : parse_table(bytes, plan.data_path, plan.data_names);
  const std::filesystem::path dir(dir_text);
  const LpvModel<Rational> planned_model = read_model_file<Rational>(plan.model_path);
  const PlannedClaim planned = planned_claim(plan);
  for (const JobWindow& w : plan.windows) {
    const LpvModel<Rational> model = window_model(planned_model, w);
    m.windows.push_back({w, judge_window(planned, w, model, (dir / w.certificate).string(), data)});
    m.counts.add(m.windows.back().r.status);
    if (progress) progress(m.windows.size(), plan.windows.size());
  }
  m.summary = verified_summary(m.windows);
  if (plan.joint) m.joint = judge_joint(planned, plan, planned_model, (dir / plan.joint->certificate).string(), data);
  m.verdict = merge_verdict(m.windows, m.joint);
  return m;
}

}  // namespace lpvid::jobs
