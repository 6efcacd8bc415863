#include "verify/certificate/class_check.h"

#include <sstream>

#include "core/number_text.h"
#include "model/simulate.h"
#include "toeplitz/fir.h"
#include "verify/certificate/class_terms.h"
#include "verify/certificate/path_dual.h"
#include "verify/certificate/verdict_text.h"
#include "verify/psd/check_progress.h"
#include "verify/psd/exact_psd.h"
#include "verify/psd/work_limits.h"

namespace lpvid {
namespace {

/// A leaf's exact value: its bound, or why the point is not a dual point.
struct LeafValue {
  std::string problem;
  Rational bound;
};

/// The dense form at (z, r) with the projected g: dual equality, terms, Y1 ⪰ 0.
std::string dense_leaf_terms(const DualPoint& d, const Mat<Rational>& z, const Mat<Rational>& r, const Mat<Rational>& g,
                             Eigen::Index ny, Eigen::Index nz, DualTerms<Rational>& terms, const RecordLengths& records) {
  const Eigen::Index L = d.horizon;
  if (d.Y1.rows() != L * (ny + nz)) return "Y1 does not have horizon*(ny+nz) rows";
  const Mat<Rational> omega = block_diagonal_sums(d.Y1, L, ny, nz);
  const Mat<Rational> adj = fir_adjoint_records(g, z, L, records);
  if (omega != adj) return "the dual equality Omega_l(W) = C_l(g) fails (exact comparison, g projected)";
  terms = dual_terms(d.Y1, g, d.sigma, r, L);
  const PsdResult psd = decide_psd(d.Y1);
  if (psd.verdict == PsdVerdict::kNotPsd) return "Y1 is not PSD (" + psd.reason + ")";
  return "";
}

/// The compact form: Y1 rebuilt from the recipe, E within the floor, U − γI ⪰ 0.
std::string path_leaf_terms(const DualPoint& d, const Mat<Rational>& z, const Mat<Rational>& r, const Mat<Rational>& g,
                            Eigen::Index ny, Eigen::Index nz, DualTerms<Rational>& terms, const RecordLengths& records) {
  const PathDualRecipe& p = d.path;
  if (p.taps.rows() != d.horizon) return "the recipe's taps do not have horizon rows";
  require_dual_order(static_cast<long>(d.horizon * ny));
  check_progress(dual_step_work(d.horizon * ny), "a class leaf: its compact dual point of order " +
                                                      std::to_string(d.horizon * ny));
  const PathDualGrid grid = path_dual_grid(p, ny, nz);
  if (!grid.problem.empty()) return "the dual recipe gives no point: " + grid.problem;
  const PathDualSums sums = path_dual_sums(p, grid.U, ny, nz);
  if (!sums.problem.empty()) return "the dual recipe gives no point: " + sums.problem;
  const PathDualValue v = path_dual_value(p, sums, fir_adjoint_records(g, z, d.horizon, records), g, d.sigma, r, ny, nz);
  if (v.E_norm2 > p.x * p.floor)
    return "the correction E of the dual equality is too large for the floor: ||E||_F^2 = " + approx_text(v.E_norm2, 8) +
           " > x*u_floor = " + approx_text(p.x * p.floor, 8);
  terms = v.terms;
  const PsdResult psd = path_dual_psd(p, grid.U, true);
  if (psd.verdict == PsdVerdict::kNotPsd) return "U - u_floor*I is not PSD (" + psd.reason + ")";
  return "";
}

/// ρ'_i = |p_e,i − c_i| + ρ_i on the boxed coordinates: the box seen from p_e.
Vec<Rational> expansion_radius(const ClassSignals& s, const Vec<Rational>& point, const Vec<Rational>& center,
                               const Vec<Rational>& radius) {
  Vec<Rational> reach = radius;
  for (const long i : s.boxed) {
    const Rational d = point(i) - center(i);
    reach(i) += d < 0 ? Rational(-d) : d;
  }
  return reach;
}

LeafValue leaf_value(const Certificate& c, const ClassSignals& s, const ClassNode& leaf, const Vec<Rational>& center,
                     const Vec<Rational>& radius) {
  const Eigen::Index ny = c.model.ny, nz = c.model.nz();
  if (leaf.dual.horizon != s.horizon) return {"its horizon is not the class's", {}};
  if (leaf.dual.g.rows() != s.a.n) return {"its g does not have one row per sample", {}};
  if (!(leaf.dual.sigma > 0)) return {"its sigma is not > 0", {}};
  // The expansion point (the box's centre unless stated) and the radii seen from it.
  const bool moved = leaf.expansion.size() > 0;
  if (moved && leaf.expansion.size() != center.size()) return {"its expansion point does not have one number per parameter", {}};
  const Vec<Rational>& point = moved ? leaf.expansion : center;
  const Vec<Rational> reach = moved ? expansion_radius(s, point, center, radius) : radius;
  const Mat<Rational> z = class_z(s, point), r = class_r(s, point);
  const Mat<Rational> g = project_out_free(leaf.dual.g, s.free_columns);
  DualTerms<Rational> terms;
  const std::string why = c.form == CertificateForm::kDualDeltaPath
                              ? path_leaf_terms(leaf.dual, z, r, g, ny, nz, terms, s.a.records)
                              : dense_leaf_terms(leaf.dual, z, r, g, ny, nz, terms, s.a.records);
  if (!why.empty()) return {why, {}};
  const ClassPenalty pen = class_penalty(s, reach, g);
  if (!pen.problem.empty()) return {pen.problem, {}};
  return {"", dual_bound(leaf_terms(terms, pen, leaf.epsilon), c.objective, c.delta2, c.dmax2, c.lambda)};
}

/// Walks the preorder tree from node `at` over the box (center, radius);
/// returns the next node index, or −1 with `why` set.
struct TreeWalk {
  const Certificate& c;
  const ClassSignals& s;
  Rational lowest;
  long leaves = 0;
  std::string why;
};
long walk(TreeWalk& w, size_t at, const Vec<Rational>& center, const Vec<Rational>& radius) {
  const ClassNode& node = w.c.region.nodes[at];
  const std::string where = "class.nodes[" + std::to_string(at) + "]";
  if (node.split >= 0) {
    const long i = node.split;
    if (std::find(w.s.free.begin(), w.s.free.end(), i) != w.s.free.end() || !(radius(i) > 0)) {
      w.why = where + " splits parameter " + std::to_string(i) + ", which is free or has radius 0";
      return -1;
    }
    Vec<Rational> half = radius, lower = center, upper = center;
    half(i) = radius(i) / Rational(2);
    lower(i) -= half(i);
    upper(i) += half(i);
    const long next = walk(w, at + 1, lower, half);
    return next < 0 ? -1 : walk(w, static_cast<size_t>(next), upper, half);
  }
  const LeafValue v = leaf_value(w.c, w.s, node, center, radius);
  if (!v.problem.empty()) {
    w.why = where + ": " + v.problem;
    return -1;
  }
  if (w.leaves == 0 || v.bound < w.lowest) w.lowest = v.bound;
  ++w.leaves;
  return static_cast<long>(at) + 1;
}

std::string claim_problem(const Certificate& c, const Rational& lowest) {
  if (c.claim == CertificateClaim::kClassInvalidated)
    return lowest > 0 ? "" : "a leaf's margin beta - delta2*tr(U) - N*dmax2*sigma (with the class terms) is " +
                                 approx_text(lowest, 8) + ", not > 0";
  return lowest >= c.lower_bound ? "" : "the lowest leaf gives the lower bound " + approx_text(lowest, 8) + ", below the claimed " +
                                            approx_text(c.lower_bound, 8);
}

}  // namespace

CertificateVerdict check_class_claim(const Certificate& c, const Experiment<Rational>& exp_in, std::string details) {
  if (c.mode != ToeplitzMode::kSignal) return invalid_verdict("a class claim is only defined for toeplitz_mode \"signal\"", details);
  // The premise of every class claim: z(p), r(p) affine in the unknowns (x0 with a
  // correction basis, state scheduling or a state offset is not).
  if (std::string why = non_affine_unknowns(c.model, c.region.unknowns); !why.empty()) return invalid_verdict(why, details);
  const Experiment<Rational> exp = with_state_scheduling(c.model, exp_in);
  ClassSignals s;
  if (std::string why = class_signals(build_affine_residual(c.model, exp, c.region.unknowns), c.region.free, s); !why.empty())
    return invalid_verdict(why, details);
  if (s.a.names != c.region.parameters)
    return invalid_verdict("class.parameters do not name the parameters of this model and these unknowns", details);
  if (c.region.horizon != s.horizon)
    return invalid_verdict("class.horizon is " + std::to_string(c.region.horizon) + " but z is zero for every parameter on the first " +
                               std::to_string(s.a.n - s.horizon) + " samples, so it must be " + std::to_string(s.horizon),
                           details);
  TreeWalk w{c, s, Rational(0), 0, ""};
  if (walk(w, 0, c.region.center, c.region.radius) < 0) return invalid_verdict(w.why, details);
  std::ostringstream d;
  d << details << ", class of " << s.a.num_params() << " parameters (" << s.free.size() << " free, " << s.boxed.size()
    << " boxed), " << w.leaves << (w.leaves == 1 ? " leaf" : " leaves") << " of horizon " << s.horizon << ", every leaf's dual point checked exactly; lowest leaf "
    << approx_text(w.lowest, 8);
  if (std::string why = claim_problem(c, w.lowest); !why.empty()) return invalid_verdict(why, d.str());
  return CertificateVerdict::holding(d.str());
}

}  // namespace lpvid
