#include "examples/paper_example1.h"

#include <cmath>

#include "core/number_text.h"
#include "examples/decimal_rounding.h"
#include "examples/model_literals.h"
#include "examples/random_stream.h"
#include "model/simulate.h"

namespace lpvid {
namespace {

using literals::dec;



Mat<Rational> m2(const char* a, const char* b, const char* c, const char* d) {
  Mat<Rational> m(2, 2);
  m << dec(a), dec(b), dec(c), dec(d);
  return m;
}

LpvModel<Rational> example1_skeleton() {
  LpvModel<Rational> m;
  m.nx = m.nu = m.ny = 2;
  m.scheduling = {"rho1", "rho2"};
  m.columns = {{"u1", "u2"}, {"y1", "y2"}, {"rho1", "rho2"}};
  m.A = ParamMatrix<Rational>(2, 2);
  m.A.add(Monomial{{0, 0}}, m2("0", "1", "-0.3", "-0.6"));
  m.A.add(Monomial{{1, 0}}, m2("0", "0", "-0.01", "0"));
  m.A.add(Monomial{{0, 1}}, m2("0", "0", "0", "-0.6"));
  m.B = ParamMatrix<Rational>(2, 2);
  m.B.add(Monomial{{0, 0}}, m2("1", "0", "0", "1"));
  m.C = ParamMatrix<Rational>(2, 2);
  m.D = ParamMatrix<Rational>(2, 2);
  m.x0 = Vec<Rational>::Zero(2);
  return m;
}

}  // namespace

LpvModel<Rational> example1_true_model() {
  LpvModel<Rational> m = example1_skeleton();
  m.C.add(Monomial{{0, 2}}, m2("1", "0", "0", "0"));
  m.C.add(Monomial{{0, 0}}, m2("0", "0", "0", "1"));
  return m;
}

LpvModel<Rational> example1_initial_model() {
  LpvModel<Rational> m = example1_skeleton();
  m.C.add(Monomial{{0, 0}}, m2("1", "0", "0", "1"));
  m.uncertainty.structure = UncertaintyStructure::kMultiplicative;
  m.uncertainty.weight = dec("0.01");
  m.correction = zero_correction<Rational>({Monomial{{0, 0}}, Monomial{{1, 0}}, Monomial{{0, 1}}, Monomial{{1, 1}},
                                           Monomial{{2, 0}}, Monomial{{0, 2}}},
                                          2, 2);
  return m;
}

Experiment<Rational> example1_experiment(const Example1Options& o) {
  RandomStream rng(o.seed);
  const int n = o.n;
  Experiment<Rational> e;
  e.source = "example1";
  e.u = Mat<Rational>::Zero(n, 2);
  e.rho = Mat<Rational>::Zero(n, 2);
  for (int ch = 0; ch < 2; ++ch)
    random_pulse_train(rng, 0, n, [&](long k, bool high) { e.u(k, ch) = high ? Rational(1) : Rational(-1); });
  for (int k = 0; k < n; ++k) {
    double t = n > 1 ? static_cast<double>(k) / (n - 1) : 0.0;
    e.rho(k, 0) = round_decimal(1.0 - t, 4);
    e.rho(k, 1) = round_decimal(0.5 + 0.45 * std::sin(6.283185307179586 * k / 17.0), 4);
  }
  e.y = Mat<Rational>::Zero(n, 2);
  Simulation<Rational> sim = simulate(example1_true_model(), e);
  double sigma = std::sqrt(o.noise_variance);
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < 2; ++i) {
      Rational y = round_decimal(sim.yhat(k, i), 10);
      if (sigma > 0) y += round_decimal(sigma * rng.normal(), 6);
      e.y(k, i) = y;
    }
  return e;
}

}  // namespace lpvid
