#include "certify/dual_certify.h"

#include <chrono>
#include <cmath>
#include <optional>
#include <utility>

#include "core/decimal_rounding.h"
#include "core/number_text.h"
#include "toeplitz/delta_form_dual.h"
#include "toeplitz/fir.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/certificate_file.h"
#include "verify/certificate/path_dual.h"
#include "verify/psd/psd_filter.h"

namespace lpvid {
namespace {

/// x on the decimal grid of `unit` (an exact power of ten), as a rational.
Rational on_grid(double x, double unit_d, const Rational& unit) {
  const double k = std::nearbyint(x / unit_d);
  if (!std::isfinite(k) || std::fabs(k) > 9e15) throw std::invalid_argument("dual certificate: entry off the grid");
  return Rational(static_cast<long>(k)) * unit;
}

DualClaim claim_of(const BoundObjective& obj) {
  switch (obj.kind) {
    case BoundObjective::Kind::kFeasibility:
      return DualClaim::kInvalidated;
    case BoundObjective::Kind::kMinDelta:
      return DualClaim::kMinDelta2;
    case BoundObjective::Kind::kMinDmax:
      return DualClaim::kMinDmax2;
    case BoundObjective::Kind::kWeighted:
      break;
  }
  return DualClaim::kWeighted;
}

/// The σ that maximises the (double) bound for fixed tr U, tr V, ‖g‖², gᵀr:
/// a scan over 10^(k/8) around the natural scale, then the best kept.
double best_sigma(double trU, double trV, double gg, double gr, double N, DualClaim claim, double t, double s,
                  double lambda, double sigma0) {
  const auto value = [&](double sigma) {
    DualTerms<double> d;
    d.trace_U = trU;
    d.N_sigma = N * sigma;
    d.beta = -(trV + gg / sigma + 2 * gr);
    return dual_bound(d, claim, t, s, lambda);
  };
  // A coarse scan in log σ, then golden-section refinement around the best
  // grid point (the bound is unimodal in σ: a concave quadratic in 1/σ, or
  // a minimum of two such for the weighted objective).
  double best = sigma0, best_value = -INFINITY;
  const double centre = sigma0 > 0 && std::isfinite(sigma0) ? sigma0 : 1.0;
  for (int k = -160; k <= 160; ++k) {
    const double sigma = centre * std::pow(10.0, k / 8.0);
    if (const double v = value(sigma); v > best_value) {
      best_value = v;
      best = sigma;
    }
  }
  double lo = std::log(best) - std::log(10.0) / 8.0, hi = std::log(best) + std::log(10.0) / 8.0;
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 80; ++it) {
    const double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
    if (value(std::exp(a)) >= value(std::exp(b)))
      hi = b;
    else
      lo = a;
  }
  const double refined = std::exp(0.5 * (lo + hi));
  return value(refined) >= best_value ? refined : best;
}



/// `done(reason)`: sets the outcome's reason and the seconds since this call, returns it.
auto outcome_closer(DualOutcome& out) {
  const auto t0 = std::chrono::steady_clock::now();
  return [&out, t0](std::string reason) {
    out.reason = std::move(reason);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  };
}

/// The fixed values of the claim, exact (from the CLI text when given).
struct FixedValues {
  Rational delta2{0}, dmax2{0}, lambda{0};
};
FixedValues fixed_values(const CertifyOptions& o, DualClaim claim) {
  const auto exact_of = [](const std::string& text, double value) {
    return rational_from_text(text.empty() ? double_to_text(value) : text);
  };
  FixedValues f;
  if (o.objective.delta_fixed()) f.delta2 = exact_of(o.fixed_delta_text, o.objective.delta) * exact_of(o.fixed_delta_text, o.objective.delta);
  if (o.objective.dmax_fixed()) f.dmax2 = exact_of(o.fixed_dmax_text, o.objective.dmax) * exact_of(o.fixed_dmax_text, o.objective.dmax);
  if (claim == DualClaim::kWeighted) f.lambda = rational_from_text(double_to_text(o.objective.lambda));
  return f;
}

/// The certificate around a dual point (form and dual filled by the caller).
Certificate dual_certificate(const LpvModel<Rational>& model, DualClaim claim, const FixedValues& f, const Rational& bound,
                             int bound_digits) {
  Certificate c;
  c.model = model;
  c.mode = ToeplitzMode::kSignal;
  c.claim = claim == DualClaim::kInvalidated ? CertificateClaim::kInvalidated : CertificateClaim::kLowerBound;
  c.objective = claim;
  c.delta2 = f.delta2;
  c.dmax2 = f.dmax2;
  c.lambda = f.lambda;
  c.lower_bound = claim == DualClaim::kInvalidated ? Rational(0) : round_down_to_digits(bound, bound_digits);
  return c;
}

/// Names the data in c, checks it after its JSON round trip (certify.h step
/// 6) on the exact experiment, fills `out` (the certificate only when it holds).
void check_and_keep(Certificate& c, const Experiment<Rational>& exp, const CertifyOptions& o, const Rational& bound,
                    DualOutcome& out) {
  set_data_reference(c, o.data);
  c.info["tool"] = "lpvid";
  c.info["objective"] = o.objective.describe();
  const CertificateVerdict v = check_certificate(parse_certificate(certificate_json(c), "the dual certificate (in memory)"), exp);
  out.verified = v.holds;
  out.verifier_details = v.details;
  out.bound = c.claim == CertificateClaim::kInvalidated ? bound : c.lower_bound;
  if (!v.holds) {
    out.reason = "the dual certificate failed the exact check: " + v.reason;
    return;
  }
  out.certificate = std::move(c);
}


/// g on a 10⁻¹⁴ grid: entries of `column` (k·ny + i order) divided by
/// `scale`, exactly, and their doubles.
struct GridSignal {
  Mat<Rational> g;
  Mat<double> g_d;
};
GridSignal grid_signal(const Vec<double>& column, double scale, Eigen::Index n, Eigen::Index ny) {
  const double unit_d = 1e-14;
  const Rational unit = power_of_ten(-14);
  GridSignal s{Mat<Rational>(n, ny), Mat<double>(n, ny)};
  for (Eigen::Index k = 0; k < n; ++k)
    for (Eigen::Index i = 0; i < ny; ++i) {
      s.g(k, i) = on_grid(column(k * ny + i) / scale, unit_d, unit);
      s.g_d(k, i) = nearest_double(s.g(k, i));
    }
  return s;
}

/// ‖g‖² and gᵀr in double (for choosing σ).
std::pair<double, double> g_norms(const Mat<double>& g_d, const Mat<Rational>& r) {
  const Mat<double> r_d = nearest_double(r);
  double gg = 0, gr = 0;
  for (Eigen::Index k = 0; k < g_d.rows(); ++k)
    for (Eigen::Index i = 0; i < g_d.cols(); ++i) {
      gg += g_d(k, i) * g_d(k, i);
      gr += g_d(k, i) * r_d(k, i);
    }
  return {gg, gr};
}

/// σ chosen in double (best_sigma), then rounded to 15 digits.
Rational chosen_sigma(double trU, double trV, const std::pair<double, double>& gg_gr, Eigen::Index N, DualClaim claim,
                      const FixedValues& f, double sigma0) {
  const auto [gg, gr] = gg_gr;
  const double sigma_d = best_sigma(trU, trV, gg, gr, static_cast<double>(N), claim, nearest_double(f.delta2),
                                    nearest_double(f.dmax2), nearest_double(f.lambda), sigma0 > 0 ? sigma0 : std::sqrt(gg + 1e-300));
  return round_to_digits(sigma_d, 15);
}

/// Y1 (normalised, symmetrised) on the 10⁻¹⁴ grid.
Mat<Rational> grid_matrix(const Mat<double>& Y1d) {
  const double unit_d = 1e-14;
  const Rational unit = power_of_ten(-14);
  const Eigen::Index P = Y1d.rows();
  Mat<Rational> Y1(P, P);
  for (Eigen::Index i = 0; i < P; ++i)
    for (Eigen::Index j = i; j < P; ++j) {
      Y1(i, j) = on_grid(0.5 * (Y1d(i, j) + Y1d(j, i)), unit_d, unit);
      Y1(j, i) = Y1(i, j);
    }
  return Y1;
}

/// Step 3: Y1 projected onto Ω_l(W) = C_l(g) exactly (the dual equality of
/// toeplitz/delta_form_dual.h), the error spread along each block diagonal.
void project_onto_dual_equality(Mat<Rational>& Y1, const Mat<Rational>& g, const Mat<Rational>& z, Eigen::Index L,
                                Eigen::Index ny, Eigen::Index nz) {
  const Mat<Rational> target = fir_adjoint(g, z, L);
  const Mat<Rational> have = block_diagonal_sums(Y1, L, ny, nz);
  const Eigen::Index off = L * ny;
  for (Eigen::Index l = 0; l < L; ++l)
    for (Eigen::Index i = 0; i < ny; ++i)
      for (Eigen::Index j = 0; j < nz; ++j) {
        const Rational E = target(l, i * nz + j) - have(l, i * nz + j);
        if (E == 0) continue;
        const Rational share = E / Rational(static_cast<long>(L - l));
        for (Eigen::Index b = 0; b + l < L; ++b) {
          Y1((b + l) * ny + i, off + b * nz + j) += share;
          Y1(off + b * nz + j, (b + l) * ny + i) = Y1((b + l) * ny + i, off + b * nz + j);
        }
      }
}

/// Step 4: Y1 + ε·I with ε from the floating λ_min, grown until the rigorous
/// filter proves it ≻ 0; nullopt when six tries fail (`eps_out`: the last ε).
std::optional<Mat<Rational>> with_psd_margin(const Mat<Rational>& Y1, Rational& eps_q, double& eps_out) {
  const Eigen::Index P = Y1.rows();
  const Mat<double> Y1f = nearest_double(Y1);
  Eigen::SelfAdjointEigenSolver<Mat<double>> es(Y1f, Eigen::EigenvaluesOnly);
  const double lmin = es.eigenvalues().minCoeff();
  double eps = std::max(0.0, -lmin) * 1.5 + 8.0 * static_cast<double>(P + 2) * 0x1.0p-53 * std::max(Y1f.trace(), 1e-300) + 1e-300;
  for (int attempt = 0; attempt < 6; ++attempt, eps *= 10) {
    eps_q = round_up_to_digits(exact_rational_of_double(eps), 2);
    Mat<Rational> Y1m = Y1;
    for (Eigen::Index i = 0; i < P; ++i) Y1m(i, i) += eps_q;
    if (run_psd_filter(Y1m).proved_pd) return Y1m;
  }
  eps_out = eps / 10;
  return std::nullopt;
}

DualOutcome certify_dual_dense(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                               const Simulation<Rational>& sim, const Mat<double>& Y1_in, const Mat<double>& Y2_in,
                               const CertifyOptions& o) {
  DualOutcome out;
  const auto done = outcome_closer(out);
  const Eigen::Index n = exp.n(), ny = model.ny, nz = model.nz();
  const Eigen::Index L = n - leading_zero_samples(sim.z);
  const Eigen::Index P = L * (ny + nz), N = n * ny;
  if (L == 0 || nz == 0) return done("z is identically zero: no Delta form");
  if (Y1_in.rows() != P || Y1_in.cols() != P || Y2_in.rows() != N + 1 || Y2_in.cols() != N + 1)
    return done("the solver returned no dual matrices of the expected sizes");
  if (!Y1_in.allFinite() || !Y2_in.allFinite()) return done("the solver's dual matrices are not finite");
  const Mat<Rational> r = exp.y - sim.output;
  const DualClaim claim = claim_of(o.objective);
  const FixedValues fixed = fixed_values(o, claim);

  // 2. Normalise (the dual is homogeneous) and round to a decimal grid; 3. project exactly.
  const double scale = std::max(Y1_in.cwiseAbs().maxCoeff(), Y2_in.col(0).cwiseAbs().maxCoeff());
  if (!(scale > 0)) return done("the solver's dual matrices are zero");
  GridSignal gs = grid_signal(Y2_in.col(0).tail(N), scale, n, ny);
  Mat<Rational> Y1 = grid_matrix(Y1_in / scale);
  project_onto_dual_equality(Y1, gs.g, sim.z, L, ny, nz);
  // 4. PSD margin.
  Rational eps_q;
  double eps_failed = 0;
  std::optional<Mat<Rational>> Y1m = with_psd_margin(Y1, eps_q, eps_failed);
  if (!Y1m) return done("the rounded dual matrix Y1 is not positive definite even with a margin of " + double_to_text(eps_failed));

  // 5. σ.
  double trU = 0, trV = 0;
  for (Eigen::Index i = 0; i < P; ++i) (i < L * ny ? trU : trV) += nearest_double((*Y1m)(i, i));
  const Rational sigma = chosen_sigma(trU, trV, g_norms(gs.g_d, r), N, claim, fixed, Y2_in(0, 0) / scale);
  if (!(sigma > 0)) return done("no positive sigma");

  // 6. The bound, exactly; the certificate; the check from the file.
  const Rational bound = dual_bound(dual_terms(*Y1m, gs.g, sigma, r, L), claim, fixed.delta2, fixed.dmax2, fixed.lambda);
  if (claim == DualClaim::kInvalidated && !(bound > 0))
    return done("after rounding and the PSD margin (" + double_to_text(nearest_double(eps_q)) +
                ") the dual point no longer proves infeasibility (margin " + double_to_text(nearest_double(bound)) + ")");
  Certificate c = dual_certificate(model, claim, fixed, bound, 12);
  c.form = CertificateForm::kDualDelta;
  c.dual.horizon = L;
  c.dual.Y1 = std::move(*Y1m);
  c.dual.g = std::move(gs.g);
  c.dual.sigma = sigma;
  c.info["psd_margin"] = nearest_double(eps_q);
  c.info["dual_scale"] = scale;
  check_and_keep(c, exp, o, bound, out);
  return done(out.reason);
}

/// The compact recipe of a central-path point: the taps (tiny ones zero),
/// t = δ², μ scaled like g, x = μ to start with.
PathDualRecipe path_recipe(const DeltaFormSolution& s, double scale) {
  PathDualRecipe recipe;
  const double hmax = s.taps.cwiseAbs().maxCoeff();
  recipe.taps = Mat<Rational>(s.taps.rows(), s.taps.cols());
  for (Eigen::Index l = 0; l < s.taps.rows(); ++l)
    for (Eigen::Index c = 0; c < s.taps.cols(); ++c) {
      const double h = s.taps(l, c);
      recipe.taps(l, c) = std::fabs(h) <= 0x1.0p-80 * hmax ? Rational(0) : exact_rational_of_double(h);
    }
  recipe.t = exact_rational_of_double(s.delta2);
  recipe.mu = exact_rational_of_double(s.path_mu / scale);
  recipe.x = recipe.mu;
  return recipe;
}

/// What a verifier's rebuild of U may change (docs/dual_certificates.md,
/// "Portable acceptance"): any U' with ‖U' − U‖₂ ≤ η = kPathDualRebuildTolerance·‖U‖_∞
/// (‖U‖_∞ ≥ ‖U‖₂) moves ‖E‖_F by at most η·‖T‖_F (E is the orthogonal
/// projection of the residual, R' − R = Ω(DT)), tr U by P·η and β by
/// 3η·‖T‖_F² (tr TᵀDT and 2⟨T, DT⟩). Doubles, rounded up by a relative 10⁻⁹.
struct RebuildMargin {
  double eta = 0;     ///< bound on ‖U' − U‖₂
  double t_frob = 0;  ///< ‖T‖_F
  double E_shift() const { return eta * t_frob; }
  double beta_shift() const { return 3 * eta * t_frob * t_frob; }
};

RebuildMargin rebuild_margin(const PathDualRecipe& recipe, const PathDualGrid& grid) {
  RebuildMargin m;
  const double up = 1 + 1e-9;
  const double row_max = grid.U.size() ? grid.U.cwiseAbs().rowwise().sum().maxCoeff() : 0.0;
  m.eta = kPathDualRebuildTolerance * std::ldexp(row_max, static_cast<int>(recipe.u_exponent)) * up;
  const Eigen::Index L = recipe.taps.rows();
  double frob2 = 0;
  for (Eigen::Index l = 0; l < L; ++l)
    frob2 += static_cast<double>(L - l) * nearest_double(recipe.taps.row(l)).squaredNorm();
  m.t_frob = std::sqrt(frob2) * up;
  return m;
}

/// The floor γ with x·γ ≥ (‖E‖_F + η‖T‖_F)² (rounded up), with the filter
/// proving U − (2γ + 2η)·I ≻ 0: twice the verifier's floor and twice what a
/// rebuild within η moves the spectrum, so that another compiler's or BLAS's
/// U still passes. x costs x·L·nz in tr V, so it starts at the smallest value
/// the spectrum allows: λ_min(U) ≥ μ/t (t·I − TTᵀ ⪯ t·I), so
/// x = max(μ, 4·‖E‖²·t/μ) keeps 2γ ≤ λ_min(U)/2; it doubles while the filter
/// cannot prove it. E depends on neither x nor σ. Empty when proved; else why not.
std::string prove_floor(PathDualRecipe& recipe, const PathDualGrid& grid, const Rational& E_norm2, const RebuildMargin& m) {
  const double E_far = (std::sqrt(nearest_double(E_norm2)) * (1 + 1e-9) + m.E_shift()) * (1 + 1e-9);
  const Rational target = std::max(E_norm2, exact_rational_of_double(E_far * E_far * (1 + 1e-9)));
  const Rational from_spectrum = Rational(4) * target * recipe.t / recipe.mu;
  if (from_spectrum > recipe.x) recipe.x = exact_rational_of_double(nearest_double(from_spectrum) * (1 + 1e-12));
  const Rational eta = exact_rational_of_double(m.eta);
  std::string why;
  for (int attempt = 0; attempt < 24; ++attempt) {
    recipe.floor = round_up_to_digits(target / recipe.x, 2);
    PathDualRecipe doubled = recipe;
    doubled.floor = (recipe.floor + eta) * Rational(2);
    const PsdResult psd = path_dual_psd(doubled, grid.U, false);
    if (psd.verdict != PsdVerdict::kNotPsd) return "";
    why = psd.reason;
    recipe.x = recipe.x * Rational(2);
  }
  return "U - 2*(u_floor + eta)*I is not proved positive definite even with x = " + double_to_text(nearest_double(recipe.x)) +
         " (" + why + ")";
}

/// The bound any rebuild within the margin still reaches: β lowered and
/// tr U raised by what the rebuild may move them (dual_bound is increasing in
/// β and non-increasing in tr U where it is positive).
Rational rebuilt_bound(DualTerms<Rational> terms, const RebuildMargin& m, Eigen::Index P, DualClaim claim,
                       const FixedValues& fixed) {
  terms.beta -= exact_rational_of_double(m.beta_shift());
  terms.trace_U += exact_rational_of_double(static_cast<double>(P) * m.eta);
  return dual_bound(terms, claim, fixed.delta2, fixed.dmax2, fixed.lambda);
}

/// The compact form (verify/certificate/path_dual.h) from a barrier's central-path point:
/// the recipe is the point itself (taps, t, μ) with x = μ; g from Y2's first
/// column on a decimal grid; the floor γ and x as in prove_floor.
DualOutcome certify_dual_path(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                              const Simulation<Rational>& sim, const DeltaFormSolution& s, const CertifyOptions& o) {
  DualOutcome out;
  const auto done = outcome_closer(out);
  const Eigen::Index n = exp.n(), ny = model.ny, nz = model.nz();
  const Eigen::Index L = n - leading_zero_samples(sim.z), N = n * ny;
  if (L == 0 || nz == 0) return done("z is identically zero: no Delta form");
  if (s.taps.rows() != L || s.taps.cols() != ny * nz || s.dual_c2.rows() != N + 1 || !(s.path_mu > 0))
    return done("the barrier returned no central-path point of the expected size");
  const DualClaim claim = claim_of(o.objective);
  const FixedValues fixed = fixed_values(o, claim);
  const Mat<Rational> r = exp.y - sim.output;

  // g on a 10⁻¹⁴ grid relative to its largest entry; μ scaled alike (homogeneous).
  const Vec<double> g_col = s.dual_c2.col(0).tail(N);
  const double scale = std::max(g_col.cwiseAbs().maxCoeff(), 1e-300);
  GridSignal gs = grid_signal(g_col, scale, n, ny);
  PathDualRecipe recipe = path_recipe(s, scale);
  std::string problem;
  const Mat<double> U_d = path_dual_floating_u(recipe, ny, nz, problem);
  if (!problem.empty()) return done(problem);
  recipe.u_exponent = path_dual_exponent(U_d);
  const PathDualGrid grid = path_dual_round(U_d, recipe.u_exponent);
  if (!grid.problem.empty()) return done(grid.problem);
  const PathDualSums sums = path_dual_sums(recipe, grid.U, ny, nz);
  if (!sums.problem.empty()) return done(sums.problem);
  const Mat<Rational> C = fir_adjoint(gs.g, sim.z, L);
  PathDualValue v = path_dual_value(recipe, sums, C, gs.g, Rational(1), r, ny, nz);
  const RebuildMargin margin = rebuild_margin(recipe, grid);
  if (const std::string why = prove_floor(recipe, grid, v.E_norm2, margin); !why.empty()) return done(why);
  v = path_dual_value(recipe, sums, C, gs.g, Rational(1), r, ny, nz);

  // σ (β(σ = 1) = −(tr V + ‖g‖² + 2gᵀr) gives tr V), then the bound exactly.
  const std::pair<double, double> gg_gr = g_norms(gs.g_d, r);
  const double trV = nearest_double(-v.terms.beta) - gg_gr.first - 2 * gg_gr.second;
  const Rational sigma = chosen_sigma(nearest_double(v.terms.trace_U), trV, gg_gr, N, claim, fixed, s.dual_c2(0, 0) / scale);
  if (!(sigma > 0)) return done("no positive sigma");
  v = path_dual_value(recipe, sums, C, gs.g, sigma, r, ny, nz);
  const Rational bound = dual_bound(v.terms, claim, fixed.delta2, fixed.dmax2, fixed.lambda);
  // What a verifier built elsewhere, with U in other last bits, still reaches.
  const Rational portable = rebuilt_bound(v.terms, margin, L * ny, claim, fixed);
  if (claim == DualClaim::kInvalidated && !(portable > 0))
    return done("the compact dual point does not prove infeasibility (margin " + double_to_text(nearest_double(bound)) +
                ", " + double_to_text(nearest_double(portable)) + " for a rebuild of U within the stated tolerance)");
  // The claimed lower end: that, and 10⁻⁹ (relative) below the bound.
  const Rational slack = bound > 0 ? bound * power_of_ten(-9) : Rational(0);
  Certificate c = dual_certificate(model, claim, fixed, std::min(portable, bound - slack), 12);
  c.form = CertificateForm::kDualDeltaPath;
  c.dual.horizon = L;
  c.dual.g = std::move(gs.g);
  c.dual.sigma = sigma;
  c.info["dual_scale"] = scale;
  c.info["x_over_mu"] = nearest_double(recipe.x / recipe.mu);
  c.info["u_floor_over_mu"] = nearest_double(recipe.floor / recipe.mu);
  c.info["rebuild_tolerance"] = kPathDualRebuildTolerance;
  c.dual.path = std::move(recipe);
  check_and_keep(c, exp, o, bound, out);
  return done(out.reason);
}

}  // namespace

DualOutcome certify_dual(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                         const Simulation<Rational>& sim, const DeltaFormSolution& s, const CertifyOptions& o) {
  if (s.path_mu > 0 && !o.dense_dual) {
    DualOutcome compact = certify_dual_path(model, exp, sim, s, o);
    if (compact.verified) return compact;
    DualOutcome dense = certify_dual_dense(model, exp, sim, s.dual_c1, s.dual_c2, o);
    dense.note = "compact dual form not used: " + compact.reason;
    if (!dense.verified) dense.reason = "compact form: " + compact.reason + "; dense form: " + dense.reason;
    dense.seconds += compact.seconds;
    return dense;
  }
  return certify_dual_dense(model, exp, sim, s.dual_c1, s.dual_c2, o);
}

}  // namespace lpvid
