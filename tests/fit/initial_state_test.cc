// The multi-start initial-state fit of fit/output_error_fit.h against
// answers known by construction.
#include <gtest/gtest.h>

#include <cmath>

#include "fit/output_error_fit.h"
#include "model/simulate.h"

namespace lpvid {
namespace {

/// x+ = a x + b u, v = x, y = dz(v) with the output dead zone [-1, 1]: a
/// Wiener model whose output does not move while |v| < 1.
LpvModel<double> dead_zone_wiener(double a, double b) {
  LpvModel<double> m;
  m.nx = m.nu = m.ny = 1;
  const Monomial one{{}};
  m.A = ParamMatrix<double>(1, 1);
  m.A.add(one, Mat<double>::Constant(1, 1, a));
  m.B = ParamMatrix<double>(1, 1);
  m.B.add(one, Mat<double>::Constant(1, 1, b));
  m.C = ParamMatrix<double>(1, 1);
  m.C.add(one, Mat<double>::Constant(1, 1, 1.0));
  m.D = ParamMatrix<double>(1, 1);
  m.statics.output.kind = StaticKind::kDeadZone;
  m.statics.output.lower = -1;
  m.statics.output.upper = 1;
  m.x0 = Vec<double>::Zero(1);
  return m;
}

/// A record of the plant at rest at u = 3 before it starts (x0 = the
/// equilibrium 3 b / (1 − a)), then u = 3 + a small square wave.
Experiment<double> record_at_rest(const LpvModel<double>& plant, double a, double b, Eigen::Index n) {
  Experiment<double> e;
  e.u.resize(n, 1);
  for (Eigen::Index k = 0; k < n; ++k) e.u(k, 0) = 3.0 + ((k / 7) % 2 == 0 ? 0.2 : -0.2);
  e.rho = Mat<double>(n, 0);
  LpvModel<double> p = plant;
  p.x0 = Vec<double>::Constant(1, 3.0 * b / (1.0 - a));
  e.y = simulate(p, e).output;
  return e;
}

// From x0 = 0 the first five outputs sit in the dead zone for every x0 near
// 0 (v moves by about b per step), so the gradient is zero and a single start
// stays at x0 = 0. The equilibrium at the first input sample is among the
// starts and reaches the true x0 (= 3 here) with zero error.
TEST(InitialStateFit, EquilibriumStartEscapesAFlatOutputMapWhereZeroStartStalls) {
  const double a = 0.99, b = 0.01;
  const LpvModel<double> m = dead_zone_wiener(a, b);
  const Experiment<double> rec = record_at_rest(m, a, b, 200);
  FitOptions warm;
  warm.last_sample = 5;
  const FitResult single = fit_slots(m, x0_slots(m), rec, warm);  // the old single start from zero
  EXPECT_NEAR(single.model.x0(0), 0.0, 1e-9);
  EXPECT_GT(single.rms, 1.0);

  const FitResult multi = fit_initial_state(m, rec, 5);
  ASSERT_TRUE(multi.finite);
  EXPECT_NEAR(multi.model.x0(0), 3.0, 1e-6);
  EXPECT_LT(multi.rms, 1e-6);

  // and the benchmark score over the rest of the record follows it
  const FreeRunScore s = warmup_score(m, rec, 5);
  EXPECT_LT(s.rms, 1e-6);
  EXPECT_GT(s.fit_percent, 99.99);
}

// The starts: zero, the model's own x0, and the equilibrium (I − A)⁻¹ B u_0
// of an LTI model at the first input sample.
TEST(InitialStateFit, StartsAreZeroTheModelsStateAndTheEquilibrium) {
  const double a = 0.9, b = 0.5;
  LpvModel<double> m = dead_zone_wiener(a, b);
  m.x0 = Vec<double>::Constant(1, -2.0);
  const Experiment<double> rec = record_at_rest(m, a, b, 50);
  const std::vector<Vec<double>> s = initial_state_starts(m, rec);
  ASSERT_EQ(s.size(), 3u);  // the two equilibria (from 0 and from x0) are one point
  EXPECT_EQ(s[0](0), 0.0);
  EXPECT_EQ(s[1](0), -2.0);
  EXPECT_NEAR(s[2](0), rec.u(0, 0) * b / (1.0 - a), 1e-9);
}

}  // namespace
}  // namespace lpvid
