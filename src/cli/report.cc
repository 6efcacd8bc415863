#include "cli/report.h"

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/decimal_rounding.h"
#include "core/file_io.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "model/model_file.h"

namespace lpvid::cli {

int exit_code(CertifyOutcome outcome) {
  switch (outcome) {
    case CertifyOutcome::kVerified: return kExitOk;
    case CertifyOutcome::kInvalidated: return kExitInvalidated;
    case CertifyOutcome::kUndecided: return kExitUndecided;
    case CertifyOutcome::kSolverFailed: return kExitSolver;
    case CertifyOutcome::kNotVerified: return kExitNotVerified;
  }
  return kExitNotVerified;
}

nlohmann::ordered_json bounds_json(const CertifiedBounds& b, const std::string& toeplitz_mode,
                                   const std::string& solver, const CertificateFiles& files) {
  nlohmann::ordered_json j;
  j["status"] = b.verified() ? "consistent" : "not_verified";
  // A bound that the exact verifier did not accept is never reported as a bound.
  j["delta"] = b.verified() ? nlohmann::ordered_json(b.delta) : nlohmann::ordered_json(nullptr);
  j["dmax"] = b.verified() ? nlohmann::ordered_json(b.dmax) : nlohmann::ordered_json(nullptr);
  if (b.verified()) {
    j["delta2_exact"] = exact_decimal_or_fraction(b.delta2);
    j["dmax2_exact"] = exact_decimal_or_fraction(b.dmax2);
  }
  j["noise_normalisation"] = "rms: ||d||_2 <= dmax*sqrt(n*ny)";
  j["toeplitz_mode"] = toeplitz_mode;
  // what produced the answer: a closed form (no solve), the structured barrier, or the SDP backend
  j["solver"] = !b.closed_form.empty() ? b.closed_form : !b.solver_used.empty() ? b.solver_used : solver;
  j["certificate"] = b.verified() && !files.certificate.empty() ? nlohmann::ordered_json(files.certificate)
                                                               : nlohmann::ordered_json(nullptr);
  j["verified"] = b.verified();
  if (!b.verified()) j["reason"] = b.reason;
  nlohmann::ordered_json c;
  c["form"] = b.horizon > 0 ? "delta (FIR, Poolla form)" : "w";
  if (b.horizon > 0) {
    c["delta_taps"] = b.taps;
    c["horizon"] = b.horizon;
  }
  c["delta2_solver"] = b.delta2_solver;
  c["delta2_margin"] = b.margin;
  c["solver_status"] = solve_status_text(b);
  if (!b.fallback.empty()) c["fallback"] = b.fallback;
  // Where the time went, stage by stage (CertifiedBounds: every solve and
  // certificate of the call, also those not kept).
  c["signals_seconds"] = b.signals_seconds;
  c["solve_seconds"] = b.solve_seconds;
  c["upper_build_seconds"] = b.upper_build_seconds;
  c["verify_seconds"] = b.verify_seconds;
  c["dual_seconds"] = b.lower.seconds;
  c["dual_check_seconds"] = b.lower.check_seconds;
  c["total_seconds"] = b.total_seconds;
  c["verifier"] = b.verifier_details;
  j["certification"] = c;
  return j;
}

nlohmann::ordered_json theta_json(const LpvModel<double>& model, const ParameterLayout& layout, const Vec<double>& p) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  Eigen::Index at = 0;
  auto matrix = [&](Eigen::Index rows, Eigen::Index cols) {
    nlohmann::ordered_json m = nlohmann::ordered_json::array();
    for (Eigen::Index r = 0; r < rows; ++r) {
      nlohmann::ordered_json row = nlohmann::ordered_json::array();
      for (Eigen::Index c = 0; c < cols; ++c) row.push_back(p(at++));
      m.push_back(row);
    }
    return m;
  };
  if (layout.n_theta_out > 0)
    for (const Monomial& f : model.correction.basis) {
      nlohmann::ordered_json t;
      t["C"] = matrix(model.ny, model.nx);
      t["D"] = matrix(model.ny, model.nu);
      j[f.text(model.scheduling)] = t;
    }
  if (layout.n_theta_unc > 0)
    for (const Monomial& f : model.correction.basis) {
      nlohmann::ordered_json& t = j[f.text(model.scheduling)];
      t["C1"] = matrix(model.nz(), model.nx);
      t["D1"] = matrix(model.nz(), model.nu);
    }
  if (layout.n_phi > 0) {
    nlohmann::ordered_json phi;
    for (const Monomial& f : model.offset.basis) {
      nlohmann::ordered_json v = nlohmann::ordered_json::array();
      for (int r = 0; r < model.ny; ++r) v.push_back(p(at++));
      phi[f.text(model.scheduling)] = v;
    }
    j["offset_phi"] = phi;
  }
  if (layout.n_x0 > 0) {
    // the identified x0 = the model's x0 + its change p; several records: one per record
    const Eigen::Index K = std::max<Eigen::Index>(1, layout.x0_records), nx = layout.n_x0 / K;
    nlohmann::ordered_json all = nlohmann::ordered_json::array();
    for (Eigen::Index k = 0; k < K; ++k) {
      nlohmann::ordered_json v = nlohmann::ordered_json::array();
      for (Eigen::Index r = 0; r < nx; ++r) v.push_back((model.x0.size() == nx ? model.x0(r) : 0.0) + p(at++));
      all.push_back(v);
    }
    if (K == 1) j["x0"] = all[0];
    else j["x0_records"] = all;
  }
  return j;
}

