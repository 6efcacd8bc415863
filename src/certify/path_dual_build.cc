#include "certify/path_dual_build.h"

#include <algorithm>
#include <cmath>

#include "core/decimal_rounding.h"
#include "core/number_text.h"
#include "toeplitz/fir.h"
#include "verify/psd/psd_filter.h"

namespace lpvid {
namespace {

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
/// "Portable acceptance"): any U' with ‖U' − U‖_F ≤ η = kPathDualRebuildTolerance·‖U‖_F
/// moves ‖E‖_F by at most η·‖T‖₂ (E is the orthogonal projection of the
/// residual, R' − R = Ω(DT), ‖DT‖_F ≤ ‖D‖_F‖T‖₂), tr U by √P·η and β by
/// 3η·‖T‖₂‖T‖_F (tr TᵀDT and 2⟨T, DT⟩, each ⟨D, TTᵀ⟩). ‖T‖₂ is bounded by
/// ‖T‖_F, by Σ_l ‖h_l‖_F (T = Σ_l S_l ⊗ h_l, S_l the l-th shift), and by √t
/// plus the rounding of the floating Cholesky factor of t·I − TTᵀ that built
/// U (it exists, so TTᵀ ⪯ t·I + 4(P+1)u(t + ‖T‖_F²)·I). Doubles, rounded up
/// by a relative 10⁻⁹.
RebuildMargin rebuild_margin(const PathDualRecipe& recipe, const PathDualGrid& grid) {
  RebuildMargin m;
  const double up = 1 + 1e-9;
  const double u_frob = std::ldexp(grid.U.norm(), static_cast<int>(recipe.u_exponent));
  m.eta = kPathDualRebuildTolerance * u_frob * up * up;
  const Eigen::Index L = recipe.taps.rows();
  double frob2 = 0, tap_sum = 0;
  for (Eigen::Index l = 0; l < L; ++l) {
    const double h2 = nearest_double(recipe.taps.row(l)).squaredNorm();
    frob2 += static_cast<double>(L - l) * h2;
    tap_sum += std::sqrt(h2);
  }
  m.t_frob = std::sqrt(frob2) * up;
  const double P = static_cast<double>(grid.U.rows()), t = nearest_double(recipe.t);
  const double from_cholesky = std::sqrt(t + 4 * (P + 1) * 0x1.0p-53 * (t + frob2));
  m.t_norm = std::min({m.t_frob, tap_sum, from_cholesky}) * up * up;
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

}  // namespace

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


FixedValues fixed_values(const CertifyOptions& o, DualClaim claim) {
  FixedValues f;
  if (o.objective.delta_fixed()) f.delta2 = o.objective.delta.exact * o.objective.delta.exact;
  if (o.objective.dmax_fixed()) f.dmax2 = o.objective.dmax.exact * o.objective.dmax.exact;
  if (claim == DualClaim::kWeighted) f.lambda = rational_from_text(double_to_text(o.objective.lambda));
  return f;
}

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

Rational portable_bound(const PathDualBuild& b, Eigen::Index P,
                        const std::function<Rational(const DualTerms<Rational>&)>& bound_of) {
  Rational least = bound_of(rebuilt_terms(b.value.terms, b.margin, P));
  for (const DualTerms<Rational>& moved : b.moved_terms) least = std::min(least, bound_of(rebuilt_terms(moved, b.margin, P)));
  return least;
}

DualTerms<Rational> rebuilt_terms(DualTerms<Rational> terms, const RebuildMargin& m, Eigen::Index P) {
  terms.beta -= exact_rational_of_double(m.beta_shift());
  terms.trace_U += exact_rational_of_double(std::sqrt(static_cast<double>(P)) * m.eta * (1 + 1e-9));
  return terms;
}

namespace {

/// The recipe with t moved by `ulps` units in the last place of its double.
PathDualRecipe with_t_moved(PathDualRecipe recipe, int ulps) {
  double t = nearest_double(recipe.t);
  for (int i = 0; i < std::abs(ulps); ++i) t = std::nextafter(t, ulps > 0 ? INFINITY : 0.0);
  recipe.t = exact_rational_of_double(t);
  return recipe;
}

/// U rebuilt from t moved by ±kPathDualTMoveUlps, on the recipe's grid, and
/// its exact sums (what the verifier computes from such a U). A move that
/// gives no U (t·I − TTᵀ not definite) is left out: it is not a rebuild.
std::vector<std::pair<PathDualRecipe, PathDualSums>> moved_rebuilds(const PathDualRecipe& recipe, Eigen::Index ny,
                                                                    Eigen::Index nz) {
  std::vector<std::pair<PathDualRecipe, PathDualSums>> out;
  for (int ulps : {-kPathDualTMoveUlps, kPathDualTMoveUlps}) {
    PathDualRecipe moved = with_t_moved(recipe, ulps);
    std::string problem;
    const Mat<double> U_d = path_dual_floating_u(moved, ny, nz, problem);
    if (!problem.empty()) continue;
    const PathDualGrid grid = path_dual_round(U_d, moved.u_exponent);
    if (!grid.problem.empty()) continue;
    PathDualSums sums = path_dual_sums(moved, grid.U, ny, nz);
    if (sums.problem.empty()) out.emplace_back(std::move(moved), std::move(sums));
  }
  return out;
}

/// Each moved rebuild's residual sums (step 2 of the compact form) for the same C.
std::vector<PathDualResidual> residuals_of(const std::vector<std::pair<PathDualRecipe, PathDualSums>>& moved,
                                           const Mat<Rational>& C) {
  std::vector<PathDualResidual> out;
  for (const auto& [m, m_sums] : moved) out.push_back(path_dual_residual(m, m_sums, C));
  return out;
}

/// The recipe with its taps padded by zero rows up to the horizon L (a centre
/// whose z has more leading zeros than the class's horizon).
PathDualRecipe padded_recipe(const DeltaFormSolution& s, double scale, Eigen::Index L) {
  PathDualRecipe recipe = path_recipe(s, scale);
  if (recipe.taps.rows() < L) {
    Mat<Rational> taps = Mat<Rational>::Zero(L, recipe.taps.cols());
    taps.topRows(recipe.taps.rows()) = recipe.taps;
    recipe.taps = std::move(taps);
  }
  return recipe;
}

/// σ from the terms at σ = 1 (β(1) = −(tr V + ‖g‖² + 2gᵀr) gives tr V) and the caller's shift.
Rational sigma_for(const PathDualBuild& b, const Mat<Rational>& r, const DeltaFormSolution& s, DualClaim claim,
                   const FixedValues& fixed, const SigmaShift& sigma_shift) {
  const std::pair<double, double> gg_gr = g_norms(nearest_double(b.g_effective), r);
  double trU = nearest_double(b.value.terms.trace_U);
  double trV = nearest_double(-b.value.terms.beta) - gg_gr.first - 2 * gg_gr.second;
  if (sigma_shift) {
    const auto [dU, dV] = sigma_shift(b.g_effective);
    trU += dU;
    trV += dV;
  }
  return chosen_sigma(trU, trV, gg_gr, r.rows() * r.cols(), claim, fixed, s.dual_c2(0, 0) / b.scale);
}

}  // namespace

PathDualBuild build_path_dual(const Mat<Rational>& z, const Mat<Rational>& r, Eigen::Index L, const DeltaFormSolution& s,
                              DualClaim claim, const FixedValues& fixed, const GTransform& effective_g,
                              const SigmaShift& sigma_shift, const RecordLengths& records) {
  PathDualBuild b;
  const Eigen::Index n = r.rows(), ny = r.cols(), nz = z.cols(), N = n * ny;
  if (L == 0 || nz == 0) return b.problem = "z is identically zero: no Delta form", b;
  if (s.taps.rows() > L || s.taps.cols() != ny * nz || s.dual_c2.rows() != N + 1 || !(s.path_mu > 0))
    return b.problem = "the barrier returned no central-path point of the expected size", b;
  // g on a 10⁻¹⁴ grid relative to its largest entry; μ scaled alike (homogeneous).
  const Vec<double> g_col = s.dual_c2.col(0).tail(N);
  b.scale = std::max(g_col.cwiseAbs().maxCoeff(), 1e-300);
  GridSignal gs = grid_signal(g_col, b.scale, n, ny);
  b.g_effective = effective_g ? effective_g(gs.g) : gs.g;
  PathDualRecipe recipe = padded_recipe(s, b.scale, L);
  Mat<double> U_d = path_dual_floating_u(recipe, ny, nz, b.problem);
  // Taps padded to a longer horizon make a larger T (‖T_L‖ ≥ ‖T_Lc‖): t·I − TTᵀ
  // may lose definiteness. Any t that keeps it definite gives a dual point
  // (the correction E makes its dual equality exact), so t grows until it does.
  for (int grow = 0; !b.problem.empty() && s.taps.rows() < L && grow < 40; ++grow) {
    b.problem.clear();
    recipe.t = recipe.t * Rational(5) / Rational(4);
    U_d = path_dual_floating_u(recipe, ny, nz, b.problem);
  }
  if (!b.problem.empty()) return b;
  recipe.u_exponent = path_dual_exponent(U_d);
  const PathDualGrid grid = path_dual_round(std::exchange(U_d, Mat<double>()), recipe.u_exponent);  // frees U_d
  if (!grid.problem.empty()) return b.problem = grid.problem, b;
  const PathDualSums sums = path_dual_sums(recipe, grid.U, ny, nz);
  if (!sums.problem.empty()) return b.problem = sums.problem, b;
  // The exact sums are formed once per U (main and moved) and once for g; x and σ only enter the terms.
  const Mat<Rational> C = fir_adjoint_records(b.g_effective, z, L, records);
  const GProducts gp = g_products(b.g_effective, r);
  const PathDualResidual res = path_dual_residual(recipe, sums, C);
  const auto value_at = [&](const PathDualRecipe& at, const PathDualSums& at_sums, const PathDualResidual& at_res,
                            const Rational& sigma) {
    return PathDualValue{at_res.E_norm2, path_dual_terms(at, at_sums, at_res, gp, sigma, N, nz)};
  };
  b.margin = rebuild_margin(recipe, grid);
  // x covers the largest E among the recipe's U and the moved rebuilds (E depends on neither x nor σ).
  auto moved = moved_rebuilds(recipe, ny, nz);
  const std::vector<PathDualResidual> moved_res = residuals_of(moved, C);
  Rational E_norm2 = res.E_norm2;
  for (const PathDualResidual& m : moved_res) E_norm2 = std::max(E_norm2, m.E_norm2);
  if (std::string why = prove_floor(recipe, grid, E_norm2, b.margin); !why.empty()) return b.problem = why, b;
  b.value = value_at(recipe, sums, res, Rational(1));
  const Rational sigma = sigma_for(b, r, s, claim, fixed, sigma_shift);
  if (!(sigma > 0)) return b.problem = "no positive sigma", b;
  b.value = value_at(recipe, sums, res, sigma);
  for (size_t k = 0; k < moved.size(); ++k) {
    auto& [m, m_sums] = moved[k];
    m.x = recipe.x;
    m.floor = recipe.floor;
    b.moved_terms.push_back(value_at(m, m_sums, moved_res[k], sigma).terms);
  }
  b.point.horizon = L;
  b.point.g = std::move(gs.g);
  b.point.sigma = sigma;
  b.point.path = std::move(recipe);
  return b;
}

}  // namespace lpvid
