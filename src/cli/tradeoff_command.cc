// lpvid tradeoff: the delta–dmax trade-off curve (docs/design.md §7.6; a
// command of its own, not an "identify --tradeoff" option): identify and
// certify for each lambda of a grid, print the table, write the curve as
// CSV and plot it with gnuplot.
// The rules are in identify/tradeoff.h.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>

#include "cli/certificate_names.h"
#include "cli/commands.h"
#include "cli/inputs.h"
#include "cli/refused_alias.h"
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
  std::string csv_path;   ///< --csv: the curve (none unless named)
  std::string plots_dir;  ///< --plots DIR: DIR/tradeoff.png, .svg, .plot.json and .csv (no figure unless named)
};

/// The inputs (with --basis in place of the model's) and the run's options printed.
Inputs tradeoff_inputs(TradeoffArgs& a, const std::vector<double>& lambdas) {
  CommonOptions& c = a.common;
  Inputs in = load_inputs(c);
  if (in.mode != ToeplitzMode::kSignal)
    throw InputError("tradeoff: --toeplitz paper is not supported (identification uses the signal form)");
  if (!a.basis.empty()) {
    const std::vector<Monomial> b = parse_basis(a.basis, in.model_q.scheduling);
    in.model_q = with_correction_basis(in.model_q, b);
    in.model_d = with_correction_basis(in.model_d, b);
  }
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
  return in;
}

/// The curve's options; each point printed as a table row while the run goes.
TradeoffOptions tradeoff_options(const TradeoffArgs& a, const Inputs& in, const std::vector<double>& lambdas) {
  TradeoffOptions o;
  o.lambdas = lambdas;
  o.iterate = a.iterate;
  o.max_iterations = a.max_iterations;
  o.rel_tol = a.rel_tol;
  o.unknowns.x0 = a.free_x0;
  o.unknowns.offset = !a.no_offset;
  o.solver.verbose = a.common.verbose;
  o.certify = certify_options(a.common, in);  // the objective and bounds: set per step
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
  return o;
}

/// The CSV (--csv) and the figure (--plots DIR), only those named; returns the PNG written ("" when none).
std::string write_curve_files(const TradeoffArgs& a, const std::vector<TradeoffPoint>& pts) {
  if (!a.csv_path.empty()) {
    write_text_file(a.csv_path, tradeoff_csv(pts), "trade-off CSV");
    std::cout << "  wrote " << a.csv_path << "\n";
  }
  if (a.plots_dir.empty()) return "";
  std::error_code ec;
  std::filesystem::create_directories(a.plots_dir, ec);
  if (!std::filesystem::is_directory(a.plots_dir)) throw IoError("tradeoff: cannot create the folder " + a.plots_dir);
  const std::string png = (std::filesystem::path(a.plots_dir) / "tradeoff.png").string();
  write_text_file(stem_of(png, {".png"}) + ".csv", tradeoff_csv(pts), "trade-off CSV");
  const PlotOutcome po = plot_png(tradeoff_plot(pts, "delta-dmax trade-off: " + a.common.data_path), png);
  std::cout << "  " << (po.ok ? po.message : "no plot: " + po.message + " (the CSV has the curve)") << "\n";
  return po.ok ? png : "";
}

/// One point's entry of the report ("points").
nlohmann::ordered_json point_json(const TradeoffPoint& p, const LpvModel<double>& model) {
  const bool v = p.bounds.verified();
  const auto or_null = [](bool has, auto value) { return has ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr); };
  nlohmann::ordered_json j;
  j["lambda"] = p.lambda;
  j["verified"] = v;
  j["delta"] = or_null(v, p.bounds.delta);
  j["dmax"] = or_null(v, p.bounds.dmax);
  if (v) {
    j["delta2_exact"] = exact_decimal_or_fraction(p.bounds.delta2);
    j["dmax2_exact"] = exact_decimal_or_fraction(p.bounds.dmax2);
  } else {
    j["reason"] = p.bounds.reason;
  }
  j["delta_solver"] = or_null(p.delta_solver >= 0, p.delta_solver);
  j["dmax_solver"] = or_null(p.dmax_solver >= 0, p.dmax_solver);
  j["status"] = to_string(p.status);
  j["relaxation"] = p.relaxation;
  j["solves"] = p.solves;
  j["certificate"] = or_null(v && !p.certificate.empty(), p.certificate);
  j["theta"] = p.layout.size() ? theta_json(model, p.layout, p.p) : nlohmann::ordered_json::object();
  return j;
}

