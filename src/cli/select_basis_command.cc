// lpvid select-basis: the paper's Appendix algorithm (docs/design.md §8.5):
// grow the correction basis until a model is consistent at the given bounds,
// then prune it. The rules are in identify/basis_selection.h.
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>

#include "cli/certificate_names.h"
#include "cli/commands.h"
#include "cli/inputs.h"
#include "cli/report.h"
#include "core/input_error.h"
#include "identify/basis_selection.h"
#include "solvers/external_solvers.h"
#include "cli/help_text.h"
#include "cli/refused_alias.h"

namespace lpvid::cli {
namespace {

struct SelectArgs {
  CommonOptions common;
  int max_degree = BasisSelectionOptions{}.max_degree;
  bool iterate = false;
  int max_iterations = IdentifyOptions{}.max_iterations;
  double rel_tol = IdentifyOptions{}.rel_tol;
  bool free_x0 = false;
  bool no_offset = false;
  bool no_prune = false;
  bool no_class = false;                                ///< --no-class-bound
  double class_box = ClassBoundOptions{}.box_fraction;  ///< --class-box
  int class_leaves = ClassBoundOptions{}.max_leaves;    ///< --class-leaves
};

class Table {
 public:
  explicit Table(size_t basis_width) : w_(basis_width) {}
  void header() const {
    std::cout << std::left << std::setw(5) << "step" << std::setw(9) << "phase" << std::setw(static_cast<int>(w_) + 2)
              << "basis" << std::setw(17) << "verdict" << std::setw(11) << "delta" << std::setw(11) << "dmax"
              << std::setw(13) << "dmax_relax" << std::setw(7) << "solves" << std::setw(9) << "time[s]"
              << "note\n";
  }
  void row(const BasisStep& s) const {
    const bool v = s.verdict == BasisVerdict::kConsistent;
    std::string note = s.same_as >= 0 ? "same as step " + std::to_string(s.same_as) : "";
    if (s.kept) note += std::string(note.empty() ? "" : "; ") + "removal kept";
    if (s.phase == "remove" && !s.kept) note += std::string(note.empty() ? "" : "; ") + "removal undone";
    char t[32];
    std::snprintf(t, sizeof t, "%.2f", s.seconds);
    std::cout << std::left << std::setw(5) << s.index << std::setw(9) << s.phase << std::setw(static_cast<int>(w_) + 2)
              << s.basis_text << std::setw(17) << to_string(s.verdict) << std::setw(11)
              << (v ? cell_text(s.bounds.delta) : "-") << std::setw(11) << (v ? cell_text(s.bounds.dmax) : "-") << std::setw(13)
              << cell_text(s.dmax_relaxation) << std::setw(7) << s.solves << std::setw(9) << t << note << "\n"
              << std::flush;
  }

