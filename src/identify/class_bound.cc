#include "identify/class_bound.h"

#include <chrono>
#include <cmath>

#include "certify/class_dual.h"
#include "core/deadline.h"
#include "core/decimal_rounding.h"
#include "core/number_text.h"
#include "core/stopwatch.h"
#include "lmi/delta_form_barrier.h"
#include "model/simulate.h"
#include "toeplitz/signal_toeplitz.h"
#include "verify/certificate/certificate_check.h"

namespace lpvid {
namespace {

/// One node of the branch-and-bound tree (children by index; −1: a leaf).
struct TreeNode {
  long split = -1;
  int lower = -1, upper = -1;
  Vec<Rational> center, radius;
  ClassLeafBuild leaf;
  Vec<Rational> cost_radius;  ///< the radii leaf.cost was computed for (an inherited leaf: its parent's)
  int source = -1;            ///< the node whose dual point this leaf carries (−1: its own)
  Vec<double> p;          ///< the solve's parameters (free ones from the solver)
  std::shared_ptr<const DeltaFormSolution> solution;  ///< kept when every parameter is free (one leaf)
  double objective = 0;   ///< the solver's objective there
};

/// What every leaf solve shares.
struct Search {
  const ClassSignals& s;
  const AffineResidual<double>& a;
  Mat<double> free_columns;  ///< (n·ny) × |free|, doubles
  BoundObjective objective;
  DualClaim claim;
  FixedValues fixed;
  std::function<void(const std::string&)> progress;  ///< stage lines with their times (may be empty)
};

/// "what in X s" on the progress line, when there is one.
void tell(const Search& q, const std::string& what, const Stopwatch& since) {
  if (q.progress) q.progress("class bound: " + what + " in " + double_to_text(std::round(since.seconds() * 10) / 10) + " s");
}

Vec<double> to_double(const Vec<Rational>& v) {
  Vec<double> d(v.size());
  for (Eigen::Index i = 0; i < v.size(); ++i) d(i) = nearest_double(v(i));
  return d;
}

/// Solves the leaf's centre with the free parameters as free regressors and
/// builds its dual point. `problem` set when either fails.
std::string evaluate(const Search& q, TreeNode& node) {
  const Stopwatch solve_time;
  const Vec<double> c = to_double(node.center);
  const Mat<double> z = unstack_rows(q.a.z(c), q.a.nz), r = unstack_rows(q.a.r(c), q.a.ny);
  DeltaFormSolution sol = solve_delta_form_barrier(z, r, q.objective, BarrierOptions{}, q.free_columns, q.a.records);
  const bool answered = has_solution(sol.solve.status) ||
                        (q.claim == DualClaim::kInvalidated && sol.solve.status == SolveStatus::kPrimalInfeasible);
  if (!answered) return "the structured solver gave no answer at a leaf's centre: " + sol.solve.message;
  if (q.claim == DualClaim::kInvalidated && has_solution(sol.solve.status))
    return "a parameter of the region explains the data at the fixed bounds (the solver found a point): not invalidated";
  node.p = c;
  for (size_t k = 0; k < q.s.free.size(); ++k) node.p(q.s.free[k]) = sol.free_coefficients(static_cast<Eigen::Index>(k));
  node.objective = q.objective.value(sol.delta2, sol.dmax2);
  tell(q, "a leaf's centre solved", solve_time);
  const Stopwatch build_time;
  node.leaf = build_class_leaf(q.s, node.center, node.radius, sol, q.claim, q.fixed);
  node.cost_radius = node.radius;
  if (q.s.boxed.empty()) node.solution = std::make_shared<const DeltaFormSolution>(std::move(sol));
  tell(q, "its dual point built and bounded exactly", build_time);
  return node.leaf.problem;
}

/// The leaf with the lowest bound.
int lowest_leaf(const std::vector<TreeNode>& tree) {
  int best = -1;
  for (int i = 0; i < static_cast<int>(tree.size()); ++i)
    if (tree[i].split < 0 && (best < 0 || tree[i].leaf.bound < tree[best].leaf.bound)) best = i;
  return best;
}

/// A child keeps its parent's dual point when that bounds its box better: made
/// at the parent's expansion point, seen from there the child's box is within
/// the parent's (ρ'_i = |p_e,i − c_i| + ρ_i ≤ the parent's ρ_i), so the bound
/// carries over and the tree's lowest leaf never falls when a leaf is split.
void inherit(const TreeNode& parent, int parent_index, TreeNode& child) {
  if (!(parent.leaf.bound > child.leaf.bound)) return;
  child.leaf = parent.leaf;
  child.cost_radius = parent.cost_radius;
  child.source = parent.source >= 0 ? parent.source : parent_index;
  if (child.leaf.node.expansion.size() == 0) child.leaf.node.expansion = parent.center;
}

/// Splits leaf `at` along its costliest boxed coordinate; false when nothing can be split.
std::string split(const Search& q, std::vector<TreeNode>& tree, int at) {
  // each coordinate's cost scaled to this leaf's own half-width (an inherited cost was computed for the parent's)
  std::vector<double> cost = tree[at].leaf.cost;
  for (size_t j = 0; j < cost.size(); ++j) {
    const long c = q.s.boxed[j];
    if (tree[at].cost_radius(c) > 0) cost[j] *= nearest_double(tree[at].radius(c)) / nearest_double(tree[at].cost_radius(c));
  }
  int k = -1;
  for (int j = 0; j < static_cast<int>(cost.size()); ++j)
    if (cost[j] > 0 && (k < 0 || cost[j] > cost[k])) k = j;
  if (k < 0) return "no coordinate left to split";
  const long i = q.s.boxed[static_cast<size_t>(k)];
  TreeNode lo, hi;
  lo.radius = hi.radius = tree[at].radius;
  lo.radius(i) = hi.radius(i) = tree[at].radius(i) / Rational(2);
  lo.center = hi.center = tree[at].center;
  lo.center(i) -= lo.radius(i);
  hi.center(i) += hi.radius(i);
  if (std::string why = evaluate(q, lo); !why.empty()) return why;
  if (std::string why = evaluate(q, hi); !why.empty()) return why;
  inherit(tree[at], at, lo);
  inherit(tree[at], at, hi);
  tree[at].split = i;
  tree[at].lower = static_cast<int>(tree.size());
  tree.push_back(std::move(lo));
  tree[at].upper = static_cast<int>(tree.size());
  tree.push_back(std::move(hi));
  return "";
}

/// The node whose dual point `at` carries.
int source_of(const std::vector<TreeNode>& tree, int at) { return tree[at].source >= 0 ? tree[at].source : at; }

/// True when every leaf below `at` carries the dual point of node `source`
/// (then the subtree adds nothing to that point's own leaf).
bool carries_only(const std::vector<TreeNode>& tree, int at, int source) {
  if (tree[at].split < 0) return source_of(tree, at) == source;
  return carries_only(tree, tree[at].lower, source) && carries_only(tree, tree[at].upper, source);
}

/// The tree in preorder, a subtree whose leaves all inherited its root's point collapsed to that leaf.
void preorder(std::vector<TreeNode>& tree, int at, std::vector<ClassNode>& out) {
  if (tree[at].split >= 0 && carries_only(tree, at, source_of(tree, at))) {
    out.push_back(tree[at].leaf.node);
    return;
  }
  if (tree[at].split >= 0) {
    ClassNode n;
    n.split = tree[at].split;
    out.push_back(n);
    preorder(tree, tree[at].lower, out);
    preorder(tree, tree[at].upper, out);
    return;
  }
  out.push_back(std::move(tree[at].leaf.node));
}

/// The box: centre θ̂ (12 digits) and ρ_i = fraction·‖z(θ̂)‖/‖Jz_i‖ (3 digits) on the boxed coordinates.
void initial_box(const ClassSignals& s, const AffineResidual<double>& a, const Vec<double>& found_p, double fraction,
                 TreeNode& root) {
  const Eigen::Index P = a.num_params();
  root.center = Vec<Rational>::Zero(P);
  root.radius = Vec<Rational>::Zero(P);
  const double zn = a.z(found_p).norm();
  for (const long i : s.boxed) {
    root.center(i) = round_to_digits(found_p(i), 12);
    const double jz = a.Jz.col(i).norm();
    if (jz > 0 && zn > 0) root.radius(i) = round_to_digits(fraction * zn / jz, 3);
  }
}

}  // namespace

namespace {

/// The parameters that do not move z (exactly): they range over all reals.
std::vector<long> free_parameters(const AffineResidual<Rational>& a) {
  std::vector<long> free;
  for (Eigen::Index i = 0; i < a.num_params(); ++i)
    if (a.Jz.col(i).isZero()) free.push_back(static_cast<long>(i));
  return free;
}

/// Splits the lowest leaf until it is within the stopping gap of `upper`, the
/// leaf budget is spent or nothing can be split. Empty string, or why a leaf failed.
std::string branch_and_bound(const Search& q, const ClassBoundOptions& o, std::vector<TreeNode>& tree,
                             const std::function<void(const std::string&)>& progress) {
  // a lower end stops after stall_splits splits without progress; an invalidation uses its whole budget
  const int stall_limit = q.claim == DualClaim::kInvalidated ? 0 : o.stall_splits;
  int leaves = 1, stalled = 0;
  while (leaves < o.max_leaves && (stall_limit <= 0 || stalled < stall_limit)) {
    check_deadline("the class bound was branching");  // the user's --timeout or a requested stop, between leaves
    const int at = lowest_leaf(tree);
    const double low = nearest_double(tree[at].leaf.bound);
    if (o.upper > 0 && low >= (1 - o.stop_rel_gap) * o.upper) break;
    if (q.s.boxed.empty() || (q.claim == DualClaim::kInvalidated && low > 0)) break;
    if (std::string why = split(q, tree, at); !why.empty()) return why == "no coordinate left to split" ? "" : why;
    ++leaves;
    stalled = tree[lowest_leaf(tree)].leaf.bound > tree[at].leaf.bound ? 0 : stalled + 1;
    if (progress)
      progress("class bound: " + std::to_string(leaves) + " leaves, lowest " + double_to_text(nearest_double(tree[lowest_leaf(tree)].leaf.bound)));
  }
  return "";
}

/// The class certificate around the tree (claim, objective, region), checked
/// after its JSON round trip on the exact experiment.
std::string certify_tree(const LpvModel<Rational>& model_q, const Experiment<Rational>& exp_q, const Search& q,
                         const CertifyOptions& certify, const ClassBoundOptions& o, std::vector<TreeNode>& tree,
                         ClassBoundResult& out) {
  Certificate c;
  c.model = model_q;
  c.mode = ToeplitzMode::kSignal;
  c.form = CertificateForm::kDualDeltaPath;
  c.claim = q.claim == DualClaim::kInvalidated ? CertificateClaim::kClassInvalidated : CertificateClaim::kClassLowerBound;
  c.objective = q.claim;
  c.delta2 = q.fixed.delta2;
  c.dmax2 = q.fixed.dmax2;
  c.lambda = q.fixed.lambda;
  const Rational lowest = tree[lowest_leaf(tree)].leaf.bound;
  c.lower_bound = q.claim == DualClaim::kInvalidated ? Rational(0) : round_down_to_digits(lowest, 12);
  if (q.claim == DualClaim::kInvalidated && !(lowest > 0)) return "the lowest leaf's margin is not > 0: not invalidated";
  if (q.claim != DualClaim::kInvalidated && !(c.lower_bound > 0))
    return "no useful class bound: the lowest leaf's bound is 0 (a smaller box, --class-box, or more leaves, "
           "--class-leaves, may give one)";
  c.region.unknowns = o.unknowns;
  c.region.parameters = q.s.a.names;
  c.region.free = q.s.free;
  c.region.center = tree[0].center;
  c.region.radius = tree[0].radius;
  c.region.horizon = q.s.horizon;
  preorder(tree, 0, c.region.nodes);
  name_certificate_data(c, certify, exp_q);
  c.info["tool"] = "lpvid";
  c.info["objective"] = certify.objective.describe();
  c.info["box_fraction"] = o.box_fraction;
  const Stopwatch check_time;
  const CertificateVerdict v = check_round_trip(c, exp_q, "the class certificate (in memory)");
  tell(q, "the class certificate checked exactly", check_time);
  if (!v.holds) return "the class certificate failed the exact check: " + v.reason;
  out.lower = c.lower_bound;
  out.certificate = std::move(c);
  return "";
}

}  // namespace

ClassBoundResult class_lower_bound(const Problem& problem, const Vec<double>& found_p, const CertifyOptions& certify,
                                   const ClassBoundOptions& o) {
  const auto& [model_q, model_d, exp_q, exp_d] = problem;
  const auto t0 = std::chrono::steady_clock::now();
  const Stopwatch signals_time;
  ClassBoundResult out;
  const auto done = [&](std::string reason) {
    out.reason = std::move(reason);
    out.outcome = out.reason.empty() ? ClassBoundOutcome::kCertified : ClassBoundOutcome::kNotCertified;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  };
  if (std::string why = non_affine_unknowns(model_q, o.unknowns); !why.empty()) return done(why);
  const AffineResidual<double> a = build_affine_residual(model_d, with_state_scheduling(model_d, exp_d), o.unknowns);
  AffineResidual<Rational> aq = build_affine_residual(model_q, with_state_scheduling(model_q, exp_q), o.unknowns);
  const std::vector<long> free = free_parameters(aq);
  ClassSignals s;
  if (std::string why = class_signals(std::move(aq), free, s); !why.empty()) return done(why);
  if (certify.progress) certify.progress("class bound: affine signals (double and exact) in " + double_to_text(std::round(signals_time.seconds() * 10) / 10) + " s");
  if (found_p.size() != a.num_params()) return done("the identified parameters do not fit the class's layout");
  const DualClaim claim = claim_of(certify.objective);
  Search q{s, a, Mat<double>(a.Jr.rows(), static_cast<Eigen::Index>(free.size())), certify.objective, claim,
           fixed_values(certify, claim), certify.progress};
  for (size_t k = 0; k < free.size(); ++k) q.free_columns.col(static_cast<Eigen::Index>(k)) = a.Jr.col(free[k]);
  out.free = free;
  out.names = a.names;
  out.whole_class = s.boxed.empty();
  std::vector<TreeNode> tree(1);
  initial_box(s, a, found_p, o.box_fraction, tree[0]);
  out.center = to_double(tree[0].center);
  out.radius = to_double(tree[0].radius);
  if (std::string why = evaluate(q, tree[0]); !why.empty()) return done(why);
  if (std::string why = branch_and_bound(q, o, tree, certify.progress); !why.empty()) return done(why);
  const TreeNode& low = tree[lowest_leaf(tree)];
  out.best_p = low.p;
  out.best_objective = low.objective;
  out.best_solution = low.solution;
  std::string why = certify_tree(model_q, exp_q, q, certify, o, tree, out);
  if (out.certificate) {
    out.leaves = 0;
    for (const ClassNode& n : out.certificate->region.nodes) out.leaves += n.split < 0 ? 1 : 0;
  }
  return done(why);
}

}  // namespace lpvid
