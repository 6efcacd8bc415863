// Scheduling on the model's own state (model/state_scheduling.h).
// Known answers from the definition: grid(v) = floor(v·2^32 + 1/2)/2^32,
// the double and the exact rule agree on values away from a midpoint, and a
// "@x1" column is the state x_1 of the model's own simulation whatever the
// data file holds there.
#include <cmath>
#include <cstdint>
#include <cstring>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "examples/effect_cases.h"
#include "model/simulate.h"
#include "model/state_scheduling.h"

namespace lpvid {
namespace {

TEST(StateScheduling, ColumnNames) {
  EXPECT_EQ(state_scheduling_index("rho1"), -1);
  EXPECT_EQ(state_scheduling_index("@x1"), 0);
  EXPECT_EQ(state_scheduling_index("@x12"), 11);
  for (const char* bad : {"@", "@x", "@y1", "@x0", "@x01", "@x1a", "@x-1"})
    EXPECT_THROW(state_scheduling_index(bad), std::invalid_argument) << bad;
  EXPECT_THROW(state_scheduled({"rho1", "@x3"}, 2), std::invalid_argument);
  const auto own = state_scheduled({"rho1", "@x2"}, 2);
  ASSERT_EQ(own.size(), 1u);
  EXPECT_EQ(own[0], std::make_pair(1, 1));
}

TEST(StateScheduling, GridOfExactValues) {
  const Rational step = Rational(1) / Rational(4294967296.0);  // 2^-32
  EXPECT_EQ(scheduling_grid(Rational(3)), Rational(3));
  EXPECT_EQ(scheduling_grid(Rational(5) * step), Rational(5) * step);
  EXPECT_EQ(scheduling_grid(Rational(5) * step + step / Rational(2)), Rational(6) * step);  // tie: upward
  EXPECT_EQ(scheduling_grid(Rational(-5) * step - step / Rational(2)), Rational(-5) * step);
  EXPECT_EQ(scheduling_grid(Rational(1, 3)), Rational(1431655765) * step);  // 2^32/3 = 1431655765.33
  EXPECT_EQ(scheduling_grid(Rational(-1, 3)), Rational(-1431655765) * step);
}

RC_GTEST_PROP(StateScheduling, DoubleAndExactGridAgree, ()) {
  const double v = *rc::gen::inRange(-2000000, 2000000) / 1000.0 + *rc::gen::inRange(0, 1000000) * 1e-13;
  const Rational q(v);  // the double's exact value
  const Rational g = scheduling_grid(q);
  // the exact grid point is within half a step and a multiple of 2^-32
  const Rational step = Rational(1) / Rational(4294967296.0);
  RC_ASSERT(CGAL::abs(g - q) <= step / Rational(2));
  RC_ASSERT(scheduling_grid(g) == g);
  RC_ASSERT(Rational(scheduling_grid(v)) == g);
}

/// The double grid is floor(v·2^32 + 1/2)·2^−32 with both scalings done by
/// std::ldexp (the definition) on every kind of double: ordinary values,
/// values whose v·2^32 overflows, subnormal and zero results (of either
/// sign), infinities and NaN: the same bits.
RC_GTEST_PROP(StateScheduling, DoubleGridIsLdexpsNumbersOnEveryDouble, ()) {
  const auto by_ldexp = [](double v) { return std::ldexp(std::floor(std::ldexp(v, kSchedulingGridBits) + 0.5), -kSchedulingGridBits); };
  const auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b)); };
  const uint64_t bits = *rc::gen::arbitrary<uint64_t>();
  double any;
  std::memcpy(&any, &bits, sizeof any);
  const int e = *rc::gen::inRange(-1100, 1030);
  const double scaled = std::ldexp(*rc::gen::inRange(-1000000, 1000000) / 999983.0, e);
  for (const double v : {any, scaled, -scaled, 0.0, -0.0, 0x1p-1074, -0x1p-1074, 0x1p991, 0x1p992, -0x1.fffffffffffffp1023,
                         HUGE_VAL, -HUGE_VAL})
    RC_ASSERT(same(scheduling_grid(v), by_ldexp(v)));
}

/// The state_feedback case's truth has A(ρ, x1) = A(ρ) + x1²·[0 0; −0.006 0]
/// (examples/effect_cases.h): simulating it exactly and in double gives the
/// same trajectory, the "@x1" column equals grid(x1), and it does not depend
/// on what the experiment holds in that column.
TEST(StateScheduling, SimulationUsesTheModelsOwnState) {
  const EffectCase c = make_effect_case("state_feedback", 60, 3, 0.0);
  LpvModel<Rational> m = c.truth;
  ASSERT_EQ(m.columns.rho.back(), "@x1");
  m.x0 = Vec<Rational>::Zero(m.nx);
  m.x0(0) = Rational(1, 2);
  Experiment<Rational> e = c.estimation;  // omits the "@x1" column
  const Simulation<Rational> sq = simulate(m, e);
  ASSERT_EQ(sq.rho.cols(), 2);
  for (Eigen::Index k = 0; k < e.n(); ++k) EXPECT_EQ(sq.rho(k, 1), scheduling_grid(sq.x(k, 0))) << k;
  // a full-width experiment with garbage in the "@x1" column: same result
  Experiment<Rational> full = with_state_scheduling(m, e);
  EXPECT_EQ(full.rho, sq.rho);
  full.rho.col(1).setConstant(Rational(7));
  EXPECT_EQ(simulate(m, full).output, sq.output);
  // double path: same trajectory to round-off
  const Simulation<double> sd = simulate(convert_model<double>(m), nearest_double(e));
  for (Eigen::Index k = 0; k < e.n(); ++k) EXPECT_NEAR(sd.output(k, 0), CGAL::to_double(sq.output(k, 0)), 1e-9) << k;
  // the nonlinearity acts: the same model without the x1² term differs
  LpvModel<Rational> linear = m;
  linear.A.terms.pop_back();
  EXPECT_GT(CGAL::to_double((simulate(linear, e).output - sq.output).cwiseAbs().maxCoeff()), 1e-3);
}

}  // namespace
}  // namespace lpvid
