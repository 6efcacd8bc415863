// lpvid tradeoff: the delta–dmax trade-off curve (SPEC §4 last item; a
// command of its own, not an "identify --tradeoff" option): identify and
// certify for each lambda of a grid, print the table, write the curve as
// CSV and plot it with gnuplot.
// The rules are in identify/tradeoff.h.
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>

#include "cli/certificate_names.h"
#include "cli/commands.h"
#include "cli/inputs.h"
#include "cli/report.h"
#include "core/decimal_rounding.h"
#include "core/file_io.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "identify/basis_selection.h"
#include "identify/tradeoff.h"
#include "plot/tradeoff_plot.h"
#include "model/model_file.h"
#include "solvers/external_solvers.h"

namespace lpvid::cli {
namespace {

struct TradeoffArgs {
  CommonOptions common;
  std::vector<double> lambdas;
  bool iterate = false;
  int max_iterations = IdentifyOptions{}.max_iterations;
  double rel_tol = IdentifyOptions{}.rel_tol;
  bool free_x0 = false;
  bool no_offset = false;
  std::vector<std::string> basis;
  std::string csv_path = "tradeoff.csv";
  std::string plot_path;  ///< default: the CSV path with .png
  bool no_plot = false;
};

int run_tradeoff(TradeoffArgs& a) {
  check_output_file(a.csv_path, "curve");
  check_output_file(a.plot_path, "plot");
  CommonOptions& c = a.common;
  Inputs in = load_inputs(c);
  if (in.mode != ToeplitzMode::kSignal)
    throw InputError("tradeoff: --toeplitz paper is not supported (identification uses the signal form)");
  if (!a.basis.empty()) {
    const std::vector<Monomial> b = parse_basis(a.basis, in.model_q.scheduling);
    in.model_q = with_correction_basis(in.model_q, b);
    in.model_d = with_correction_basis(in.model_d, b);
  }
  const std::vector<double> lambdas = a.lambdas.empty() ? default_lambda_grid() : a.lambdas;
  std::cout << "lpvid tradeoff\n"
            << data_lines(c, in)
            << "  model       " << c.model_path << "\n"
            << "  basis       " << basis_text(in.model_q.correction.basis, in.model_q.scheduling) << "\n"
            << "  objective   minimise lambda*delta^2 + (1-lambda)*dmax^2 for lambda in";
  for (double l : lambdas) std::cout << " " << l;
  std::cout << "\n"
            << "  method      " << (a.iterate ? "Theorem 3.1 with iterated re-linearisation (beyond the paper)"
                                              : "Theorem 3.1 relaxation at S_I (paper)")
            << ", then Theorem 2.1 certificate (Delta form, exact check) per lambda\n"
            << "  solver      " << c.solver << "\n"
            << "  noise       dmax is the RMS bound: ||d||_2 <= dmax*sqrt(n*ny)\n\n";

  TradeoffOptions o;
  o.lambdas = lambdas;
  o.iterate = a.iterate;
  o.max_iterations = a.max_iterations;
  o.rel_tol = a.rel_tol;
  o.unknowns.x0 = a.free_x0;
  o.unknowns.offset = !a.no_offset;
  o.solver.verbose = c.verbose;
  o.certify = certify_options(c, in);  // the objective and bounds: set per step
  const std::string stem = stem_of(certificate_path(c), {".cert.json", ".json"});
  std::cout << std::left << std::setw(9) << "lambda" << std::setw(13) << "delta" << std::setw(13) << "dmax"
            << std::setw(10) << "verified" << std::setw(13) << "delta_relax" << std::setw(13) << "dmax_relax"
            << std::setw(7) << "solves" << "time[s]\n";
  o.on_point = [](const TradeoffPoint& p) {
    const bool v = p.bounds.verified();
    char t[32];
    std::snprintf(t, sizeof t, "%.2f", p.seconds);
    // certified cells rounded up (printed = certified); the solver's own values as they are
    std::cout << std::left << std::setw(9) << p.lambda << std::setw(13) << (v ? upper_sqrt_text(p.bounds.delta2) : "-")
              << std::setw(13) << (v ? upper_sqrt_text(p.bounds.dmax2) : "-") << std::setw(10) << (v ? "true" : "false")
              << std::setw(13) << cell_text(p.delta_solver) << std::setw(13) << cell_text(p.dmax_solver) << std::setw(7)
              << p.solves << t << (v ? "" : "   " + p.bounds.reason) << "\n"
              << std::flush;
  };
  auto solver = make_solver_for_cli(c.solver, c.write_sdpa);
  std::vector<TradeoffPoint> pts = tradeoff_curve(in.model_q, in.model_d, in.exp_q, in.exp_d, o, *solver);
  write_tradeoff_certificates(pts, stem);

  std::cout << "\n  delta, dmax  = certified (the exact verifier accepted <stem>.lambda<k>.cert.json)\n"
            << "  *_relax      = the identification relaxation's own values (solver)\n";
  const std::string mono = tradeoff_monotonicity_violation(pts, 1e-3, 1e-6);
  if (!mono.empty()) std::cout << "  NOTE: the certified curve is not monotone in lambda: " << mono << "\n";

  write_text_file(a.csv_path, tradeoff_csv(pts), "trade-off CSV");
  std::cout << "  wrote " << a.csv_path << "\n";
  std::string plot;
  if (!a.no_plot) {
    const std::string png = a.plot_path.empty() ? stem_of(a.csv_path, {".csv"}) + ".png" : a.plot_path;
    const PlotOutcome po = plot_png(tradeoff_plot(pts, "delta-dmax trade-off: " + c.data_path), png);
    std::cout << "  " << (po.ok ? po.message : "no plot: " + po.message + " (the CSV has the curve)") << "\n";
    if (po.ok) plot = png;
  }

  nlohmann::ordered_json report;
  int verified = 0, solves = 0;
  nlohmann::ordered_json jp = nlohmann::ordered_json::array();
  for (const TradeoffPoint& p : pts) {
    const bool v = p.bounds.verified();
    verified += v;
    solves += p.solves;
    nlohmann::ordered_json j;
    j["lambda"] = p.lambda;
    j["verified"] = v;
    j["delta"] = v ? nlohmann::ordered_json(p.bounds.delta) : nlohmann::ordered_json(nullptr);
    j["dmax"] = v ? nlohmann::ordered_json(p.bounds.dmax) : nlohmann::ordered_json(nullptr);
    if (v) {
      j["delta2_exact"] = exact_decimal_or_fraction(p.bounds.delta2);
      j["dmax2_exact"] = exact_decimal_or_fraction(p.bounds.dmax2);
    } else {
      j["reason"] = p.bounds.reason;
    }
    j["delta_solver"] = p.delta_solver >= 0 ? nlohmann::ordered_json(p.delta_solver) : nlohmann::ordered_json(nullptr);
    j["dmax_solver"] = p.dmax_solver >= 0 ? nlohmann::ordered_json(p.dmax_solver) : nlohmann::ordered_json(nullptr);
    j["status"] = to_string(p.status);
    j["relaxation"] = p.relaxation;
    j["solves"] = p.solves;
    j["certificate"] = v ? nlohmann::ordered_json(p.certificate) : nlohmann::ordered_json(nullptr);
    j["theta"] = p.layout.size() ? theta_json(in.model_d, p.layout, p.p) : nlohmann::ordered_json::object();
    jp.push_back(j);
  }
  report["command"] = "tradeoff";
  report["status"] = verified == static_cast<int>(pts.size()) ? "consistent" : "not_verified";
  report["verified"] = verified == static_cast<int>(pts.size());
  report["noise_normalisation"] = "rms: ||d||_2 <= dmax*sqrt(n*ny)";
  report["toeplitz_mode"] = c.toeplitz;
  report["solver"] = c.solver;
  report["relaxation"] = pts.empty() ? "" : pts.front().relaxation;
  report["iterations"] = solves;
  report["points"] = jp;
  report["monotone"] = mono.empty();
  report["csv"] = a.csv_path;
  report["plots"] = plot.empty() ? nlohmann::ordered_json::array() : nlohmann::ordered_json::array({plot});
  report["samples"] = in.exp_q.n();
  write_json(c.report_path, report);
  return verified == static_cast<int>(pts.size()) ? kExitOk : kExitNotVerified;
}

}  // namespace

Runner add_tradeoff_command(CLI::App& app) {
  auto a = std::make_shared<TradeoffArgs>();
  CLI::App* cmd = app.add_subcommand(
      "tradeoff", "delta-dmax trade-off curve: identify + certify for a grid of lambda, CSV and PNG plot");
  add_common_options(*cmd, a->common, false);
  cmd->add_option("--lambdas", a->lambdas, "lambda grid, e.g. 0.1,0.5,0.9 (default 11 values 0.02..0.98)")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_flag("--iterate", a->iterate, "re-linearise at each solution until the objective stalls (beyond the paper)");
  cmd->add_option("--max-iterations", a->max_iterations, "solves of --iterate per lambda")->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--rel-tol", a->rel_tol, "stop --iterate when the objective improves by less")->capture_default_str();
  cmd->add_flag("--free-x0", a->free_x0, "the initial state is an unknown too");
  cmd->add_flag("--no-offset", a->no_offset, "do not identify the offset phi even if the model declares one");
  cmd->add_option("--basis", a->basis, "correction basis, e.g. 1,rho1,rho1*rho2 (replaces the model's)")->delimiter(',');
  cmd->add_option("--csv", a->csv_path, "where to write the curve (default tradeoff.csv)");
  auto* plot = cmd->add_option("--plot", a->plot_path, "where to write the PNG plot (default: the CSV path with .png)");
  cmd->add_flag("--no-plot", a->no_plot, "do not run gnuplot")->excludes(plot);
  return [cmd, a] { return cmd->parsed() ? run_tradeoff(*a) : -1; };
}

}  // namespace lpvid::cli
