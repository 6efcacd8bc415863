#include "certify/class_dual.h"

#include <cmath>

#include "core/decimal_rounding.h"
#include "core/number_text.h"

namespace lpvid {
namespace {

/// ε of c·√t ≤ c·(t/(2ε) + ε/2): tight at t = ε², so ε = √t at the solver's
/// point (δ itself when δ is fixed), a short rational.
Rational epsilon_for(const DeltaFormSolution& solution, DualClaim claim, const FixedValues& fixed) {
  const bool delta_fixed = claim == DualClaim::kInvalidated || claim == DualClaim::kMinDmax2;
  const double t = delta_fixed ? nearest_double(fixed.delta2) : solution.delta2;
  return round_to_digits(std::max(std::sqrt(std::max(t, 0.0)), 1e-12), 6);
}

/// Each boxed parameter's share of the penalties (for choosing a split).
std::vector<double> penalty_costs(const ClassSignals& s, const Vec<Rational>& radius, const Mat<Rational>& g, double t) {
  const Vec<double> gv = nearest_double(Mat<Rational>(g)).reshaped<Eigen::RowMajor>();
  const double gnorm = gv.norm();
  std::vector<double> cost;
  for (const long i : s.boxed) {
    const Vec<double> jr = nearest_double(Mat<Rational>(s.a.Jr.col(i))), jz = nearest_double(Mat<Rational>(s.a.Jz.col(i)));
    cost.push_back(nearest_double(radius(i)) * (2 * std::fabs(gv.dot(jr)) + 2 * gnorm * std::sqrt(std::max(t, 0.0)) * jz.norm()));
  }
  return cost;
}

}  // namespace

ClassLeafBuild build_class_leaf(const ClassSignals& s, const Vec<Rational>& center, const Vec<Rational>& radius,
                                const DeltaFormSolution& solution, DualClaim claim, const FixedValues& fixed) {
  ClassLeafBuild out;
  const Rational epsilon = epsilon_for(solution, claim, fixed);
  const Mat<Rational> z = class_z(s, center), r = class_r(s, center);
  const GTransform project = [&s](const Mat<Rational>& g) { return project_out_free(g, s.free_columns); };
  const SigmaShift shift = [&](const Mat<Rational>& g) {
    const ClassPenalty p = class_penalty(s, radius, g);
    const double c = nearest_double(p.bilinear), e = nearest_double(epsilon);
    return std::make_pair(c / (2 * e), nearest_double(p.linear) + c * e / 2);
  };
  PathDualBuild b = build_path_dual(z, r, s.horizon, solution, claim, fixed, project, shift, s.a.records);
  if (!b.problem.empty()) return out.problem = b.problem, out;
  const ClassPenalty pen = class_penalty(s, radius, b.g_effective);
  if (!pen.problem.empty()) return out.problem = pen.problem, out;
  const Rational exact = dual_bound(leaf_terms(b.value.terms, pen, epsilon), claim, fixed.delta2, fixed.dmax2, fixed.lambda);
  const Rational portable = portable_bound(b, s.horizon * s.a.ny, [&](const DualTerms<Rational>& terms) {
    return dual_bound(leaf_terms(terms, pen, epsilon), claim, fixed.delta2, fixed.dmax2, fixed.lambda);
  });
  const Rational slack = exact > 0 ? exact * power_of_ten(-9) : Rational(0);
  out.bound = std::min(portable, exact - slack);
  out.node.dual = std::move(b.point);
  out.node.epsilon = epsilon;
  out.cost = penalty_costs(s, radius, b.g_effective, nearest_double(epsilon) * nearest_double(epsilon));
  return out;
}

}  // namespace lpvid
