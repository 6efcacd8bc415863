// lpvid certify: an outside SDP solver's solution of the Theorem 2.1 program
// (written by `lpvid invalidate --write-sdpa`) turned into a checked
// certificate (certify/outside_solution.h).
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/refused_alias.h"
#include "cli/inputs.h"
#include "cli/records_report.h"
#include "cli/report.h"
#include "core/input_error.h"
#include "certify/outside_solution.h"

namespace lpvid::cli {
namespace {

struct CertifyArgs {
  CommonOptions common;
  std::string program_path, solution_path, format = "csdp";
  int exit_code = 0;
};

int run_certify(CertifyArgs& a) {
  CommonOptions& c = a.common;
  Inputs in = load_inputs(c);
  if (in.mode != ToeplitzMode::kSignal)
    throw InputError("certify: --toeplitz paper has no Delta-form program; outside solutions are read for the signal mode only");
  c.solver = "outside (" + a.format + " solution file " + a.solution_path + ")";  // for the printed options
  print_options(c, in, "certify");
  const CertifyOptions co = certify_options(c, in);
  const OutsideSolution outside = read_outside_solution(
      a.program_path, a.solution_path, a.format == "sdpa" ? SolutionFormat::kSdpa : SolutionFormat::kCsdp, a.exit_code);
  const CertifiedBounds b = certify_outside_solution(in.model_q, in.exp_q, co, outside);
  const CertificateFiles files = write_named_certificates(b, named_certificate_path(c));
  std::cout << "\nTheorem 2.1 (Delta form) solved outside: " << a.solution_path << " for " << a.program_path << "\n"
            << bounds_text(b, files);
  nlohmann::ordered_json report = bounds_json(b, c.toeplitz, c.solver, files);
  report["relaxation"] = "none (fixed model: Theorem 2.1 is an LMI)";
  report["program"] = a.program_path;
  report["solution"] = a.solution_path;
  report["samples"] = in.exp_q.n();
  std::cout << add_record_figures(report, in.records, in.model_d, in.exp_d, b);
  const CertifyOutcome outcome = b.outcome;
  if (in.objective.kind == BoundObjective::Kind::kFeasibility)
    report["verdict"] = outcome == CertifyOutcome::kVerified ? "consistent" : to_string(outcome);
  write_json(c.report_path, report);
  return exit_code(outcome);
}

}  // namespace

Runner add_certify_command(CLI::App& app) {
  auto args = std::make_shared<CertifyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "certify", "an outside SDP solver's solution of the Theorem 2.1 program (lpvid invalidate --write-sdpa) -> checked certificate");
  add_common_options(*cmd, args->common, true);
  cmd->add_option("--program", args->program_path, "the SDPA file written by 'lpvid invalidate --write-sdpa'")
      ->required();
  cmd->add_option("--solution", args->solution_path, "the outside solver's solution file (csdp: 'csdp P.dat-s P.sol')")
      ->required();
  cmd->add_option("--solution-format", args->format, "csdp (default: the csdp program's .sol) or sdpa (the sdpa program's output)")
      ->check(CLI::IsMember({"csdp", "sdpa"}));
  // The program was solved outside: no backend runs here, and the program file exists already.
  for (const char* ignored : {"--solver", "--verbose", "--write-sdpa"})
    refuse_shared_option(*cmd, ignored, "does nothing here: the program was solved outside (--solution); give it to "
                                        "'lpvid invalidate --write-sdpa' instead");
  cmd->add_option("--solver-exit-code", args->exit_code,
                  "the outside solver's exit status (csdp: 0 optimal, 1 primal infeasible, 2 dual infeasible, 3 partial, ...)");
  return [cmd, args] { return cmd->parsed() ? run_certify(*args) : -1; };
}

}  // namespace lpvid::cli