 private:
  size_t w_;
};

void print_legend(const CommonOptions& c, bool iterate) {
  std::cout << "\n  consistent      = a certificate at delta = " << c.delta_text << ", dmax = " << c.dmax_text
            << " passed the exact verifier (delta, dmax columns)\n"
            << "  cannot_explain  = a class certificate (lpvid-verify certificate checks it): no theta of this basis, with\n"
            << "                    any Delta of norm <= delta and any noise of RMS <= dmax, explains the data\n"
            << "  box_invalidated = the same for the theta of a box around the step's theta only (another theta may\n"
            << "                    explain the data: for the algorithm it counts as not decided)\n"
            << "  not_decided     = no consistent model found and no class certificate: the solver's verdict on "
            << (iterate ? "the best model of the iterated relaxation (Theorem 2.1)"
                        : "the relaxation of Theorem 3.1 at S_I (conservative: one relaxation step cannot make large corrections)")
            << "\n"
            << "  dmax_relax      = the smallest dmax at the given delta that the (iterated) relaxation reached\n";
}

/// "every theta of the basis" or "box of k parameters around …, radius a … b; m free".
std::string class_region_text(const ClassBoundResult& k) {
  if (k.whole_class) return "every theta of the basis";
  double lo = 0, hi = 0;
  long boxed = 0;
  for (Eigen::Index i = 0; i < k.radius.size(); ++i)
    if (k.radius(i) > 0) {
      lo = boxed == 0 ? k.radius(i) : std::min(lo, k.radius(i));
      hi = std::max(hi, k.radius(i));
      ++boxed;
    }
  return "box of " + std::to_string(boxed) + " parameters, half-widths " + cell_text(lo) + " to " + cell_text(hi) + ", " +
         std::to_string(k.free.size()) + " free; " + std::to_string(k.leaves) + (k.leaves == 1 ? " leaf" : " leaves");
}

nlohmann::ordered_json class_json(const BasisStep& s) {
  if (!s.klass) return nullptr;
  const ClassBoundResult& k = *s.klass;
  nlohmann::ordered_json j{{"certified", k.certified()}};
  if (!k.certified()) {
    j["reason"] = k.reason;
    return j;
  }
  j["certificate"] = s.class_certificate.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(s.class_certificate);
  j["region"] = k.whole_class ? "whole_class" : "box";
  j["center"] = k.whole_class ? "none" : s.class_centered_at_fit ? "identified" : "zero";
  nlohmann::ordered_json box = nlohmann::ordered_json::array();
  for (size_t i = 0; i < k.names.size(); ++i)
    if (k.radius(static_cast<Eigen::Index>(i)) > 0)
      box.push_back({{"name", k.names[i]}, {"center", k.center(static_cast<Eigen::Index>(i))},
                     {"radius", k.radius(static_cast<Eigen::Index>(i))}});
  j["box"] = box;
  j["free_parameters"] = k.free.size();
  j["leaves"] = k.leaves;
  return j;
}

/// The selection's options from the command line.
BasisSelectionOptions selection_options(const SelectArgs& a, const Inputs& in) {
  const CommonOptions& c = a.common;
  BasisSelectionOptions o;
  o.delta = in.objective.delta;
  o.dmax = in.objective.dmax;
  o.max_degree = a.max_degree;
  o.iterate = a.iterate;
  o.max_iterations = a.max_iterations;
  o.rel_tol = a.rel_tol;
  o.prune = !a.no_prune;
  o.unknowns.x0 = a.free_x0;
  o.unknowns.offset = !a.no_offset;
  o.class_certificates = !a.no_class;
  o.klass.box_fraction = a.class_box;
  o.klass.max_leaves = a.class_leaves;
  o.solver.verbose = c.verbose;
  o.certify = certify_options(c, in);  // objective and bounds: set per step
  return o;
}

/// The inputs, checked, the basis growth order, and the run's options printed.
Inputs select_inputs(SelectArgs& a, std::vector<Monomial>& order) {
  CommonOptions& c = a.common;
  if (c.delta_text.empty() || c.dmax_text.empty())
    throw InputError("select-basis: give both --delta and --dmax (the bounds at which consistency is decided)");
  Inputs in = load_inputs(c);
  if (in.mode != ToeplitzMode::kSignal)
    throw InputError("select-basis: --toeplitz paper is not supported (identification uses the signal form)");
  print_options(c, in, "select-basis");
  order = basis_growth_order(in.model_d.n_rho(), a.max_degree);
  std::cout << "  growth      " << basis_text(order, in.model_d.scheduling) << " (max degree " << a.max_degree
            << ")\n"
            << "  method      "
            << (a.iterate ? "Theorem 3.1, min dmax at the given delta with iterated re-linearisation (beyond the paper),"
                            " then Theorem 2.1 certificate at the given bounds"
                          : "Theorem 3.1 relaxation at S_I (paper) with the given bounds, then Theorem 2.1 certificate "
                            "at the given bounds")
            << "\n\n";
  return in;
}

/// The steps that are not consistent, with their reasons.
void print_step_notes(const BasisSelectionResult& r) {
  for (const BasisStep& s : r.steps)
    if (s.verdict != BasisVerdict::kConsistent && s.same_as < 0) {
      std::cout << "  step " << s.index << ": " << s.detail << "\n";
      if (!s.class_certificate.empty())
        std::cout << "          class certificate " << s.class_certificate << " (" << class_region_text(*s.klass) << ")\n";
    }
  const std::string mono = monotonicity_violation(r.steps);
  if (!mono.empty()) std::cout << "  NOTE: verdicts are not monotone (solver or relaxation effect): " << mono << "\n";
}

/// A basis was found: its certificate written (when named) and its bounds printed.
nlohmann::ordered_json render_found(const BasisSelectionResult& r, const CommonOptions& c, const std::string& final_cert) {
  const BasisStep& f = r.steps[static_cast<size_t>(r.final_step)];
  const CertificateFiles files = write_named_certificates(f.bounds, final_cert);
  std::cout << "\nSelected basis: " << f.basis_text << " (step " << f.index << ")\n"
            << bounds_text(f.bounds, files,
                           "for this theta: the lower end bounds the model with the selected theta fixed, not the "
                           "model class");
  nlohmann::ordered_json report = bounds_json(f.bounds, c.toeplitz, c.solver, files);
  report["relaxation"] = f.relaxation;
  return report;
}

/// No basis was found: why, printed, and the report's verdict fields.
nlohmann::ordered_json render_not_found(const BasisSelectionResult& r, const SelectArgs& a) {
  const CommonOptions& c = a.common;
  std::cout << "\nNo basis up to degree " << a.max_degree << " gives a model consistent with the data at delta = "
            << c.delta_text << ", dmax = " << c.dmax_text << "\n";
  if (!a.iterate) std::cout << "  (the relaxation at S_I cannot make large corrections at tight bounds: try --iterate)\n";
  if (r.outcome == SelectionOutcome::kCannotExplain)
    std::cout << "  certified: the largest basis tried (step " << r.steps.back().index
              << ") cannot explain the data, so no basis of these terms can (class certificate)\n";
  nlohmann::ordered_json report;
  report["status"] = to_string(r.outcome);
  report["delta"] = nullptr;
  report["dmax"] = nullptr;
  report["noise_normalisation"] = "rms: ||d||_2 <= dmax*sqrt(n*ny)";
  report["toeplitz_mode"] = c.toeplitz;
  report["solver"] = c.solver;
  report["certificate"] = nullptr;
  report["verified"] = false;
  report["relaxation"] = a.iterate ? "iterated re-linearisation" : "linearised at the initial model (paper, after eq. 16)";
  return report;
}

/// The terms of `basis` as text.
nlohmann::ordered_json basis_json(const std::vector<Monomial>& basis, const std::vector<std::string>& scheduling) {
  nlohmann::ordered_json b = nlohmann::ordered_json::array();
  for (const Monomial& m : basis) b.push_back(m.text(scheduling));
  return b;
}

/// One step's entry of the report ("steps").
nlohmann::ordered_json step_json(const BasisStep& s, const std::vector<std::string>& scheduling) {
  const bool v = s.verdict == BasisVerdict::kConsistent;
  const auto or_null = [](bool has, auto value) { return has ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr); };
  return {{"step", s.index},
          {"phase", s.phase},
          {"basis", basis_json(s.basis, scheduling)},
          {"verdict", to_string(s.verdict)},
          {"detail", s.detail},
          {"delta", or_null(v, s.bounds.delta)},
          {"dmax", or_null(v, s.bounds.dmax)},
          {"dmax_relaxation", or_null(s.dmax_relaxation >= 0, s.dmax_relaxation)},
          {"relaxation", s.relaxation},
          {"solves", s.solves},
          {"seconds", s.seconds},
          {"same_as", or_null(s.same_as >= 0, s.same_as)},
          {"kept", s.kept},
          {"certificate", or_null(v && !s.certificate.empty(), s.certificate)},
          {"class_certificate", class_json(s)}};
}

/// The report's fields common to both outcomes.
void add_selection_json(nlohmann::ordered_json& report, const BasisSelectionResult& r, const SelectArgs& a,
                        const Inputs& in) {
  const std::vector<std::string>& scheduling = in.model_d.scheduling;
  int total_solves = 0;
  for (const BasisStep& s : r.steps) total_solves += s.solves;
  report["command"] = "select-basis";
  report["iterations"] = total_solves;
  report["delta_given"] = a.common.delta_text;
  report["dmax_given"] = a.common.dmax_text;
  report["iterate"] = a.iterate;
  report["max_degree"] = a.max_degree;
  report["order"] = basis_json(r.order, scheduling);
  report["steps"] = nlohmann::ordered_json::array();
  for (const BasisStep& s : r.steps) report["steps"].push_back(step_json(s, scheduling));
  if (r.found()) {
    const BasisStep& f = r.steps[static_cast<size_t>(r.final_step)];
    report["final_basis"] = basis_json(f.basis, scheduling);
    report["final_step"] = f.index;
    report["theta"] = theta_json(with_correction_basis(in.model_d, f.basis), f.layout, f.p);
  } else {
    report["final_basis"] = nullptr;
    report["theta"] = nullptr;
  }
  report["samples"] = in.exp_q.n();
}

int run_select(SelectArgs& a) {
  CommonOptions& c = a.common;
  std::vector<Monomial> order;
  Inputs in = select_inputs(a, order);
  BasisSelectionOptions o = selection_options(a, in);
  // the step certificates only under a stem the user named
  const std::string final_cert = named_certificate_path(c);
  const std::string stem = final_cert.empty() ? "" : stem_of(final_cert, {".cert.json", ".json"});
  const Table table(std::max<size_t>(16, std::min<size_t>(60, basis_text(order, in.model_d.scheduling).size())));
  table.header();
  o.on_step = [&](const BasisStep& s) { table.row(s); };
  auto solver = make_solver_for_cli(c.solver, c.write_sdpa);
  BasisSelectionResult r = select_basis(in, o, *solver);
  if (!stem.empty()) write_step_certificates(r, stem);
  print_legend(c, a.iterate);
  print_step_notes(r);
  nlohmann::ordered_json report = r.found() ? render_found(r, c, final_cert) : render_not_found(r, a);
  add_selection_json(report, r, a, in);
  write_json(c.report_path, report);
  switch (r.outcome) {
    case SelectionOutcome::kFound: return kExitOk;
    case SelectionOutcome::kCannotExplain: return kExitInvalidated;
    case SelectionOutcome::kNotVerified: return kExitNotVerified;
    case SelectionOutcome::kNotDecided: break;
  }
  return kExitUndecided;
}

}  // namespace

