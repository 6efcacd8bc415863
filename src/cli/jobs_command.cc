// lpvid jobs plan / lpvid jobs merge: the windows of a long record as
// separate processes (jobs/plan.h says what a window's bound claims).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "core/progress_sink.h"
#include "cli/commands.h"
#include "cli/inputs.h"
#include "cli/refused_alias.h"
#include "cli/report.h"
#include "core/decimal_rounding.h"
#include "core/file_io.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "core/sha256.h"
#include "core/text_printf.h"
#include "diagnose/bound_windows.h"
#include "jobs/merge.h"
#include "jobs/plan.h"
#include "jobs/window_check.h"
#include "jobs/window_states.h"
#include "model/model_file.h"
#include "cli/help_text.h"

namespace lpvid::cli {
namespace {

namespace fs = std::filesystem;
using jobs::JobPlan;
using jobs::JobWindow;
using jobs::JointJob;
using jobs::MergedWindow;
using jobs::MergeResult;
using jobs::MergeVerdict;
using jobs::StatusCounts;
using jobs::VerifiedSummary;
using jobs::WindowResult;
using jobs::WindowStatus;
using jobs::merge_jobs;
using jobs::objective_name;
using jobs::plan_json;
using jobs::shell_quote;
using jobs::to_string;

struct PlanArgs {
  long window = kDefaultWindowLength, min_last = kDefaultMinLastWindow;
  std::string dir, lpvid;
  bool joint = false;  ///< --joint: one more job, every window a record of one claim
};

std::string window_name(int k, const char* suffix) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "w%05d", k);
  return buf + std::string(suffix);
}

/// The options every job passes on to `lpvid invalidate`.
std::string forwarded_options(const CommonOptions& c) {
  std::string s;
  if (!c.names.empty()) {
    s += " --names";
    for (const auto& n : c.names) s += " " + shell_quote(n);
  }
  s += " --toeplitz " + c.toeplitz + " --solver " + c.solver + " --max-taps " + std::to_string(c.max_taps) +
       " --delta-norm " + c.delta_norm;
  if (c.dense_dual) s += " --dense-dual";
  if (!c.delta_text.empty()) s += " --delta " + shell_quote(c.delta_text);
  if (!c.dmax_text.empty()) s += " --dmax " + shell_quote(c.dmax_text);
  if (c.lambda) s += " --lambda " + double_to_text(*c.lambda);
  return s;
}

/// The job of `plan --joint`: one `lpvid invalidate` with every window of
/// the plan as a record (--data F --rows b:e --x0 <the window's x0>) and the
/// plan's model.
JointJob joint_job(const JobPlan& plan, const fs::path& dir, const std::string& program, const std::string& options) {
  JointJob j{"", "joint.cert.json", "joint.report.json"};
  j.command = shell_quote(program) + " invalidate --quiet";
  for (const JobWindow& w : plan.windows) {
    std::string x0;
    for (const std::string& v : w.x0) x0 += (x0.empty() ? "" : ",") + v;
    j.command += " --data " + shell_quote(plan.data_path) + " --rows " + std::to_string(w.file_begin) + ":" +
                 std::to_string(w.file_end) + (x0.empty() ? "" : " --x0 " + shell_quote(x0));
  }
  j.command += " --model " + shell_quote(plan.model_path) + " --certificate " + shell_quote((dir / j.certificate).string()) +
               " --report " + shell_quote((dir / j.report).string()) + options;
  return j;
}

/// The options of `jobs plan` that cannot make a plan, refused.
void check_plan_options(const CommonOptions& c, const PlanArgs& a) {
  if (!c.certificate_path.empty() || !c.report_path.empty() || !c.write_sdpa.empty())
    throw InputError("jobs plan: --certificate, --report and --write-sdpa belong to the jobs (one per window); "
                     "'lpvid jobs merge' writes the report");
  if (a.window < 2) throw InputError("jobs plan: --window-length must be at least 2 rows");
  if (a.min_last < 1) throw InputError("jobs plan: --min-last must be at least 1 row");
  if (c.data_paths.size() > 1)
    throw InputError("jobs plan: one --data (the plan tiles one record into windows); several records: 'lpvid invalidate'");
}