/// The report of the curve.
nlohmann::ordered_json tradeoff_report(const TradeoffArgs& a, const Inputs& in, const std::vector<TradeoffPoint>& pts,
                                       bool monotone, const std::string& plot) {
  nlohmann::ordered_json report;
  int verified = 0, solves = 0;
  nlohmann::ordered_json jp = nlohmann::ordered_json::array();
  for (const TradeoffPoint& p : pts) {
    verified += p.bounds.verified();
    solves += p.solves;
    jp.push_back(point_json(p, in.model_d));
  }
  const bool all = verified == static_cast<int>(pts.size());
  report["command"] = "tradeoff";
  report["status"] = all ? "consistent" : "not_verified";
  report["verified"] = all;
  report["noise_normalisation"] = "rms: ||d||_2 <= dmax*sqrt(n*ny)";
  report["toeplitz_mode"] = a.common.toeplitz;
  report["solver"] = a.common.solver;
  report["relaxation"] = pts.empty() ? "" : pts.front().relaxation;
  report["iterations"] = solves;
  report["points"] = jp;
  report["monotone"] = monotone;
  report["csv"] = a.csv_path.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(a.csv_path);
  report["plots"] = plot.empty() ? nlohmann::ordered_json::array() : nlohmann::ordered_json::array({plot});
  report["samples"] = in.exp_q.n();
  return report;
}

bool all_verified(const std::vector<TradeoffPoint>& pts) {
  for (const TradeoffPoint& p : pts)
    if (!p.bounds.verified()) return false;
  return true;
}

int run_tradeoff(TradeoffArgs& a) {
  check_output_file(a.csv_path, "curve");
  CommonOptions& c = a.common;
  const std::vector<double> lambdas = a.lambdas.empty() ? default_lambda_grid() : a.lambdas;
  const Inputs in = tradeoff_inputs(a, lambdas);
  const TradeoffOptions o = tradeoff_options(a, in, lambdas);
  // the per-lambda certificates only under a stem the user named
  const std::string named = named_certificate_path(c);
  const std::string stem = named.empty() ? "" : stem_of(named, {".cert.json", ".json"});
  std::cout << std::left << std::setw(9) << "lambda" << std::setw(13) << "delta" << std::setw(13) << "dmax"
            << std::setw(10) << "verified" << std::setw(13) << "delta_relax" << std::setw(13) << "dmax_relax"
            << std::setw(7) << "solves" << "time[s]\n";
  auto solver = make_solver_for_cli(c.solver, c.write_sdpa);
  std::vector<TradeoffPoint> pts = tradeoff_curve(in, o, *solver);
  if (!stem.empty()) write_tradeoff_certificates(pts, stem);
  std::cout << "\n  delta, dmax  = certified (the exact verifier accepted "
            << (stem.empty() ? std::string("the certificate in memory; ") + kNoCertificateFile + ")"
                             : stem + ".lambda<k>.cert.json)")
            << "\n"
            << "  *_relax      = the identification relaxation's own values (solver)\n";
  const std::string mono = tradeoff_monotonicity_violation(pts, 1e-3, 1e-6);
  if (!mono.empty()) std::cout << "  NOTE: the certified curve is not monotone in lambda: " << mono << "\n";
  const std::string plot = write_curve_files(a, pts);
  write_json(c.report_path, tradeoff_report(a, in, pts, mono.empty(), plot));
  return all_verified(pts) ? kExitOk : kExitNotVerified;
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
  cmd->add_option("--csv", a->csv_path, "where to write the curve (no CSV unless named)");
  cmd->add_option("--plots", a->plots_dir, "folder for the figure: DIR/tradeoff.png (.svg, .plot.json, .csv); no figure unless named");
  add_renamed_option(*cmd, "--plot", "--plots", "a folder, as in compare and diagnose");
  add_refused_option(*cmd, "--no-plot", "is gone: tradeoff draws no figure unless --plots DIR is given");
  return [cmd, a] { return cmd->parsed() ? run_tradeoff(*a) : -1; };
}

}  // namespace lpvid::cli