Runner add_select_basis_command(CLI::App& app) {
  auto a = std::make_shared<SelectArgs>();
  CLI::App* cmd = app.add_subcommand(
      "select-basis",
      "Appendix algorithm: grow the correction basis until consistent at --delta/--dmax, then prune; a basis is "
      "'cannot_explain' only with a class certificate (lpvid-verify checks it), else 'not_decided'");
  add_common_options(*cmd, a->common, true);
  cmd->add_option("--degree", a->max_degree, with_default("largest total degree of a candidate term", a->max_degree))
      ->check(CLI::Range(0, 8));
  // One meaning per name: --max-degree is the input limit (before the command); the terms' degree is --degree, as in diagnose.
  add_refused_option(*cmd, "--max-degree",
                     "is the input limit on a model's polynomial degree, not the candidate terms' degree: give it "
                     "before the command (lpvid --max-degree N select-basis ...), or --degree D for the candidate terms");
  cmd->add_flag("--iterate", a->iterate,
                "per basis: minimise dmax at delta with iterated re-linearisation (beyond the paper), then certify");
  cmd->add_option("--max-iterations", a->max_iterations, "solves of --iterate per basis")->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--rel-tol", a->rel_tol, "stop --iterate when dmax^2 improves by less")->capture_default_str();
  cmd->add_flag("--free-x0", a->free_x0, "the initial state is an unknown too");
  cmd->add_flag("--no-offset", a->no_offset, "do not identify the offset phi even if the model declares one");
  cmd->add_flag("--no-prune", a->no_prune, "skip the removal phase");
  cmd->add_flag("--no-class-bound", a->no_class,
                "do not try class certificates: every step not consistent is then not_decided (or unverified)");
  cmd->add_option("--class-box", a->class_box,
                  with_default("half-width of the class box of a step whose corrections move z: each may move z by this fraction "
                  "of ||z||", a->class_box))
      ->check(CLI::PositiveNumber);
  cmd->add_option("--class-leaves", a->class_leaves, with_default("leaves of a step's class certificate", a->class_leaves))
      ->check(CLI::Range(1, 4095));
  return [cmd, a] { return cmd->parsed() ? run_select(*a) : -1; };
}

}  // namespace lpvid::cli
