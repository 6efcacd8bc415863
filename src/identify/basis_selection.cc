#include "identify/basis_selection.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

#include "core/input_error.h"
#include "identify/fix_and_certify.h"
#include "model/simulate.h"
#include "identify/identify.h"

namespace lpvid {
namespace {

/// All exponent vectors of length n with total degree ≤ d.
void enumerate(int n, int d, std::vector<int>& cur, std::vector<std::vector<int>>& out) {
  if (static_cast<int>(cur.size()) == n) {
    out.push_back(cur);
    return;
  }
  for (int p = 0; p <= d; ++p) {
    cur.push_back(p);
    enumerate(n, d - p, cur, out);
    cur.pop_back();
  }
}

int degree_of(const std::vector<int>& e) {
  int s = 0;
  for (int p : e) s += p;
  return s;
}

bool multilinear(const std::vector<int>& e) {
  return std::all_of(e.begin(), e.end(), [](int p) { return p <= 1; });
}

bool pure_power(const std::vector<int>& e) {
  return std::count_if(e.begin(), e.end(), [](int p) { return p > 0; }) == 1;
}

/// Stage of the growth order: 0 constant, 1 affine, 2 multilinear, 3 the rest.
int stage(const std::vector<int>& e) {
  const int d = degree_of(e);
  if (d <= 1) return d;
  return multilinear(e) ? 2 : 3;
}

using BasisKey = std::vector<std::vector<int>>;

BasisKey key_of(const std::vector<Monomial>& basis) {
  BasisKey k;
  for (const Monomial& m : basis) k.push_back(m.powers);
  std::sort(k.begin(), k.end());
  return k;
}

bool subset(const std::vector<Monomial>& a, const std::vector<Monomial>& b) {
  for (const Monomial& m : a)
    if (std::find(b.begin(), b.end(), m) == b.end()) return false;
  return true;
}

int unknown_offset_count(const LpvModel<double>& m) {
  return m.offset.values.empty() ? static_cast<int>(m.offset.basis.size()) : 0;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The selection's outcome: found when a step was kept; otherwise "cannot
/// explain" only with a whole-class certificate of the largest basis grown
/// (the last grow or initial step), else not verified when some step's
/// answer failed the exact check, else not decided.
SelectionOutcome outcome_of(const std::vector<BasisStep>& steps, int final_step) {
  if (final_step >= 0) return SelectionOutcome::kFound;
  for (auto s = steps.rbegin(); s != steps.rend(); ++s)
    if (s->phase == "grow" || s->phase == "initial") {
      if (s->verdict == BasisVerdict::kCannotExplain) return SelectionOutcome::kCannotExplain;
      break;
    }
  for (const BasisStep& s : steps)
    if (s.verdict == BasisVerdict::kUnverified) return SelectionOutcome::kNotVerified;
  return SelectionOutcome::kNotDecided;
}

class Selector {
 public:
  Selector(const Problem& p, const BasisSelectionOptions& o, SdpSolver& s)
      : mq_(p.model_q), md_(p.model_d), eq_(p.exp_q), ed_(p.exp_d), o_(o), solver_(s) {}

  BasisSelectionResult run() {
    BasisSelectionResult r;
    r.order = basis_growth_order(md_.n_rho(), o_.max_degree);
    // 0. S_I alone (Theorem 2.1; with its offset identified, if unknown).
    std::vector<Monomial> basis;
    const BasisStep& s0 = evaluate(basis, "initial");
    int final_step = s0.verdict == BasisVerdict::kConsistent ? s0.index : -1;
    // 1. Grow, one monomial at a time.
    for (size_t i = 0; final_step < 0 && i < r.order.size(); ++i) {
      basis.push_back(r.order[i]);
      const BasisStep& s = evaluate(basis, "grow");
      if (s.verdict == BasisVerdict::kConsistent) final_step = s.index;
    }
    // 2. Remove, most recent term first, one pass.
    if (final_step >= 0 && o_.prune && !basis.empty()) {
      const std::vector<Monomial> grown = basis;
      for (auto t = grown.rbegin(); t != grown.rend(); ++t) {
        std::vector<Monomial> smaller;
        for (const Monomial& m : basis)
          if (!(m == *t)) smaller.push_back(m);
        const BasisStep& s = evaluate(smaller, "remove");
        if (s.kept) {
          basis = smaller;
          final_step = s.index;
        }
      }
    }
    r.steps = steps_;
    r.final_step = final_step;
    if (final_step >= 0) r.basis = steps_[static_cast<size_t>(final_step)].basis;
    r.outcome = outcome_of(r.steps, final_step);
    return r;
  }

 private:
  const BasisStep& evaluate(const std::vector<Monomial>& basis, const std::string& phase) {
    BasisStep s;
    s.index = static_cast<int>(steps_.size());
    s.phase = phase;
    s.basis = basis;
    s.basis_text = lpvid::basis_text(basis, md_.scheduling);
    const BasisKey key = key_of(basis);
    if (auto it = seen_.find(key); it != seen_.end()) {
      const BasisStep& prev = steps_[static_cast<size_t>(it->second)];
      s.verdict = prev.verdict;
      s.bounds = prev.bounds;
      s.certificate = prev.certificate;
      s.dmax_relaxation = prev.dmax_relaxation;
      s.relaxation = prev.relaxation;
      s.layout = prev.layout;
      s.p = prev.p;
      s.klass = prev.klass;
      s.class_centered_at_fit = prev.class_centered_at_fit;
      s.same_as = prev.index;
      s.detail = "same basis as step " + std::to_string(prev.index) + " (not solved again)";
    } else {
      const auto t0 = std::chrono::steady_clock::now();
      solve(s);
      s.seconds = seconds_since(t0);
      seen_[key] = s.index;
    }
    s.kept = phase == "remove" && s.verdict == BasisVerdict::kConsistent;
    steps_.push_back(s);
    if (o_.on_step) o_.on_step(steps_.back());
    return steps_.back();
  }

  CertifyOptions certify_options() const {
    CertifyOptions co = o_.certify;
    co.objective.kind = BoundObjective::Kind::kFeasibility;
    co.objective.delta = o_.delta;
    co.objective.dmax = o_.dmax;
    co.solver = o_.solver;
    return co;
  }

  /// Sets the verdict from a certification of a fixed model.
  void judge(BasisStep& s, const CertifiedBounds& b, const std::string& what) {
    s.bounds = b;
    ++s.solves;
    if (b.verified()) {
      s.verdict = BasisVerdict::kConsistent;
      s.detail = what + " is consistent at the given bounds: certificate verified exactly";
    } else if (b.invalidated()) {
      // This one model is refuted exactly (e.g. at delta = 0 in closed form); for the
      // algorithm that is "not decided", as a box invalidation: the class may still help.
      s.verdict = BasisVerdict::kNotDecided;
      s.detail = what + " is invalidated at the given bounds: an invalidation certificate checked exactly (" +
                 b.reason + ")";
    } else if (b.solve_status == SolveStatus::kPrimalInfeasible) {
      s.verdict = BasisVerdict::kNotDecided;
      s.detail = what + ": the solver found the Theorem 2.1 LMI infeasible at the given bounds (a solver verdict)";
    } else {
      s.verdict = BasisVerdict::kUnverified;
      s.detail = what + ": not verified: " + b.reason;
    }
  }

  Unknowns unknowns() const {
    Unknowns u = o_.unknowns;
    u.correction = true;
    return u;
  }

  /// A step not certified consistent: the class certificate over the
  /// step's basis (whole class, or a box centred at `centre`, zero when empty).
  void certify_class(BasisStep& s, const Problem& step, Vec<double> centre) {
    if (!o_.class_certificates || s.verdict == BasisVerdict::kConsistent) return;
    ClassBoundOptions cbo = o_.klass;
    cbo.unknowns = unknowns();
    cbo.upper = 0;
    s.class_centered_at_fit = centre.size() > 0;
    if (!s.class_centered_at_fit)
      centre = Vec<double>::Zero(
          build_affine_residual(step.model_d, with_state_scheduling(step.model_d, ed_), cbo.unknowns).num_params());
    ClassBoundResult k = class_lower_bound(step, centre, certify_options(), cbo);
    s.solves += k.leaves;
    if (k.certified()) {
      s.verdict = k.whole_class ? BasisVerdict::kCannotExplain : BasisVerdict::kBoxInvalidated;
      s.detail = (k.whole_class ? "no theta of this basis" : "no theta of the box around the " +
                                                                 std::string(s.class_centered_at_fit ? "identified theta" : "initial model (theta = 0)")) +
                 " explains the data at the given bounds: class certificate checked exactly (" + std::to_string(k.leaves) +
                 (k.leaves == 1 ? " leaf" : " leaves") + (k.whole_class ? ")" : "; theta outside the box is not decided)") +
                 "; before it: " + s.detail;
    } else {
      s.detail += "; no class certificate: " + k.reason;
    }
    s.klass = std::move(k);
  }

  void solve(BasisStep& s) {
    // the model with the step's basis, in both views, beside the data (copied)
    const Problem step{with_correction_basis(mq_, s.basis), with_correction_basis(md_, s.basis), eq_, ed_};
    Vec<double> centre;
    identify_step(s, step.model_q, step.model_d, centre);
    certify_class(s, step, centre);
  }

  /// The solver's side of a step: the fit and its certification (`centre`: the fit's parameters, if any).
  void identify_step(BasisStep& s, const LpvModel<Rational>& mq, const LpvModel<double>& md, Vec<double>& centre) {
    const CertifyOptions co = certify_options();
    const bool unknowns = !s.basis.empty() || (o_.unknowns.offset && unknown_offset_count(md) > 0) || o_.unknowns.x0;
    if (!unknowns) {
      s.relaxation = "none (fixed model: Theorem 2.1)";
      judge(s, certify_fixed_model(mq, eq_, co, solver_), "S_I");
      return;
    }
    IdentifyOptions io;
    io.unknowns = this->unknowns();
    io.solver = o_.solver;
    if (o_.iterate) {
      io.objective.kind = BoundObjective::Kind::kMinDmax;
      io.objective.delta = o_.delta;
      io.iterate = true;
      io.max_iterations = o_.max_iterations;
      io.rel_tol = o_.rel_tol;
    } else {
      io.objective.kind = BoundObjective::Kind::kFeasibility;
      io.objective.delta = o_.delta;
      io.objective.dmax = o_.dmax;
    }
    const IdentifyResult res = identify(md, ed_, io, solver_);
    s.solves = static_cast<int>(res.iterates.size());
    s.relaxation = res.relaxation;
    const std::string what = s.basis.empty() ? "S_I with the identified offset" : "the identified model";
    if (res.iterates.empty() || !has_solution(res.iterates.front().status)) {  // no model at all
      if (res.status == SolveStatus::kPrimalInfeasible) {
        s.verdict = BasisVerdict::kNotDecided;
        s.detail = "the solver found the relaxation of Theorem 3.1 (" + res.relaxation +
                   ") infeasible at the given bounds: no consistent model found (a solver verdict; the relaxation is "
                   "conservative)";
      } else {
        s.verdict = BasisVerdict::kUnverified;
        s.detail = std::string("the identification solve ended with status ") + to_string(res.status) +
                   (res.message.empty() ? "" : ": " + res.message);
      }
      return;
    }
    if (o_.iterate) {
      double best = -1;
      for (const IterateRecord& it : res.iterates)
        if (has_solution(it.status) && (best < 0 || it.dmax2 < best * best)) best = std::sqrt(std::max(0.0, it.dmax2));
      s.dmax_relaxation = best;
    }
    const FixedParameters fp = fix_parameters(mq, res.layout, res.p, co.digits, eq_.record_x0);
    centre = fp.value;
    s.p = fp.value;
    s.layout = res.layout;
    judge(s, certify_fixed_model(fp.model, with_fixed_initial_states(eq_, fp), co, solver_), what);
  }

  const LpvModel<Rational>& mq_;
  const LpvModel<double>& md_;
  const Experiment<Rational>& eq_;
  const Experiment<double>& ed_;
  const BasisSelectionOptions& o_;
  SdpSolver& solver_;
  std::vector<BasisStep> steps_;
  std::map<BasisKey, int> seen_;
};

}  // namespace

std::vector<Monomial> basis_growth_order(int n_rho, int max_degree) {
  if (n_rho < 0 || max_degree < 0) throw std::invalid_argument("basis_growth_order: negative size or degree");
  std::vector<std::vector<int>> all;
  std::vector<int> cur;
  enumerate(n_rho, max_degree, cur, all);
  std::stable_sort(all.begin(), all.end(), [](const std::vector<int>& a, const std::vector<int>& b) {
    const int sa = stage(a), sb = stage(b);
    if (sa != sb) return sa < sb;
    const int da = degree_of(a), db = degree_of(b);
    if (da != db) return da < db;
    if (sa == 3 && pure_power(a) != pure_power(b)) return pure_power(a);
    return a > b;  // descending lexicographic: rho1 before rho2, rho1*rho2 before rho1*rho3
  });
  std::vector<Monomial> out;
  for (auto& e : all) out.push_back(Monomial{e});
  return out;
}

template <typename T>
LpvModel<T> with_correction_basis(const LpvModel<T>& model, const std::vector<Monomial>& basis) {
  LpvModel<T> m = model;
  Correction<T> c;
  const Correction<T>& old = model.correction;
  for (const Monomial& f : basis) {
    Mat<T> A = Mat<T>::Zero(model.nx, model.nx), B = Mat<T>::Zero(model.nx, model.nu);
    for (size_t i = 0; i < old.basis.size(); ++i)
      if (old.basis[i] == f) {
        if (i < old.A.size() && old.A[i].size() != 0) A = old.A[i];
        if (i < old.B.size() && old.B[i].size() != 0) B = old.B[i];
      }
    c.basis.push_back(f);
    c.A.push_back(A);
    c.B.push_back(B);
  }
  m.correction = c;
  return m;
}

template LpvModel<double> with_correction_basis(const LpvModel<double>&, const std::vector<Monomial>&);
template LpvModel<Rational> with_correction_basis(const LpvModel<Rational>&, const std::vector<Monomial>&);

std::string basis_text(const std::vector<Monomial>& basis, const std::vector<std::string>& names) {
  if (basis.empty()) return "(none)";
  std::string out;
  for (const Monomial& m : basis) out += (out.empty() ? "" : ", ") + m.text(names);
  return out;
}

const char* to_string(BasisVerdict v) {
  switch (v) {
    case BasisVerdict::kConsistent: return "consistent";
    case BasisVerdict::kCannotExplain: return "cannot_explain";
    case BasisVerdict::kBoxInvalidated: return "box_invalidated";
    case BasisVerdict::kNotDecided: return "not_decided";
    case BasisVerdict::kUnverified: return "unverified";
  }
  return "unverified";
}

BasisSelectionResult select_basis(const Problem& problem, const BasisSelectionOptions& options, SdpSolver& solver) {
  const double delta = options.delta.approx, dmax = options.dmax.approx;
  if (!(delta >= 0) || !(dmax >= 0) || !std::isfinite(delta) || !std::isfinite(dmax))
    throw InputError("select-basis: delta and dmax must be finite and non-negative");
  if (options.max_degree < 0 || options.max_degree > kMaxMonomialPower)
    throw InputError("select-basis: --max-degree must be in 0.." + std::to_string(kMaxMonomialPower));
  Selector sel(problem, options, solver);
  return sel.run();
}

const char* to_string(SelectionOutcome outcome) {
  switch (outcome) {
    case SelectionOutcome::kFound: return "found";
    case SelectionOutcome::kCannotExplain: return "cannot_explain";
    case SelectionOutcome::kNotVerified: return "not_verified";
    case SelectionOutcome::kNotDecided: return "not_decided";
  }
  return "not_decided";
}

std::string monotonicity_violation(const std::vector<BasisStep>& steps) {
  for (const BasisStep& a : steps)
    for (const BasisStep& b : steps) {
      const bool counted = b.verdict == BasisVerdict::kCannotExplain || b.verdict == BasisVerdict::kBoxInvalidated ||
                           b.verdict == BasisVerdict::kNotDecided;
      if (a.verdict != BasisVerdict::kConsistent || !counted || !subset(a.basis, b.basis)) continue;
      const std::string why = b.verdict == BasisVerdict::kCannotExplain
                                  ? "certified unable to explain the data (two exact certificates contradict: a bug)"
                                  : std::string(b.verdict == BasisVerdict::kBoxInvalidated
                                                    ? "invalidated on a box only (the consistent theta lies outside it)"
                                                    : "not decided (solver verdict)");
      return "step " + std::to_string(a.index) + " {" + a.basis_text + "} is consistent but its superset step " +
             std::to_string(b.index) + " {" + b.basis_text + "} is " + why;
    }
  return "";
}

}  // namespace lpvid
