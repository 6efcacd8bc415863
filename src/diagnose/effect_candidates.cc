#include "diagnose/effect_candidates.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "core/integer_power.h"
#include "core/rms.h"
#include "diagnose/cascade_form.h"
#include "diagnose/store_cascade.h"
#include "fit/wiener_starts.h"
#include "model/simulate.h"
#include "model/state_scheduling.h"

namespace lpvid {

namespace {

/// q-quantile (0 ≤ q ≤ 1) of all entries of m, by nearest rank.
double quantile(const Mat<double>& m, double q) {
  std::vector<double> v(m.data(), m.data() + m.size());
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const auto i = static_cast<size_t>(std::clamp(q, 0.0, 1.0) * static_cast<double>(v.size() - 1) + 0.5);
  return v[std::min(i, v.size() - 1)];
}

void pad(Monomial& f) { f.powers.push_back(0); }

void pad(ParamMatrix<double>& pm) {
  for (auto& t : pm.terms) pad(t.basis);
}

bool has_term(const ParamMatrix<double>& pm, const Monomial& f) {
  return std::any_of(pm.terms.begin(), pm.terms.end(), [&](const auto& t) { return t.basis == f; });
}

/// All monomials of n variables with total degree 1..max_degree.
/// Every monomial of degree 1..max_degree in n variables; a variable marked
/// in `linear_only` appears with power at most 1, and at most one of them
/// per monomial (a state-function column √|x − c|, max(x − c, 0) acts through
/// the state offset; its products with each other are a combinatorial
/// explosion of candidates without a physical reading).
std::vector<Monomial> monomials(size_t n, int max_degree, const std::vector<bool>& linear_only = {}) {
  std::vector<Monomial> out;
  std::vector<int> p(n, 0);
  // enumerate exponent vectors in a fixed order (odometer over 0..max_degree)
  while (true) {
    int deg = 0, functions = 0;
    for (int e : p) deg += e;
    for (size_t k = 0; k < linear_only.size() && k < n; ++k)
      if (linear_only[k] && p[k] > 0) functions += p[k];
    if (deg >= 1 && deg <= max_degree && functions <= 1) out.push_back(Monomial{p});
    size_t k = 0;
    while (k < n && ++p[k] > max_degree) p[k++] = 0;
    if (k == n) break;
  }
  std::stable_sort(out.begin(), out.end(), [](const Monomial& a, const Monomial& b) { return a.degree() < b.degree(); });
  return out;
}

/// A scheduling name for an input column ("u1" → "u1"; other characters → '_').
std::string scheduling_name(const std::string& column, const std::vector<std::string>& taken) {
  std::string s;
  for (char c : column) s += (std::isalnum(static_cast<unsigned char>(c)) || c == '_') ? c : '_';
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) s = "rho_" + s;
  std::string name = s;
  for (int i = 2; std::find(taken.begin(), taken.end(), name) != taken.end(); ++i) name = s + "_" + std::to_string(i);
  return name;
}

EffectCandidate make(const std::string& kind, const std::string& label, int extra,
                     std::vector<LpvModel<double>> starts) {
  EffectCandidate c;
  c.kind = kind;
  c.label = label;
  c.effect_parameters = extra;
  c.slots = refit_slots(starts.front());
  c.starts = std::move(starts);
  return c;
}

/// 4 significant digits, for labels.
std::string short_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

/// What every family's generator reads: the current model made explicit,
/// the estimation record, the options, the model's simulation on the record
/// and v, what a static output map would act on.
struct CandidateContext {
  const LpvModel<double>& base;  ///< explicit_model(current)
  const Experiment<double>& est;
  const CandidateOptions& o;
  const Simulation<double>& sim;  ///< base simulated on est
  const Mat<double>& v;           ///< sim.yhat + sim.offset
};

/// The measured inputs among f's variables, for a label: " (scheduled on the
/// measured input u1)", or "" when f has none.
std::string input_note(const LpvModel<double>& base, const Monomial& f) {
  std::string note;
  for (size_t k = 0; k < f.powers.size(); ++k)
    if (f.powers[k] > 0 && std::find(base.columns.u.begin(), base.columns.u.end(), base.columns.rho[k]) !=
                               base.columns.u.end())
      note += (note.empty() ? " (scheduled on the measured input " : ", ") +
              (base.scheduling[k] == base.columns.rho[k] ? base.scheduling[k]
                                                         : base.scheduling[k] + " = " + base.columns.rho[k]);
  if (!note.empty()) note += ")";
  return note;
}

/// basis_term: new f(ρ) in S_C (eq. 10), entering C and D; and the same f(ρ)
/// entering the state through B
void basis_term_candidates(const CandidateContext& cx, std::vector<EffectCandidate>& out) {
  const LpvModel<double>& base = cx.base;
  std::vector<bool> function_column(base.scheduling.size(), false);
  for (size_t k = 0; k < base.scheduling.size(); ++k)
    function_column[k] = parse_state_column(base.columns.rho[k]).function != StateFunction::kState;
  for (const Monomial& f : monomials(base.scheduling.size(), cx.o.max_degree, function_column)) {
    if (has_term(base.C, f) || has_term(base.D, f)) continue;
    const std::string note = input_note(base, f);
    LpvModel<double> s = base;
    s.C.add(f, Mat<double>::Zero(base.ny, base.nx));
    s.D.add(f, Mat<double>::Zero(base.ny, base.nu));
    out.push_back(make("basis_term", "basis_term " + f.text(base.scheduling) + " in C, D" + note,
                       base.ny * (base.nx + base.nu), {s}));
    // the same f(ρ) entering the state through B: x_{k+1} = A x + (B + f(ρ) B_f) u
    if (!has_term(base.B, f) && base.nx > 0) {
      LpvModel<double> sb = base;
      sb.B.add(f, Mat<double>::Zero(base.nx, base.nu));
      EffectCandidate cb = make("basis_term", "basis_term " + f.text(base.scheduling) + " in B" + note,
                                base.nx * base.nu, {sb});
      const std::vector<ParameterSlot> extra = input_term_slots(sb, f);
      cb.slots.insert(cb.slots.end(), extra.begin(), extra.end());
      out.push_back(std::move(cb));
    }
  }
}

/// basis_term scheduled on the model's own state x_1 (model/state_scheduling.h):
/// A(ρ) = A_0 + ρ^j A_j with ρ = x_1, i.e. a polynomial state feedback
/// (cubic stiffness, a level-dependent outflow) as a quasi-LPV term
/// (several degrees over the rounds: once x_1 is a scheduling variable, the
/// degrees A does not have yet are offered on it, the state not rescaled again)
void state_scheduled_basis_term_candidates(const CandidateContext& cx, std::vector<EffectCandidate>& out) {
  const LpvModel<double>& base = cx.base;
  if (base.nx <= 0 || cx.o.state_degree <= 0) return;
  const auto at = std::find(base.columns.rho.begin(), base.columns.rho.end(), "@x1");
  LpvModel<double> sched;
  if (at == base.columns.rho.end()) {
    // x_1 rescaled (x → x/s, s a power of two ≥ max |x_1|): ρ = x_1 in [-1, 1],
    // so ρ^j is well scaled and a finite-difference step in A_j stays small
    double peak = cx.sim.x.col(0).cwiseAbs().maxCoeff();
    // not with state columns already there (their values would change with the scale)
    const bool own_columns = !state_scheduled(base.columns.rho, base.nx).empty();
    const double s_pow2 =
        std::isfinite(peak) && peak > 0 && !own_columns ? std::exp2(std::ceil(std::log2(peak))) : 1.0;
    sched = add_scheduling_variable(scale_state(base, s_pow2), scheduling_name("xhat1", base.scheduling), "@x1");
  } else {
    sched = base;
  }
  const size_t j = at == base.columns.rho.end() ? sched.scheduling.size() - 1
                                                : static_cast<size_t>(at - base.columns.rho.begin());
  for (int d = 1; d <= cx.o.state_degree; ++d) {
    Monomial f = constant_monomial(sched.scheduling.size());
    f.powers[j] = d;
    if (has_term(sched.A, f)) continue;
    LpvModel<double> s = sched;
    s.A.add(f, Mat<double>::Zero(base.nx, base.nx));
    EffectCandidate c = make("basis_term",
                             "basis_term " + f.text(sched.scheduling) + " in A (scheduled on the model's own state x1)",
                             base.nx, {s});
    c.slots = with_dynamics_slots(c.slots, s);  // the new A term moves whatever the ranking's options
    out.push_back(std::move(c));
  }
}

/// state_nonlinearity: x_{k+1} = A x + B u' + e·f(x_i − c),
/// f = √|·|, |·| or max(·, 0), as a scheduling column "@f(x<i>-c)" and a state
/// offset term ρ_new·e (model.state_offset). e starts at 0 (the start is the
/// current model), c below the simulated range of x_i for √ and |·| (so the
/// argument keeps its sign along the trajectory), at its 0.9 quantile for the
/// hinge (an overflow level). The joint re-fit moves e, c, A and B.
void state_nonlinearity_candidates(const CandidateContext& cx, std::vector<EffectCandidate>& out) {
  const LpvModel<double>& base = cx.base;
  struct Kind {
    StateFunction f;
    const char* name;
    const char* before;  ///< the words around x_i
    const char* after;
  };
  const Kind kinds[] = {
      {StateFunction::kSqrt, "sqrt", "e*sqrt|", " - c| (a square-root law in the distance of the state from c)"},
      {StateFunction::kAbs, "abs", "e*|", " - c| (a V: a feedback that grows with the distance of the state from c on either side)"},
      {StateFunction::kHinge, "hinge", "e*max(", " - c, 0) (a one-sided feedback, active only above c: with e = -1 the state is clipped at c)"},
  };
  std::vector<StateColumn> existing;
  for (const std::string& col : base.columns.rho) existing.push_back(parse_state_column(col));
  for (int i = 0; i < base.nx; ++i) {
    const Mat<double> xi = cx.sim.x.col(i);
    if (xi.size() == 0 || !xi.allFinite()) continue;
    const double lo = xi.minCoeff(), hi = xi.maxCoeff();
    const double margin = std::max(0.05 * (hi - lo), 1e-6 * std::max(1.0, std::abs(lo)));
    for (const Kind& k : kinds) {
      const bool has = std::any_of(existing.begin(), existing.end(),
                                   [&](const StateColumn& c) { return c.state == i && c.function == k.f; });
      if (has) continue;
      const double c = k.f == StateFunction::kHinge ? quantile(xi, 0.9) : lo - margin;
      const std::string x = "x" + std::to_string(i + 1);
      LpvModel<double> s = add_scheduling_variable(base, scheduling_name(std::string(k.name) + "_" + x, base.scheduling),
                                                   state_column_text(k.f, i, c));
      const int j = s.n_rho() - 1;
      Monomial h = constant_monomial(static_cast<size_t>(s.n_rho()));
      h.powers[static_cast<size_t>(j)] = 1;
      s.state_offset.basis.push_back(h);
      s.state_offset.values.push_back(Vec<double>::Zero(base.nx));
      const std::string words = k.before + x + k.after;
      EffectCandidate cand = make("state_nonlinearity",
                                  "state_nonlinearity " + std::string(k.name) + "(" + x + ") in the state equation: " +
                                      words + ", c fitted (start " + short_text(c) + ")",
                                  base.nx + 1, {s});
      cand.slots.push_back(state_shift_slot(s, j));
      cand.slots = with_dynamics_slots(cand.slots, s);  // E's values, A and B move
      out.push_back(std::move(cand));
    }
  }
}

/// The √ outflow and the overflow hinge on the levels of the cascade
/// realisation (diagnose/cascade_form.h): one candidate per store and kind,
/// started from both pole orderings (same structure, so the same slots).
void cascade_state_nonlinearity_candidates(const CandidateContext& cx, std::vector<EffectCandidate>& out) {
  const LpvModel<double>& base = cx.base;
  const std::vector<LpvModel<double>> cascades = cascade_realisations(base);
  if (cascades.empty()) return;
  const StateFunction kinds[] = {StateFunction::kSqrt, StateFunction::kHinge};
  for (int i = 0; i < 2; ++i)
    for (StateFunction f : kinds) {
      std::vector<LpvModel<double>> starts;
      for (const LpvModel<double>& c : cascades) {
        const Mat<double> zi = simulate(c, cx.est).x.col(i);
        if (zi.size() == 0 || !zi.allFinite()) continue;
        const double lo = zi.minCoeff(), hi = zi.maxCoeff();
        const double shift = f == StateFunction::kHinge ? quantile(zi, 0.9)
                                                        : lo - std::max(0.05 * (hi - lo), 1e-6 * std::max(1.0, std::abs(lo)));
        const std::string z = "x" + std::to_string(i + 1);
        LpvModel<double> s = add_scheduling_variable(
            c, scheduling_name(std::string(f == StateFunction::kSqrt ? "sqrt_" : "hinge_") + "level" + std::to_string(i + 1), c.scheduling),
            state_column_text(f, i, shift));
        Monomial h = constant_monomial(static_cast<size_t>(s.n_rho()));
        h.powers[static_cast<size_t>(s.n_rho() - 1)] = 1;
        s.state_offset.basis.push_back(h);
        s.state_offset.values.push_back(Vec<double>::Zero(base.nx));
        starts.push_back(std::move(s));
      }
      if (starts.empty()) continue;
      const std::string level = i == 0 ? "the upstream store x1 (feeds x2)" : "the downstream store x2 (y = x2)";
      EffectCandidate cand = make(
          "state_nonlinearity",
          std::string("state_nonlinearity ") + (f == StateFunction::kSqrt ? "sqrt" : "hinge") + " of " + level +
              ", states in cascade form: " +
              (f == StateFunction::kSqrt ? "e*sqrt|x - c| (a square-root outflow law)" : "e*max(x - c, 0) (a one-sided feedback above c)"),
          base.nx + 1, starts);
      cand.slots.push_back(state_shift_slot(starts.front(), starts.front().n_rho() - 1));
      cand.slots = with_dynamics_slots(cand.slots, starts.front());
      out.push_back(std::move(cand));
    }
}

/// The store cascade (diagnose/store_cascade.h) in place of an LTI SISO
/// linear part: every start of the grid, with A, B, C, D, E, the four levels,
/// φ and x0 free.
void store_cascade_candidate(const CandidateContext& cx, std::vector<EffectCandidate>& out) {
  const LpvModel<double>& base = cx.base;
  std::vector<LpvModel<double>> starts = store_cascade_starts(base, cx.est);
  if (starts.empty()) return;
  const int first = base.n_rho();
  const int added = 4 * 2 + 4;  // E's four 2-vectors and the four levels
  const std::string count = std::to_string(starts.size());
  EffectCandidate cand = make("state_nonlinearity",
                              "store cascade: two stores x1 -> x2 (A = I), outflow e*sqrt(max(x_i - c_i, 0)) and overflow "
                              "e*max(x_i - o_i, 0) from each, levels fitted; replaces the linear part (" +
                                  count + " starts)",
                              added, std::move(starts));
  for (int j = first; j < first + 4; ++j) cand.slots.push_back(state_shift_slot(cand.starts.front(), j));
  cand.slots = with_dynamics_slots(cand.slots, cand.starts.front());
  cand.starts_for = [base](const Experiment<double>& rows) { return store_cascade_starts(base, rows); };
  out.push_back(std::move(cand));
}

/// output_offset: Φ = φ_1 (basis 1) when the model has no constant offset,
/// and Φ(ρ_i) (eq. 20) for each measured scheduling variable ρ_i
void output_offset_candidates(const CandidateContext& cx, std::vector<EffectCandidate>& out) {
  const LpvModel<double>& base = cx.base;
  const Monomial one = constant_monomial(base.scheduling.size());
  if (std::find(base.offset.basis.begin(), base.offset.basis.end(), one) == base.offset.basis.end()) {
    LpvModel<double> s = base;
    s.offset.basis.push_back(one);
    s.offset.values.push_back(Vec<double>::Zero(base.ny));
    out.push_back(make("output_offset", "output_offset phi (constant)", base.ny, {s}));
  }
  // Φ(ρ) = Σ_j h_j(ρ) φ_j (eq. 20, docs/design.md §5.4) over {1, ρ_i, …, ρ_i^max_degree} for
  // each measured scheduling variable ρ_i (not an input, not the model's state)
  for (size_t i = 0; i < base.scheduling.size(); ++i) {
    const std::string& col = base.columns.rho[i];
    if (state_scheduling_index(col) >= 0 ||
        std::find(base.columns.u.begin(), base.columns.u.end(), col) != base.columns.u.end())
      continue;
    LpvModel<double> s = base;
    std::string basis_text;
    int added = 0;
    for (int d = 0; d <= cx.o.max_degree; ++d) {
      Monomial h = constant_monomial(base.scheduling.size());
      h.powers[i] = d;
      basis_text += (d ? ", " : "") + h.text(base.scheduling);
      if (std::find(s.offset.basis.begin(), s.offset.basis.end(), h) != s.offset.basis.end()) continue;
      s.offset.basis.push_back(h);
      s.offset.values.push_back(Vec<double>::Zero(base.ny));
      ++added;
    }
    if (added > 1)
      out.push_back(make("output_offset", "output_offset phi(" + base.scheduling[i] + ") over {" + basis_text + "}",
                         base.ny * added, {s}));
  }
}

/// A model's static input map or its static output map (model/static_blocks.h).
using StaticSide = StaticMap<double> StaticBlocks<double>::*;
constexpr StaticSide kInputMap = &StaticBlocks<double>::input;
constexpr StaticSide kOutputMap = &StaticBlocks<double>::output;

/// The base model with its input or output map set to g.
LpvModel<double> with_map(const LpvModel<double>& base, StaticSide which, StaticKind kind, double lo, double hi,
                          std::vector<double> coef = {}) {
  LpvModel<double> s = base;
  StaticMap<double>& g = s.statics.*which;
  g.kind = kind;
  g.lower = lo;
  g.upper = hi;
  g.coefficients = std::move(coef);
  return s;
}

/// The three starts of a saturation of `signal` (u for the input map, v for
/// the output map): its 5 % and 95 % quantiles, and each side left open.
std::vector<LpvModel<double>> saturation_starts(const LpvModel<double>& base, StaticSide which,
                                                const Mat<double>& signal) {
  const double lo = quantile(signal, 0), hi = quantile(signal, 1), r = std::max(hi - lo, 1e-12);
  return {with_map(base, which, StaticKind::kSaturation, quantile(signal, 0.05), quantile(signal, 0.95)),
          with_map(base, which, StaticKind::kSaturation, lo - r, quantile(signal, 0.85)),
          with_map(base, which, StaticKind::kSaturation, quantile(signal, 0.15), hi + r)};
}

/// The coefficients c_0 … c_degree of the identity polynomial (c_1 = 1).
std::vector<double> identity_polynomial(int degree) {
  std::vector<double> c(static_cast<size_t>(degree + 1), 0.0);
  c[1] = 1;
  return c;
}

/// The static input maps (model/static_blocks.h) when the model has none:
/// input_saturation, dead_zone and input_polynomial u' = c0 + u + c2 u² + c3 u³
void input_map_candidates(const CandidateContext& cx, std::vector<EffectCandidate>& out) {
  const LpvModel<double>& base = cx.base;
  if (!base.statics.input.is_identity()) return;
  const Mat<double>& u = cx.est.u;
  const double ur = std::max(quantile(u, 1) - quantile(u, 0), 1e-12);
  out.push_back(make("input_saturation", "input_saturation", 2, saturation_starts(base, kInputMap, u)));
  const double mid = quantile(u, 0.5);
  out.push_back(make("dead_zone", "dead_zone (input)", 2,
                     {with_map(base, kInputMap, StaticKind::kDeadZone, mid - 0.1 * ur, mid + 0.1 * ur),
                      with_map(base, kInputMap, StaticKind::kDeadZone, mid - 0.25 * ur, mid + 0.25 * ur),
                      with_map(base, kInputMap, StaticKind::kDeadZone, -0.1 * ur, 0.1 * ur)}));
  const int p = cx.o.polynomial_degree;
  out.push_back(make("input_polynomial", "input_polynomial degree " + std::to_string(p), p,
                     {with_map(base, kInputMap, StaticKind::kPolynomial, 0, 0, identity_polynomial(p))}));
}

/// The quadratic-kernel direction (fit/wiener_starts.h), used only
/// where that regression already fits y better than the current model
/// does (an even map hiding the linear part): elsewhere the start repeats
/// what the model has, at the cost of two more joint fits per round.
Vec<double> quadratic_kernel_direction(const CandidateContext& cx) {
  Vec<double> w;
  if (cx.base.ny == 1) {
    const QuadraticKernel qk = quadratic_kernel_signal(cx.est);
    const double model_rms = rms(cx.est.y - cx.v);
    if (qk.w.size() > 0 && qk.rms < model_rms) w = qk.w;
  }
  return w;
}

/// abs_value: |·| at the sensor (a static output map); the fit also needs a
/// constant offset inside the map
void abs_value_candidate(const CandidateContext& cx, const Vec<double>& w, std::vector<EffectCandidate>& out) {
  const LpvModel<double>& base = cx.base;
  const Experiment<double>& est = cx.est;
  LpvModel<double> s = with_map(base, kOutputMap, StaticKind::kAbs, 0, 0);
  const Monomial one = constant_monomial(base.scheduling.size());
  int extra = 0;
  if (std::find(s.offset.basis.begin(), s.offset.basis.end(), one) == s.offset.basis.end()) {
    s.offset.basis.push_back(one);
    s.offset.values.push_back(Vec<double>::Zero(base.ny));
    extra = base.ny;
  }
  std::vector<LpvModel<double>> starts = {s};
  // the linear part re-fitted to a sign-recovered y (fit/wiener_starts.h)
  if (base.ny == 1) starts.push_back(fitted_to_target(s, est, sign_recovered_target(est.y.col(0))));
  // and to α·w, w the dominant direction of the best quadratic
  // approximation (an even map's linear approximation is ~0), α from y ≈ c + α|w|
  if (w.size() > 0) {
    Mat<double> X(w.size(), 2);
    X.col(0).setOnes();
    X.col(1) = w.cwiseAbs();
    const Vec<double> g = X.colPivHouseholderQr().solve(Vec<double>(est.y.col(0)));
    if (g.allFinite()) starts.push_back(fitted_to_target(s, est, g(1) * w));
  }
  out.push_back(make("abs_value", "abs_value (sensor)", extra, std::move(starts)));
}

/// A second start of the output polynomial c, in the basin of the data:
/// (c_0, c_2, …) by linear least squares of y − v on (1, v², v³, …) with the
/// current v (c_1 = 1 is fixed); and the linear part re-fitted to the map's
/// inverse of y (fit/wiener_starts.h).
void output_polynomial_regression_starts(const CandidateContext& cx, const std::vector<double>& c,
                                         std::vector<LpvModel<double>>& starts) {
  const Experiment<double>& est = cx.est;
  const Mat<double>& v = cx.v;
  if (!(cx.base.ny == 1 && est.y.rows() == v.rows() && v.allFinite())) return;
  const Eigen::Index n = v.rows(), p = cx.o.polynomial_degree;
  Mat<double> X(n, p);
  for (Eigen::Index k = 0; k < n; ++k)
    for (Eigen::Index i = 0, e = 0; e <= p; ++e)
      if (e != 1) X(k, i++) = integer_power(v(k, 0), static_cast<int>(e));
  const Vec<double> beta = X.colPivHouseholderQr().solve(Vec<double>(est.y.col(0) - v.col(0)));
  if (!beta.allFinite()) return;
  std::vector<double> cl = c;
  for (Eigen::Index i = 0, e = 0; e <= p; ++e)
    if (e != 1) cl[static_cast<size_t>(e)] = beta(i++);
  starts.push_back(with_map(cx.base, kOutputMap, StaticKind::kPolynomial, 0, 0, cl));
  starts.push_back(fitted_to_target(starts.back(), est, polynomial_inverse_target(cl, est.y.col(0), v.col(0))));
}

/// A start of the output polynomial c from the quadratic kernel:
/// y ≈ Σ_e γ_e w^e, v* = γ_1 w, c_e = γ_e/γ_1^e.
void output_polynomial_kernel_start(const CandidateContext& cx, const Vec<double>& w, const std::vector<double>& c,
                                    std::vector<LpvModel<double>>& starts) {
  if (w.size() == 0) return;
  const Eigen::Index p = cx.o.polynomial_degree;
  Mat<double> X(w.size(), p + 1);
  for (Eigen::Index e = 0; e <= p; ++e) X.col(e) = w.unaryExpr([e](double x) { return integer_power(x, static_cast<int>(e)); });
  const Vec<double> g = X.colPivHouseholderQr().solve(Vec<double>(cx.est.y.col(0)));
  if (!(g.allFinite() && std::abs(g(1)) > 0)) return;
  std::vector<double> cl = c;
  cl[0] = g(0);
  for (Eigen::Index e = 2; e <= p; ++e) cl[static_cast<size_t>(e)] = g(e) / integer_power(g(1), static_cast<int>(e));
  const LpvModel<double> s = with_map(cx.base, kOutputMap, StaticKind::kPolynomial, 0, 0, cl);
  starts.push_back(fitted_to_target(s, cx.est, g(1) * w));
}

/// output_polynomial: y = c0 + v + c2 v² + c3 v³ (v = ŷ + Φ), from the
/// identity, from the data's regression and from the quadratic kernel
void output_polynomial_candidate(const CandidateContext& cx, const Vec<double>& w, std::vector<EffectCandidate>& out) {
  const int p = cx.o.polynomial_degree;
  const std::vector<double> c = identity_polynomial(p);
  std::vector<LpvModel<double>> starts = {with_map(cx.base, kOutputMap, StaticKind::kPolynomial, 0, 0, c)};
  output_polynomial_regression_starts(cx, c, starts);
  output_polynomial_kernel_start(cx, w, c, starts);
  out.push_back(make("output_polynomial", "output_polynomial degree " + std::to_string(p), p, std::move(starts)));
}

/// output_piecewise_linear: a piecewise-linear output map (√, one-sided
/// clips, monotone curves): knots at the quantiles of v, values by linear
/// least squares of y on the knots' hat functions (the map is linear in its
/// values), then re-fitted
void output_piecewise_linear_candidate(const CandidateContext& cx, std::vector<EffectCandidate>& out) {
  const Mat<double>& v = cx.v;
  const int n_knots = cx.o.pwl_knots;
  if (!(cx.base.ny == 1 && n_knots >= 2 && cx.est.y.rows() == v.rows() && v.allFinite())) return;
  const double vr = std::max(quantile(v, 1) - quantile(v, 0), 1e-12);
  std::vector<double> knots;
  for (int i = 0; i < n_knots; ++i) {
    const double x = quantile(v, static_cast<double>(i) / (n_knots - 1));
    if (knots.empty() || x > knots.back() + 1e-9 * vr) knots.push_back(x);
  }
  if (knots.size() < 2) return;
  LpvModel<double> s = cx.base;
  StaticMap<double>& g = s.statics.output;
  g.kind = StaticKind::kPiecewiseLinear;
  g.knots = knots;
  g.coefficients = knots;  // identity
  std::vector<LpvModel<double>> pstarts = {s};
  Mat<double> H = Mat<double>::Zero(v.rows(), static_cast<Eigen::Index>(knots.size()));
  for (size_t i = 0; i < knots.size(); ++i) {
    StaticMap<double> hat = g;
    std::fill(hat.coefficients.begin(), hat.coefficients.end(), 0.0);
    hat.coefficients[i] = 1.0;
    for (Eigen::Index k = 0; k < v.rows(); ++k) H(k, static_cast<Eigen::Index>(i)) = hat(v(k, 0));
  }
  const Vec<double> values = H.colPivHouseholderQr().solve(Vec<double>(cx.est.y.col(0)));
  if (values.allFinite()) {
    g.coefficients.assign(values.data(), values.data() + values.size());
    pstarts.push_back(s);
  }
  out.push_back(make("output_piecewise_linear", "output_piecewise_linear (" + std::to_string(knots.size()) + " knots)",
                     static_cast<int>(knots.size()), std::move(pstarts)));
}

/// The static output maps (model/static_blocks.h) when the model has none:
/// output_saturation, abs_value, output_polynomial, output_piecewise_linear
void output_map_candidates(const CandidateContext& cx, std::vector<EffectCandidate>& out) {
  if (!cx.base.statics.output.is_identity()) return;
  const Vec<double> w = quadratic_kernel_direction(cx);
  out.push_back(make("output_saturation", "output_saturation", 2, saturation_starts(cx.base, kOutputMap, cx.v)));
  abs_value_candidate(cx, w, out);
  output_polynomial_candidate(cx, w, out);
  output_piecewise_linear_candidate(cx, out);
}

/// input_delay: u'_k = u_{k−d}, one candidate started at every d = 1 … max_delay
void input_delay_candidate(const CandidateContext& cx, std::vector<EffectCandidate>& out) {
  if (cx.base.statics.input_delay != 0 || cx.o.max_delay <= 0) return;
  std::vector<LpvModel<double>> starts;
  for (int d = 1; d <= cx.o.max_delay; ++d) {
    LpvModel<double> s = cx.base;
    s.statics.input_delay = d;
    starts.push_back(s);
  }
  out.push_back(make("input_delay", "input_delay", 1, std::move(starts)));
}

}  // namespace

