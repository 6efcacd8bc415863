// lpvid identify: Theorem 3.1 (docs/design.md §8) + certificate (docs/design.md §10).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "cli/class_interval_report.h"
#include "cli/commands.h"
#include "cli/inputs.h"
#include "cli/records_report.h"
#include "cli/report.h"
#include "core/file_io.h"
#include "core/input_error.h"
#include "certify/certify.h"
#include "identify/fix_and_certify.h"
#include "model/model_file.h"
#include "solvers/external_solvers.h"
#include "cli/help_text.h"

namespace lpvid::cli {
namespace {

struct IdentifyArgs {
  CommonOptions common;
  bool iterate = false;
  int max_iterations = IdentifyOptions{}.max_iterations;
  double rel_tol = IdentifyOptions{}.rel_tol;
  bool free_x0 = false;
  bool no_offset = false;
  std::string method = "relaxation";
  long alt_taps = IdentifyOptions{}.taps;
  std::vector<std::string> basis;  ///< --basis: replaces the model's correction basis
  std::string model_out;           ///< --model-out: the identified exact model
  ClassIntervalArgs class_interval;
};

/// The identification options of the command line.
IdentifyOptions identify_options(const IdentifyArgs& a, const Inputs& in) {
  IdentifyOptions opt;
  opt.objective = in.objective;
  opt.iterate = a.iterate;
  opt.method = a.method == "alternating" ? IdentifyMethod::kAlternating : IdentifyMethod::kRelaxation;
  opt.taps = a.alt_taps;
  if (opt.method == IdentifyMethod::kAlternating && a.iterate)
    throw InputError("--iterate belongs to --method relaxation; the alternating method always iterates");
  opt.max_iterations = a.max_iterations;
  opt.rel_tol = a.rel_tol;
  opt.unknowns.x0 = a.free_x0;
  opt.unknowns.offset = !a.no_offset;
  opt.solver.verbose = a.common.verbose;
  return opt;
}

/// The inputs, with --basis in place of the model's correction basis.
Inputs identify_inputs(IdentifyArgs& a) {
  Inputs in = load_inputs(a.common);
  if (!a.basis.empty()) {
    const std::vector<Monomial> basis = parse_basis(a.basis, in.model_q.scheduling);
    in.model_q.correction = zero_correction<Rational>(basis, in.model_q.nx, in.model_q.nu);
    in.model_d.correction = zero_correction<double>(basis, in.model_d.nx, in.model_d.nu);
  }
  print_options(a.common, in, "identify");
  std::cout << "  basis       ";
  for (const Monomial& f : in.model_q.correction.basis) std::cout << f.text(in.model_q.scheduling) << " ";
  std::cout << "\n";
  if (in.mode != ToeplitzMode::kSignal)
    throw InputError("--toeplitz paper is supported by 'invalidate' (fixed model) only; identification uses the "
                     "signal form (T_z built from the simulated z)");
  return in;
}

/// Theorem 3.1's solves, printed.
void print_solves(const IdentifyResult& res) {
  std::cout << "\nTheorem 3.1: " << res.relaxation << "\n"
            << "  unknowns    " << res.names.size() << " (" << res.free_directions << " free after pinning)\n";
  if (res.pinned_samples > 0)
    std::cout << "  pinned      z_k = 0 for k < " << res.pinned_samples
              << ": the relaxation keeps these samples of z at zero, and w_k = 0 there\n";
  for (const auto& it : res.iterates)
    std::cout << "  solve " << it.index << "     " << to_string(it.status) << "  delta = " << std::sqrt(std::max(0.0, it.delta2))
              << "  dmax = " << std::sqrt(std::max(0.0, it.dmax2)) << "  (solver values, " << it.seconds << " s)\n";
}

/// The SDP back end found no solution: no model and no bound (report and exit code).
int render_no_solution(const IdentifiedModel& id, const IdentifyOptions& opt, const std::string& report_path) {
  const IdentifyResult& res = id.fit;
  std::cout << "  the SDP backend ended with '" << to_string(res.status) << "': no model and no bound\n";
  nlohmann::ordered_json report;
  report["status"] = to_string(res.status);
  report["verified"] = false;
  report["delta"] = nullptr;
  report["dmax"] = nullptr;
  report["message"] = res.message;
  // The relaxation (and the alternating method) are restrictions of the
  // BMI: their infeasibility says nothing about the model class.
  if (id.outcome() == CertifyOutcome::kUndecided) {
    report["status"] = "undecided";
    std::cout << "  -> UNDECIDED: the " << (opt.method == IdentifyMethod::kAlternating ? "alternating (local) method" : "relaxation")
              << " found no consistent model at the given bounds; its infeasibility is not an invalidation of the model class\n";
  }
  write_json(report_path, report);
  return exit_code(id.outcome());
}

/// The report of an identification with a solution (without class interval and model file).
nlohmann::ordered_json identify_report(const IdentifyArgs& a, const Inputs& in, const IdentifiedModel& id,
                                       const CertificateFiles& files) {
  const IdentifyResult& res = id.fit;
  const CertifiedBounds& b = id.bounds;
  nlohmann::ordered_json report = bounds_json(b, a.common.toeplitz, a.common.solver, files);
  report["method"] = a.method;
  report["relaxation"] = res.relaxation;
  report["iterations"] = static_cast<int>(res.iterates.size());
  report["pinned_samples"] = res.pinned_samples;
  nlohmann::ordered_json its = nlohmann::ordered_json::array();
  for (const auto& it : res.iterates)
    its.push_back({{"solve", it.index}, {"status", to_string(it.status)}, {"delta_solver", std::sqrt(std::max(0.0, it.delta2))},
                   {"dmax_solver", std::sqrt(std::max(0.0, it.dmax2))}, {"objective", it.objective}, {"seconds", it.seconds}});
  report["iterates"] = its;
  report["theta"] = theta_json(in.model_d, res.layout, id.fixed.value);
  report["samples"] = in.exp_q.n();
  // each record's figures for the identified model (θ folded in, x0 as identified)
  std::cout << add_record_figures(report, in.records, convert_model<double>(id.fixed.model),
                                  nearest_double(with_fixed_initial_states(in.exp_q, id.fixed)), b);
  if (in.objective.kind != BoundObjective::Kind::kFeasibility) {
    report["interval"] = interval_json(b, in.objective, files);
    report["interval"]["scope"] = "the model with the identified theta fixed (not the model class)";
  }
  return report;
}

/// --model-out: the exact model the bounds are about (θ folded in, x0 and φ as identified).
void write_identified_model(const IdentifiedModel& id, const std::string& path, nlohmann::ordered_json& report) {
  LpvModel<Rational> m = id.fixed.model;
  // θ is folded into C and D: a correction basis with no fixed part left
  // would only make 'invalidate' say that it ignores it
  const auto zero = [](const std::vector<Mat<Rational>>& v) {
    return std::all_of(v.begin(), v.end(), [](const Mat<Rational>& x) { return x.isZero(); });
  };
  if (zero(m.correction.A) && zero(m.correction.B)) m.correction = {};
  write_model_file(path, m);
  report["model_out"] = path;
  std::cout << "  model       " << path << " (the identified model, exact; 'lpvid invalidate --model " << path
            << "' re-certifies it)\n";
}

int run_identify(IdentifyArgs& a) {
  if (!a.model_out.empty()) check_output_file(a.model_out, "--model-out");
  Inputs in = identify_inputs(a);
  const IdentifyOptions opt = identify_options(a, in);
  CertifyOptions co = certify_options(a.common, in);
  co.solver = opt.solver;
  auto solver = make_solver_for_cli(a.common.solver, a.common.write_sdpa);
  IdentifiedModel id = identify_and_certify(in, opt, co, *solver);
  print_solves(id.fit);
  if (!has_solution(id.fit.status)) return render_no_solution(id, opt, a.common.report_path);

  std::optional<ClassInterval> klass;
  if (!a.class_interval.skip && id.bounds.verified() && in.objective.kind != BoundObjective::Kind::kFeasibility) {
    ClassBoundOptions cbo;
    cbo.unknowns = opt.unknowns;
    cbo.box_fraction = a.class_interval.box;
    cbo.max_leaves = a.class_interval.leaves;
    cbo.stall_splits = a.class_interval.stall;
    klass = class_interval(id, in, co, cbo, *solver);
    adopt_class_optimum(id, *klass);  // the class optimum, when certified lower, replaces the found theta
  }
  const CertifiedBounds& b = id.bounds;
  const std::string certificate = named_certificate_path(a.common);
  const CertificateFiles files = write_named_certificates(b, certificate);
  if (!id.taps_note.empty()) std::cout << "\n  the iterate's own Delta did not certify (" << id.taps_note << "); solved again\n";
  std::cout << "\nCertified bounds of the identified model (Theorem 2.1, Delta form, exact check)\n"
            << bounds_text(b, files,
                           "for this theta: the lower end bounds the model with the identified theta fixed, not the "
                           "model class (another theta may do better)");
  nlohmann::ordered_json report = identify_report(a, in, id, files);
  if (klass) report["class_interval"] = report_class_interval(*klass, b, certificate);
  if (!a.model_out.empty()) write_identified_model(id, a.model_out, report);
  write_json(a.common.report_path, report);
  // Not exit_code(id.outcome): an "invalidated" or "undecided" certification
  // here is about the identified theta only, never the model class.
  return b.verified() ? kExitOk : kExitNotVerified;
}

}  // namespace

Runner add_identify_command(CLI::App& app) {
  auto args = std::make_shared<IdentifyArgs>();
  CLI::App* cmd = app.add_subcommand("identify", "Theorem 3.1: identify the correction S_C(rho) with certified bounds");
  add_common_options(*cmd, args->common, true);
  cmd->add_flag("--iterate", args->iterate, "re-linearise at each solution until the objective stalls (beyond the paper)");
  cmd->add_option("--max-iterations", args->max_iterations, "solves of --iterate, or Delta steps of --method alternating")->capture_default_str()->check(CLI::Range(1, 1000));
  cmd->add_option("--rel-tol", args->rel_tol, "stop --iterate (or --method alternating) when the objective improves by less (relative)")->capture_default_str();
  cmd->add_option("--method", args->method,
                  "relaxation: the paper's linearised BMI (default); alternating: Delta/theta block-coordinate descent "
                  "in the Delta form, every iterate feasible for the true BMI (fast for long records)")
      ->check(CLI::IsMember({"relaxation", "alternating"}));
  cmd->add_option("--alt-taps", args->alt_taps, with_default("FIR taps of Delta in --method alternating", args->alt_taps))
      ->check(CLI::Range(1L, 100000L));
  cmd->add_flag("--free-x0", args->free_x0, "the initial state is an unknown too");
  cmd->add_option("--basis", args->basis, "correction basis, e.g. 1,rho1,rho1*rho2 (replaces the model's)")
      ->delimiter(',');
  cmd->add_flag("--no-offset", args->no_offset, "do not identify the offset phi even if the model declares one");
  cmd->add_option("--model-out", args->model_out,
                  "write the identified model (exact, the one the bounds are about) as an lpvid-model/1 file");
  add_class_interval_options(cmd, args->class_interval);
  return [cmd, args] { return cmd->parsed() ? run_identify(*args) : -1; };
}

}  // namespace lpvid::cli
