#include "examples/effect_cases.h"

#include <cmath>

#include "core/input_error.h"
#include "core/number_text.h"
#include "examples/decimal_rounding.h"
#include "examples/model_literals.h"
#include "examples/random_stream.h"
#include "model/simulate.h"

namespace lpvid {

namespace {

constexpr int kDigits = 8;
using literals::kOne;
using literals::kRho;
using literals::kRho2;

using literals::dec;

Mat<Rational> row2(const char* a, const char* b) { return literals::mat(1, 2, {a, b}); }

/// x_{k+1} = A(ρ)x + B u, y = C(ρ)x + D u with
/// A(ρ) = [0 1; −0.3 0.9] + ρ[0 0; 0 0.15], B = [0; 1], C(ρ) = [1 0.5] + ρ[0.3 0], D = 0.2:
/// frozen poles inside |z| ≤ 0.87 for |ρ| ≤ 1.
LpvModel<Rational> declared_model() {
  LpvModel<Rational> m = literals::siso_rho1_skeleton();
  m.A.add(kOne, literals::mat(2, 2, {"0", "1", "-0.3", "0.9"}));
  m.A.add(kRho, literals::mat(2, 2, {"0", "0", "0", "0.15"}));
  m.B.add(kOne, literals::mat(2, 1, {"0", "1"}));
  m.C.add(kOne, row2("1", "0.5"));
  m.C.add(kRho, row2("0.3", "0"));
  m.D.add(kOne, literals::mat(1, 1, {"0.2"}));
  return m;
}

LpvModel<Rational> with_effect(const std::string& kind) {
  LpvModel<Rational> m = declared_model();
  StaticBlocks<Rational>& s = m.statics;
  if (kind == "output_offset") {
    m.offset.basis = {kOne};
    m.offset.values = {Vec<Rational>::Constant(1, dec("0.5"))};
  } else if (kind == "input_saturation") {
    s.input.kind = StaticKind::kSaturation;
    s.input.lower = dec("-0.6");
    s.input.upper = dec("0.6");
  } else if (kind == "basis_term") {
    m.C.add(kRho2, row2("0.5", "-0.4"));
  } else if (kind == "abs_value") {
    s.output.kind = StaticKind::kAbs;
  } else if (kind == "output_polynomial") {
    s.output.kind = StaticKind::kPolynomial;
    s.output.coefficients = {dec("0"), dec("1"), dec("0.4")};
  } else if (kind == "input_delay") {
    s.input_delay = 2;
  } else if (kind == "dead_zone") {
    s.input.kind = StaticKind::kDeadZone;
    s.input.lower = dec("-0.4");
    s.input.upper = dec("0.4");
  } else if (kind == "scheduled_offset") {
    m.offset.basis = {kOne, kRho};
    m.offset.values = {Vec<Rational>::Constant(1, dec("0.3")), Vec<Rational>::Constant(1, dec("0.6"))};
  } else if (kind == "output_saturation") {
    // one-sided: a sensor that clips at 1.2 (the lower limit is never reached)
    s.output.kind = StaticKind::kSaturation;
    s.output.lower = dec("-1000");
    s.output.upper = dec("1.2");
  } else if (kind == "output_piecewise_linear") {
    // a sensor whose gain drops to 1/3 above 1.5 (a kink no polynomial has):
    // g(v) = v for v <= 1.5, 1.5 + (v - 1.5)/3 above
    s.output.kind = StaticKind::kPiecewiseLinear;
    s.output.knots = {dec("0"), dec("1.5"), dec("3")};
    s.output.coefficients = {dec("0"), dec("1.5"), dec("2")};
  } else if (kind == "input_polynomial") {
    s.input.kind = StaticKind::kPolynomial;
    s.input.coefficients = {dec("0"), dec("1"), dec("0"), dec("0.3")};
  } else if (kind == "state_feedback") {
    // scheduling on the model's own state (model/state_scheduling.h):
    // A(ρ, x1) = A(ρ) + x1²·[0 0; −0.006 0], a cubic stiffness −0.006 x1³
    // (small enough that the records stay bounded: |y| < 12 on the seeds used)
    m.scheduling.push_back("xs");
    m.columns.rho.push_back("@x1");
    for (ParamMatrix<Rational>* pm : {&m.A, &m.B, &m.C, &m.D})
      for (auto& t : pm->terms) t.basis.powers.push_back(0);
    m.A.add(Monomial{{0, 2}}, literals::mat(2, 2, {"0", "0", "-0.006", "0"}));
  } else if (kind != "none") {
    std::string known;
    for (const auto& k : effect_case_kinds()) known += (known.empty() ? "" : ", ") + k;
    throw InputError("generate effect-case: unknown effect '" + kind + "' (known: " + known + ")");
  }
  return m;
}

/// u: Gaussian levels held for 3 samples; ρ: two sinusoids with random
/// phases (independent of u); y = truth + white noise; all 8-digit decimals.
Experiment<Rational> record(const LpvModel<Rational>& truth, int n, RandomStream& rnd, double noise_std,
                            const std::string& name) {
  Experiment<Rational> e;
  e.source = name;
  e.u.resize(n, 1);
  e.rho.resize(n, 1);
  e.y.resize(n, 1);
  const double ph1 = 6.283185307179586 * rnd.uniform(), ph2 = 6.283185307179586 * rnd.uniform();
  double level = 0;
  for (int k = 0; k < n; ++k) {
    if (k % 3 == 0) level = rnd.normal();
    e.u(k, 0) = round_decimal(level, kDigits);
    e.rho(k, 0) = round_decimal(0.6 * std::sin(0.061 * k + ph1) + 0.3 * std::sin(0.173 * k + ph2), kDigits);
  }
  const LpvModel<double> m = convert_model<double>(truth);
  Experiment<double> ed;
  ed.u = nearest_double(e.u);
  ed.rho = nearest_double(e.rho);
  ed.y = Mat<double>::Zero(n, 1);
  const Simulation<double> sim = simulate(m, ed);
  for (int k = 0; k < n; ++k) e.y(k, 0) = round_decimal(sim.output(k, 0) + noise_std * rnd.normal(), kDigits);
  return e;
}

}  // namespace

const std::vector<std::string>& effect_case_kinds() {
  static const std::vector<std::string> kinds = {"output_offset",     "input_saturation", "basis_term",
                                                 "abs_value",         "output_polynomial", "input_delay",
                                                 "dead_zone",         "output_saturation", "input_polynomial",
                                                 "state_feedback",    "scheduled_offset",  "output_piecewise_linear",
                                                 "none"};
  return kinds;
}

std::string reported_effect_kind(const std::string& kind) {
  if (kind == "state_feedback") return "basis_term";
  if (kind == "scheduled_offset") return "output_offset";
  return kind;
}

EffectCase make_effect_case(const std::string& kind, int n, uint64_t seed, double noise_std) {
  if (n < 20) throw InputError("generate effect-case: --n must be at least 20");
  if (!(noise_std >= 0) || !std::isfinite(noise_std))
    throw InputError("generate effect-case: the noise standard deviation must be finite and >= 0");
  EffectCase c;
  c.declared = declared_model();
  c.truth = with_effect(kind);
  RandomStream rnd(seed);
  c.estimation = record(c.truth, n, rnd, noise_std, "estimation");
  c.validation = record(c.truth, n, rnd, noise_std, "validation");
  return c;
}

}  // namespace lpvid