/// The plan's record, model and objective (no windows yet).
JobPlan plan_header(const CommonOptions& c, const PlanArgs& a, const Inputs& in) {
  JobPlan plan;
  plan.data_path = fs::absolute(c.data_path).lexically_normal().string();
  plan.data_sha256 = sha256_hex(read_text_file(c.data_path));
  plan.data_names = c.names;
  plan.model_path = fs::absolute(c.model_path).lexically_normal().string();
  plan.model_sha256 = sha256_hex(read_text_file(c.model_path));
  plan.toeplitz = c.toeplitz;
  plan.objective = objective_name(in.objective.kind);
  plan.delta_text = c.delta_text;
  plan.dmax_text = c.dmax_text;
  plan.lambda_text = c.lambda ? double_to_text(*c.lambda) : "";
  plan.window = a.window;
  plan.min_last = a.min_last;
  return plan;
}

/// Each window with its model file written in `dir`: the window starts from
/// the model's own state there (x0 of the model at the first selected row,
/// simulated in floating point, 12 digits declared).
void plan_windows(JobPlan& plan, const std::vector<RowWindow>& windows, long first_row, const Inputs& in,
                  const fs::path& dir, const std::string& program, const std::string& options) {
  std::vector<Eigen::Index> first_rows;
  for (const RowWindow& w : windows) first_rows.push_back(w.first);
  const std::vector<Vec<Rational>> x0 = jobs::window_start_states(in.model_d, in.exp_d, first_rows, 12);
  for (size_t k = 0; k < windows.size(); ++k) {
    const auto [b, e] = windows[k];
    JobWindow w;
    w.index = static_cast<int>(k);
    w.file_begin = first_row + static_cast<long>(b);
    w.file_end = first_row + static_cast<long>(e);
    w.model = window_name(w.index, ".model.json");
    w.certificate = window_name(w.index, ".cert.json");
    w.report = window_name(w.index, ".report.json");
    LpvModel<Rational> m = in.model_q;
    m.x0 = x0[k];
    for (Eigen::Index i = 0; i < m.x0.size(); ++i) w.x0.push_back(rational_to_text(m.x0(i)));
    write_model_file((dir / w.model).string(), m);
    w.command = shell_quote(program) + " invalidate --quiet --data " + shell_quote(plan.data_path) + " --rows " +
                std::to_string(w.file_begin) + ":" + std::to_string(w.file_end) + " --model " +
                shell_quote((dir / w.model).string()) + " --certificate " + shell_quote((dir / w.certificate).string()) +
                " --report " + shell_quote((dir / w.report).string()) + options;
    plan.windows.push_back(w);
  }
}

/// What was planned and how to run the jobs.
void print_plan(const CommonOptions& c, const PlanArgs& a, const Inputs& in, size_t windows, const fs::path& dir) {
  const std::string jobs = shell_quote((dir / "jobs.txt").string());
  std::cout << "planned " << windows << " window(s) of " << a.window << " rows over " << in.exp_q.n()
            << " samples of " << c.data_path << " (" << in.objective.describe() << ")\n"
            << "  " << (dir / "jobs.txt").string() << ": one 'lpvid invalidate' per line; each window starts from the\n"
            << "  model's own simulated state (declared as x0 in its model file " << window_name(0, ".model.json")
            << ", ...)\n"
            << (a.joint ? "  and last the joint job: every window a record of ONE claim (one Delta, one noise bound; "
                          "each window from its declared x0)\n"
                        : "")
            << "time one window first:   sed -n 1p " << jobs << " | (time bash)\n"
            << "then run them with any batch engine, e.g.\n"
            << "  GNU parallel:  parallel -j 2 < " << jobs << "\n"
            << "  xargs:         xargs -P 2 -d '\\n' -n 1 sh -c < " << jobs << "\n"
            << "  Slurm array:   sbatch --array=1-" << windows + (a.joint ? 1 : 0) << " --wrap \"sed -n \\${SLURM_ARRAY_TASK_ID}p "
            << jobs << " | bash\"\n"
            << "and assemble:    lpvid jobs merge --dir " << shell_quote(dir.string())
            << "   (re-checks every certificate exactly)\n";
}