LpvModel<double> with_input_scheduling(const LpvModel<double>& m) {
  LpvModel<double> out = m;
  for (const std::string& col : m.columns.u)
    if (std::find(out.columns.rho.begin(), out.columns.rho.end(), col) == out.columns.rho.end())
      out = add_scheduling_variable(out, scheduling_name(col, out.scheduling), col);
  return out;
}

Experiment<double> with_input_scheduling(const Experiment<double>& e, const LpvModel<double>& declared,
                                         const LpvModel<double>& augmented) {
  if (e.n_rho() != declared.n_rho())
    throw std::invalid_argument("with_input_scheduling: the experiment does not match the declared model");
  Experiment<double> out = e;
  out.rho.resize(e.n(), augmented.n_rho());
  if (e.n_rho() > 0) out.rho.leftCols(e.n_rho()) = e.rho;
  for (int k = declared.n_rho(); k < augmented.n_rho(); ++k) {
    const auto& cols = declared.columns.u;
    const auto it = std::find(cols.begin(), cols.end(), augmented.columns.rho[static_cast<size_t>(k)]);
    if (it == cols.end()) throw std::invalid_argument("with_input_scheduling: scheduling column is not an input");
    out.rho.col(k) = e.u.col(it - cols.begin());
  }
  return out;
}