void write_json(const std::string& path, const nlohmann::ordered_json& j) {
  if (path.empty()) return;
  write_text_file(path, j.dump(2) + "\n", "report");
}

namespace {
/// What the interval is on.
std::string interval_quantity(BoundObjective::Kind k) {
  switch (k) {
    case BoundObjective::Kind::kMinDelta:
      return "delta^2";
    case BoundObjective::Kind::kMinDmax:
      return "dmax^2";
    case BoundObjective::Kind::kWeighted:
      return "lambda*delta^2 + (1-lambda)*dmax^2";
    case BoundObjective::Kind::kFeasibility:
      break;
  }
  return "";
}
}  // namespace

nlohmann::ordered_json interval_json(const CertifiedBounds& b, const BoundObjective& objective, const CertificateFiles& files) {
  nlohmann::ordered_json j;
  j["of"] = interval_quantity(objective.kind);
  // printed = certified: the upper end rounded up, the lower end down (core/decimal_rounding.h)
  j["upper"] = b.verified() ? nlohmann::ordered_json(double_up(b.upper)) : nlohmann::ordered_json(nullptr);
  j["upper_verified"] = b.verified();
  if (b.verified()) j["upper_exact"] = exact_decimal_or_fraction(b.upper);
  j["lower"] = b.lower.verified() ? nlohmann::ordered_json(double_down(b.lower.value)) : nlohmann::ordered_json(nullptr);
  j["lower_verified"] = b.lower.verified();
  if (b.lower.verified()) j["lower_exact"] = exact_decimal_or_fraction(b.lower.value);
  const double gap = relative_gap(b);
  j["relative_gap"] = std::isfinite(gap) ? nlohmann::ordered_json(gap) : nlohmann::ordered_json(nullptr);
  j["lower_certificate"] =
      b.lower.verified() && !files.lower.empty() ? nlohmann::ordered_json(files.lower) : nlohmann::ordered_json(nullptr);
  if (!b.lower.verified()) j["lower_reason"] = b.lower.reason;
  j["full_horizon"] = b.full_horizon;
  j["note"] = !b.closed_form.empty() ? b.closed_form + ": both ends exact with no solve (docs/dual_certificates.md, the delta = 0 lower end)"
              : b.full_horizon      ? "both ends from the full-horizon program"
                                    : "upper end from a K-tap restriction (it can only raise the upper end); lower end from its "
                                      "dual lifted to the full horizon";
  j["lower_seconds"] = b.lower.seconds;
  j["lower_check_seconds"] = b.lower.check_seconds;
  return j;
}

CertificateFiles write_named_certificates(const CertifiedBounds& b, const std::string& path) {
  return path.empty() ? CertificateFiles{} : write_certificates(b, path);
}

namespace {
/// An exact certified value for reading: its exact text, or for a number of
/// thousands of digits (an exact ||r||^2/(n*ny)) 17 digits rounded up and its length.
std::string exact_or_long_text(const Rational& q) {
  const std::string text = exact_decimal_or_fraction(q);
  if (text.size() <= 80) return text;
  return upper_text(q, 17) + " rounded up; exact: " + std::to_string(text.size()) + " characters, in the certificate and the report";
}

/// What proved the lower end, for the text.
std::string lower_end_kind(const CertifiedBounds& b) {
  if (b.lower.certificate && is_closed_form(b.lower.certificate->form))
    return std::string("closed-form certificate, form ") + to_string(b.lower.certificate->form);
  return "dual certificate";
}
}  // namespace

std::string bounds_text(const CertifiedBounds& b, const CertificateFiles& files, const std::string& scope) {
  std::ostringstream o;
  if (b.verified()) {
    // printed = certified: upper ends rounded up, lower ends down (core/decimal_rounding.h)
    o << "  delta       <= " << upper_sqrt_text(b.delta2) << "   (delta^2 = " << exact_or_long_text(b.delta2) << ")\n"
      << "  dmax        <= " << upper_sqrt_text(b.dmax2) << "   (dmax^2 = " << exact_or_long_text(b.dmax2) << ", RMS)\n"
      << "  verified    true: "
      << (files.certificate.empty() ? std::string("checked exactly by the verifier; ") + kNoCertificateFile
                                    : files.certificate + " checked exactly by the verifier")
      << "\n"
      << "              " << b.verifier_details << "\n";
    if (b.lower.verified()) {
      o << "  interval    [" << lower_text(b.lower.value) << ", " << upper_text(b.upper)
        << "]  relative gap " << relative_gap(b) << "  (objective; both ends verified"
        << (!b.closed_form.empty() ? ", " + b.closed_form + ", no solve"
            : b.full_horizon       ? ", full horizon"
                                   : ", upper end from " + std::to_string(b.taps) + " taps")
        << ")"
        << (scope.empty() ? "" : "\n              " + scope) << "\n"
        << "  lower end   " << (files.lower.empty() ? std::string("not written") : files.lower)
        << " (" << lower_end_kind(b) << ", checked exactly)\n";
    } else if (!b.lower.reason.empty()) {
      o << "  lower end   not certified: " << b.lower.reason << "\n";
    }
  } else {
    o << "  verified    false: " << b.reason << "\n"
      << "  (no bound is reported: nothing was verified)\n";
  }
  return o.str();
}

std::string cell_text(double x) {
  if (x < 0) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

}  // namespace lpvid::cli