int run_plan(CommonOptions& c, const PlanArgs& a) {
  check_plan_options(c, a);
  Inputs in = load_inputs(c);
  if (!in.model_q.offset.basis.empty() && in.model_q.offset.values.empty())
    throw InputError(c.model_path + ": offset: the offset values are unknown; give \"values\" (the jobs run 'lpvid invalidate')");
  const long first_row = c.rows_text.empty() ? 0 : c.row_begin;
  const std::vector<RowWindow> windows = tile_windows(in.exp_q.n(), a.window, a.min_last);
  if (a.joint && windows.size() < 2)
    throw InputError("jobs plan --joint: the record makes " + std::to_string(windows.size()) +
                     " window; the joint claim needs at least 2 (a smaller --window-length)");
  if (a.joint && c.toeplitz != "signal")
    throw InputError("jobs plan --joint: several records are certified in --toeplitz signal only");
  JobPlan plan = plan_header(c, a, in);
  std::error_code ec;
  fs::create_directories(a.dir, ec);
  if (!fs::is_directory(a.dir)) throw IoError("jobs plan: cannot create the folder " + a.dir);
  const fs::path dir = fs::absolute(a.dir).lexically_normal();
  const std::string program = a.lpvid.empty() ? fs::read_symlink("/proc/self/exe", ec).string() : a.lpvid;
  if (program.empty()) throw InputError("jobs plan: cannot find this program's path; give --lpvid");
  const std::string options = forwarded_options(c);
  plan_windows(plan, windows, first_row, in, dir, program, options);
  std::string job_lines;
  for (const JobWindow& w : plan.windows) job_lines += w.command + "\n";
  if (a.joint) {
    plan.joint = joint_job(plan, dir, program, options);
    job_lines += plan.joint->command + "\n";
  }
  write_text_file((dir / "jobs.txt").string(), job_lines, "job list");
  write_text_file((dir / "plan.json").string(), plan_json(plan).dump(1) + "\n", "job plan");
  print_plan(c, a, in, windows.size(), dir);
  return kExitOk;
}

/// The joint claim of `plan --joint`: printed, and its entry of merged.json
/// ("joint").
nlohmann::ordered_json render_joint(const WindowResult& r, const JobPlan& plan) {
  const bool ok = r.status == WindowStatus::kVerified || r.status == WindowStatus::kInvalidated;
  nlohmann::ordered_json j = {{"certificate", plan.joint->certificate}, {"status", to_string(r.status)}, {"verified", ok}};
  std::cout << "joint claim (the " << plan.windows.size() << " windows as records of one claim: one Delta, one noise bound): "
            << to_string(r.status);
  if (r.status == WindowStatus::kVerified) {
    j["delta2_exact"] = rational_to_text(r.delta2);
    j["dmax2_exact"] = rational_to_text(r.dmax2);
    j["delta"] = upper_sqrt_text(r.delta2);
    j["dmax"] = upper_sqrt_text(r.dmax2);
    std::cout << ", delta <= " << upper_sqrt_text(r.delta2) << ", dmax <= " << upper_sqrt_text(r.dmax2);
  }
  if (r.status == WindowStatus::kInvalidated) j["verdict"] = "invalidated";
  if (!r.reason.empty()) {
    j["reason"] = r.reason;
    std::cout << ": " << r.reason;
  }
  std::cout << "\n";
  j["meaning"] = "one Delta (acting on each window from rest, each window from its declared x0) and one noise bound on "
                 "the RMS over all samples of all windows explain every window (Theorem 2.1 over several records)";
  return j;
}

/// A window's entry of merged.json ("windows").
nlohmann::ordered_json window_json(const MergedWindow& m, const std::string& objective) {
  nlohmann::ordered_json j = {{"index", m.w.index}, {"rows", {m.w.file_begin, m.w.file_end}}, {"status", to_string(m.r.status)}};
  if (m.r.status == WindowStatus::kVerified) {
    j["delta2_exact"] = rational_to_text(m.r.delta2);
    j["dmax2_exact"] = rational_to_text(m.r.dmax2);
    j["delta"] = upper_sqrt_text(m.r.delta2);
    j["dmax"] = upper_sqrt_text(m.r.dmax2);
    if (objective != "feasibility") j["upper_exact"] = rational_to_text(m.r.upper);
    if (m.r.has_lower) j["lower_exact"] = rational_to_text(m.r.lower);
    j["x0"] = m.r.x0;
  }
  if (!m.r.reason.empty()) j["reason"] = m.r.reason;
  j["certificate"] = m.w.certificate;
  return j;
}