LpvModel<double> scale_state(const LpvModel<double>& m, double s) {
  LpvModel<double> out = m;
  for (auto& t : out.B.terms) t.value /= s;
  for (auto& t : out.C.terms) t.value *= s;
  for (auto& t : out.uncertainty.C1.terms) t.value *= s;
  for (auto& b : out.correction.B) b /= s;
  for (auto& e : out.state_offset.values) e /= s;
  out.x0 /= s;
  for (auto& x : out.later_x0) x /= s;
  return out;
}

LpvModel<double> add_scheduling_variable(const LpvModel<double>& m, const std::string& name,
                                         const std::string& column) {
  LpvModel<double> out = m;
  out.scheduling.push_back(name);
  out.columns.rho.push_back(column);
  for (ParamMatrix<double>* pm : {&out.A, &out.B, &out.C, &out.D, &out.uncertainty.C1, &out.uncertainty.D1}) pad(*pm);
  for (Monomial& f : out.correction.basis) pad(f);
  for (Monomial& f : out.offset.basis) pad(f);
  for (Monomial& f : out.state_offset.basis) pad(f);
  return out;
}

std::vector<EffectCandidate> candidate_effects(const LpvModel<double>& current, const Experiment<double>& est,
                                               const CandidateOptions& o) {
  const LpvModel<double> base = explicit_model(current);
  const Simulation<double> sim = simulate(base, est);
  const Mat<double> v = sim.yhat + sim.offset;  // what a static output map would act on
  const CandidateContext cx{base, est, o, sim, v};
  // the families in a fixed order: the ranking depends on it
  std::vector<EffectCandidate> out;
  basis_term_candidates(cx, out);
  state_scheduled_basis_term_candidates(cx, out);
  if (o.state_functions) {
    state_nonlinearity_candidates(cx, out);
    cascade_state_nonlinearity_candidates(cx, out);
    store_cascade_candidate(cx, out);
  }
  output_offset_candidates(cx, out);
  input_map_candidates(cx, out);
  output_map_candidates(cx, out);
  input_delay_candidate(cx, out);
  return out;
}

}  // namespace lpvid
