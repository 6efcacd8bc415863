// lpvid invalidate: Theorem 2.1 for a fixed model (docs/design.md §7) + certificate.
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/inputs.h"
#include "cli/records_report.h"
#include "cli/report.h"
#include "core/input_error.h"
#include "certify/certify.h"
#include "certify/outside_solution.h"
#include "solvers/sdpa_sidecar.h"
#include "solvers/external_solvers.h"

namespace lpvid::cli {
namespace {

/// The verdict at a fixed (delta, dmax): printed, and its report fields.
void render_feasibility(nlohmann::ordered_json& report, const CertifiedBounds& b, const CertificateFiles& files,
                        const CommonOptions& c) {
  const CertifyOutcome outcome = b.outcome;
  report["verdict"] = outcome == CertifyOutcome::kVerified ? "consistent" : to_string(outcome);
  if (outcome != CertifyOutcome::kVerified) report["status"] = to_string(outcome);
  if (outcome == CertifyOutcome::kInvalidated) {
    report["certificate"] = files.certificate.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(files.certificate);
    report["verified"] = true;
    std::cout << "  -> INVALIDATED at delta = " << c.delta_text << ", dmax = " << c.dmax_text
              << ": no causal LTI Delta with ||Delta||_inf <= delta and no noise with RMS <= dmax explain the data.\n"
              << "     certificate " << (files.certificate.empty() ? "in memory" : files.certificate)
              << (b.closed_form.empty() ? " (claim \"invalidated\", a dual point of the full-horizon problem)"
                                        : " (claim \"invalidated\", form zero_delta: " + b.closed_form +
                                              ", Delta = 0 leaves d = r)")
              << ", checked exactly: " << b.lower.verifier_details << "\n";
    if (files.certificate.empty()) std::cout << "     " << kNoCertificateFile << "\n";
  }
  if (outcome == CertifyOutcome::kUndecided) {
    std::cout << "  -> UNDECIDED at delta = " << c.delta_text << ", dmax = " << c.dmax_text
              << ": neither a consistency nor an invalidation certificate passed the exact check\n";
  }
}

int run_invalidate(CommonOptions& c) {
  Inputs in = load_inputs(c);
  print_options(c, in, "invalidate");
  if (!in.model_q.offset.basis.empty() && in.model_q.offset.values.empty())
    throw InputError(c.model_path + ": offset: the offset values are unknown; give \"values\" or use 'lpvid identify'");
  // --write-sdpa: the Theorem 2.1 program itself, for an outside solver and
  // `lpvid certify --solution` (certify/outside_solution.h).
  const bool export_program = !c.write_sdpa.empty() && in.mode == ToeplitzMode::kSignal;
  auto solver = make_solver_for_cli(c.solver, export_program ? "" : c.write_sdpa);
  const CertifyOptions co = certify_options(c, in);
  if (export_program) {
    write_sdpa_with_sidecar(theorem21_program(in.model_q, in.exp_q, co).delta.program, c.write_sdpa);
    std::cout << "wrote the Theorem 2.1 program " << c.write_sdpa << " and its sidecar " << c.write_sdpa
              << ".json (scalings, variable meanings); solve it with e.g. 'csdp " << c.write_sdpa
              << " P.sol', then 'lpvid certify' with the same options and --program, --solution\n";
  }
  const CertifiedBounds b = certify_fixed(in.model_q, in.exp_q, in.mode, co, *solver);
  const CertificateFiles files = write_named_certificates(b, named_certificate_path(c));
  std::cout << "\nTheorem 2.1 (" << (in.mode == ToeplitzMode::kSignal ? "Delta form" : "w form, paper T_z")
            << "), the model as written: "
            << (in.model_q.correction.basis.empty() ? std::string("no correction")
                                                    : "the correction basis is ignored (theta = 0)")
            << ", x0 as in the model file\n"
            << bounds_text(b, files);
  nlohmann::ordered_json report = bounds_json(b, c.toeplitz, c.solver, files);
  report["relaxation"] = "none (fixed model: Theorem 2.1 is an LMI)";
  report["model_as_written"] = "theta = 0 (any correction basis is ignored), x0 as in the model file";
  report["iterations"] = 1;
  report["samples"] = in.exp_q.n();
  std::cout << add_record_figures(report, in.records, in.model_d, in.exp_d, b);
  if (in.objective.kind == BoundObjective::Kind::kFeasibility)
    render_feasibility(report, b, files, c);
  else
    report["interval"] = interval_json(b, in.objective, files);
  const CertifyOutcome outcome = b.outcome;
  write_json(c.report_path, report);
  return exit_code(outcome);
}

}  // namespace

Runner add_invalidate_command(CLI::App& app) {
  auto args = std::make_shared<CommonOptions>();
  CLI::App* cmd = app.add_subcommand("invalidate", "Theorem 2.1: bounds for a fixed model, with a certificate");
  add_common_options(*cmd, *args, true);
  return [cmd, args] { return cmd->parsed() ? run_invalidate(*args) : -1; };
}

}  // namespace lpvid::cli