/// The table: every window up to 40, else the first 10 verified ones and
/// the first 30 that are not; then the counts.
void print_merge_table(const MergeResult& res) {
  const std::vector<MergedWindow>& rows = res.windows;
  std::cout << "lpvid jobs merge: " << res.plan.windows.size() << " window(s) of " << res.plan.data_path << ", objective "
            << res.plan.objective << "; every certificate re-checked exactly\n";
  std::cout << text_printf("%6s %15s  %-11s %12s %12s  %s\n", "window", "rows", "status", "delta <=", "dmax <=", "note");
  size_t shown = 0, shown_ok = 0, shown_other = 0;
  for (const MergedWindow& m : rows) {
    const bool good = m.r.status == WindowStatus::kVerified;
    const bool show = rows.size() <= 40 || (good ? shown_ok < 10 : shown_other < 30);
    if (!show) continue;
    ++shown;
    ++(good ? shown_ok : shown_other);
    const std::string span = std::to_string(m.w.file_begin) + ":" + std::to_string(m.w.file_end);
    std::cout << text_printf("%6d %15s  %-11s %12s %12s  %s\n", m.w.index, span.c_str(), to_string(m.r.status),
                good ? upper_sqrt_text(m.r.delta2).c_str() : "-", good ? upper_sqrt_text(m.r.dmax2).c_str() : "-",
                m.r.reason.c_str());
  }
  if (shown < rows.size()) std::cout << text_printf("   ... %zu more window(s) in the report\n", rows.size() - shown);
  const StatusCounts& c = res.counts;
  std::cout << text_printf("verified %zu, invalidated %zu, missing %zu, refused %zu (of %zu)\n", c.verified, c.invalidated, c.missing,
              c.refused, rows.size());
}

/// The summary over the verified windows: printed, and its entry of
/// merged.json ("summary").
nlohmann::ordered_json render_summary(const MergeResult& res) {
  const VerifiedSummary& v = res.summary;
  const std::string& objective = res.plan.objective;
  nlohmann::ordered_json s;
  s["largest_delta"] = upper_sqrt_text(v.worst_delta2);
  s["largest_dmax"] = upper_sqrt_text(v.worst_dmax2);
  // Σ_k ‖d_k‖² ≤ Σ_k n_k·ny·d_k²: the noise over the verified windows has RMS ≤ this
  s["dmax_over_verified_windows"] = upper_sqrt_text(v.record_dmax2);
  s["dmax2_over_verified_windows_exact"] = rational_to_text(v.record_dmax2);
  s["samples_in_verified_windows"] = v.samples;
  if (objective != "feasibility") s["largest_upper_end_exact"] = rational_to_text(v.worst_upper);
  if (v.any_lower) s["largest_lower_end_exact"] = rational_to_text(v.best_lower);
  s["meaning"] = "each window: this model with the x0 declared for it explains the window's rows with ||Delta|| <= delta "
                 "and noise RMS <= dmax (Theorem 2.1); the windows' Delta are separate";
  std::cout << "over the " << res.counts.verified << " verified window(s) (" << v.samples << " samples): delta <= "
            << upper_sqrt_text(v.worst_delta2) << " on every window, dmax <= " << upper_sqrt_text(v.worst_dmax2)
            << " on every window, noise RMS over them <= " << upper_sqrt_text(v.record_dmax2) << "\n";
  if (v.any_lower && objective != "feasibility")
    std::cout << "largest certified lower end of the objective ("
              << (objective == "min_dmax" ? "dmax^2" : objective == "min_delta" ? "delta^2" : "weighted")
              << ") on a window: " << lower_text(v.best_lower) << " (no Delta within the bound does better there)\n";
  return s;
}

/// The verdict's closing line and exit code.
int render_verdict(const MergeResult& res) {
  StatusCounts all = res.counts;
  if (res.joint) all.add(res.joint->status);
  const bool joint_invalidated = res.joint && res.joint->status == WindowStatus::kInvalidated;
  switch (res.verdict) {
    case MergeVerdict::kInvalidated:
      std::cout << "-> INVALIDATED on " << all.invalidated << (joint_invalidated ? " claim(s)" : " window(s)")
                << ": the model (with the state declared there) cannot explain those rows within the given bounds\n";
      return kExitInvalidated;
    case MergeVerdict::kNotVerified:
      std::cout << "-> INCOMPLETE: " << all.missing + all.refused
                << (res.plan.joint ? " claim(s) (windows or the joint one)" : " window(s)")
                << " without a certificate that passed\n";
      return kExitNotVerified;
    default: return kExitOk;
  }
}

