#include "examples/paper_example2.h"

#include <cmath>

#include "core/number_text.h"
#include "examples/decimal_rounding.h"
#include "examples/model_literals.h"
#include "examples/random_stream.h"
#include "model/simulate.h"

namespace lpvid {
namespace {

using literals::dec;
using literals::mat;

using literals::kOne;
using literals::kRho;
using literals::kRho2;

LpvModel<Rational> example2_skeleton() {
  LpvModel<Rational> m = literals::siso_rho1_skeleton();
  m.A.add(kOne, mat(2, 2, {"0", "1", "-0.24", "0.9"}));
  m.A.add(kRho, mat(2, 2, {"0", "0", "-0.1", "-0.4"}));
  m.B.add(kOne, mat(2, 1, {"0", "1"}));
  m.C.add(kOne, mat(1, 2, {"1", "0"}));
  m.C.add(kRho, mat(1, 2, {"0.5", "0"}));
  m.uncertainty.structure = UncertaintyStructure::kMultiplicative;
  m.uncertainty.weight = dec("0.01");
  m.offset.basis = {kOne, kRho, kRho2};
  return m;
}

}  // namespace

LpvModel<Rational> example2_true_model() {
  LpvModel<Rational> m = example2_skeleton();
  m.offset.values = {Vec<Rational>::Constant(1, dec("0.5")), Vec<Rational>::Constant(1, dec("0.8")),
                     Vec<Rational>::Constant(1, dec("-0.3"))};
  return m;
}

LpvModel<Rational> example2_initial_model() { return example2_skeleton(); }

Experiment<Rational> example2_experiment(const Example2Options& o) {
  RandomStream rng(o.seed);
  const int n = o.n;
  Experiment<Rational> e;
  e.source = "example2";
  e.u = Mat<Rational>::Zero(n, 1);
  e.rho = Mat<Rational>::Zero(n, 1);
  random_pulse_train(rng, 0, n, [&](long k, bool high) { e.u(k, 0) = high ? dec("0.5") : dec("-0.5"); });
  for (int i = 0; i < n; ++i) {
    const double t = n > 1 ? static_cast<double>(i) / (n - 1) : 0.0;
    e.rho(i, 0) = round_decimal(0.5 - 0.45 * std::cos(6.283185307179586 * t), 4);
  }
  e.y = Mat<Rational>::Zero(n, 1);
  const Simulation<Rational> sim = simulate(example2_true_model(), e);
  const double sigma = std::sqrt(o.noise_variance);
  for (int i = 0; i < n; ++i) {
    Rational y = round_decimal(sim.yhat(i, 0) + sim.offset(i, 0), 10);
    if (sigma > 0) y += round_decimal(sigma * rng.normal(), 6);
    e.y(i, 0) = y;
  }
  return e;
}

}  // namespace lpvid