int run_merge(const std::string& dir_text, std::string report_path, bool quiet) {
  const auto started = std::chrono::steady_clock::now();
  auto last = started;
  const MergeResult res = merge_jobs(dir_text, [&](size_t done, size_t total) {
    const auto now = std::chrono::steady_clock::now();
    if (!quiet && (std::chrono::duration<double>(now - last).count() > 2.0 || done == total)) {
      progress_printf("[jobs merge %6.1f s] checked %zu of %zu windows",
                   std::chrono::duration<double>(now - started).count(), done, total);
      last = now;
    }
  });
  if (res.verdict == MergeVerdict::kDataChanged || res.verdict == MergeVerdict::kModelChanged)
    throw InputError(res.changed);
  print_merge_table(res);
  nlohmann::ordered_json report;
  report["format"] = "lpvid-jobs-report/1";
  report["data"] = {{"path", res.plan.data_path}, {"sha256", res.plan.data_sha256}};
  report["model"] = res.plan.model_path;
  report["objective"] = res.plan.objective;
  const StatusCounts& c = res.counts;
  report["counts"] = {{"windows", res.windows.size()}, {"verified", c.verified}, {"invalidated", c.invalidated},
                      {"missing", c.missing},          {"refused", c.refused}};
  if (c.verified > 0) report["summary"] = render_summary(res);
  report["windows"] = nlohmann::ordered_json::array();
  for (const MergedWindow& m : res.windows) report["windows"].push_back(window_json(m, res.plan.objective));
  if (res.joint) report["joint"] = render_joint(*res.joint, res.plan);
  if (report_path.empty()) report_path = (std::filesystem::path(dir_text) / "merged.json").string();
  write_json(report_path, report);
  std::cout << "report " << report_path << "\n";
  return render_verdict(res);
}

}  // namespace

Runner add_jobs_command(CLI::App& app) {
  CLI::App* jobs = app.add_subcommand("jobs", "A long record past one machine: one job per window, then merge")
                       ->require_subcommand(1);
  auto common = std::make_shared<CommonOptions>();
  auto plan = std::make_shared<PlanArgs>();
  CLI::App* p = jobs->add_subcommand("plan", "Write one 'lpvid invalidate' command per window (jobs.txt) and plan.json");
  add_common_options(*p, *common, true);
  common->command = "jobs plan";
  p->add_option("--dir", plan->dir, "folder for the plan, the window models, jobs.txt and (later) the certificates")
      ->required();
  p->add_option("--window-length", plan->window, with_default("rows per window", plan->window))->check(CLI::Range(2L, 1000000000L));
  p->add_option("--min-last", plan->min_last, with_default("a last window shorter than this joins the one before", plan->min_last))
      ->check(CLI::Range(1L, 1000000000L));
  add_renamed_option(*p, "--window", "--window-length", "rows per window, as in diagnose; diagnose's --window is B:E ranges");
  // The jobs write the certificates and SDP files (one per window), 'jobs merge' the report; the plan runs no solver.
  for (const char* ignored : {"--certificate", "--report", "--write-sdpa"})
    refuse_shared_option(*p, ignored, "belongs to the jobs (one per window); 'lpvid jobs merge' writes the report");
  for (const char* ignored : {"--verbose", "--quiet"})
    refuse_shared_option(*p, ignored, "does nothing here: the plan runs no solver and prints no progress (the jobs run with --quiet)");
  p->add_option("--lpvid", plan->lpvid, "the lpvid program the jobs run (default: this one, by absolute path)");
  p->add_flag("--joint", plan->joint,
              "one more job (last in jobs.txt): every window as a record of ONE claim (one Delta for all windows, each "
              "from rest and from its declared x0, one noise bound on the RMS over all samples); merge judges it too");
  auto merge_dir = std::make_shared<std::string>();
  auto merge_report = std::make_shared<std::string>();
  auto merge_quiet = std::make_shared<bool>(false);
  CLI::App* m = jobs->add_subcommand("merge", "Compare every window's certificate (and the joint one of 'plan --joint') with the plan, re-check each exactly, assemble the report");
  m->add_option("--dir", *merge_dir, "the folder of 'lpvid jobs plan'")->required();
  m->add_option("--report", *merge_report, "where to write the merged report (default <dir>/merged.json)");
  m->add_flag("--quiet", *merge_quiet, "no progress lines on stderr");
  return [p, m, common, plan, merge_dir, merge_report, merge_quiet] {
    if (p->parsed()) return run_plan(*common, *plan);
    if (m->parsed()) return run_merge(*merge_dir, *merge_report, *merge_quiet);
    return -1;
  };
}

}  // namespace lpvid::cli
