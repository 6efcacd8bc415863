// An effect's reading says what its fitted parameters make it on the record
// (diagnose/effect_reading.h). Known answers by construction: a dead zone
// the record never enters is exactly an input offset, one of width 5e-9 is
// within 2.5e-9 of one; |.| of a positive signal is exactly the identity; a
// saturation no sample reaches is the identity. Maps the record does use
// keep their label (empty reading). A state |.| or hinge that never crosses
// its kink is the linear term (or zero) it is. The estimation share that
// the acceptance floor reads is checked against its formula.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "diagnose/effect_ranking.h"
#include "diagnose/effect_reading.h"
#include "model/simulate.h"

namespace lpvid {
namespace {

/// y = D u + offset c (no state): the output map's argument is D u + c.
LpvModel<double> static_gain(double d, double c) {
  LpvModel<double> m;
  m.nx = 0;
  m.nu = m.ny = 1;
  m.columns = {{"u"}, {"y"}, {}};
  const Monomial one = constant_monomial(0);
  m.A = ParamMatrix<double>(0, 0);
  m.B = ParamMatrix<double>(0, 1);
  m.C = ParamMatrix<double>(1, 0);
  m.D = ParamMatrix<double>(1, 1);
  m.D.add(one, Mat<double>::Constant(1, 1, d));
  m.offset.basis = {one};
  m.offset.values = {Vec<double>::Constant(1, c)};
  return m;
}

/// u_k sweeping [lo, hi] (a triangle), y = 0.
Experiment<double> sweep(double lo, double hi, int n = 200) {
  Experiment<double> e;
  e.u.resize(n, 1);
  for (int k = 0; k < n; ++k) e.u(k, 0) = lo + (hi - lo) * (k < n / 2 ? 2.0 * k / n : 2.0 * (n - k) / n);
  e.y = Mat<double>::Zero(n, 1);
  e.rho.resize(n, 0);
  return e;
}

LpvModel<double> with_input(StaticKind kind, double lower, double upper) {
  LpvModel<double> m = static_gain(1, 0);
  m.statics.input.kind = kind;
  m.statics.input.lower = lower;
  m.statics.input.upper = upper;
  return m;
}

TEST(EffectReading, DeadZoneNoSampleEntersIsAnInputOffset) {
  const LpvModel<double> m = with_input(StaticKind::kDeadZone, 0.0082 - 5e-9, 0.0082);
  const Experiment<double> e = sweep(2, 9);
  const std::string r = effect_reading("dead_zone", m, e);
  EXPECT_NE(r.find("input offset"), std::string::npos) << r;
  EXPECT_NE(r.find("u' = u - 0.0082"), std::string::npos) << r;
  // the claim, checked: the map is u - 0.0082 on every sample
  const Mat<double> g = m.statics.model_input(e.u);
  for (Eigen::Index k = 0; k < e.n(); ++k) EXPECT_DOUBLE_EQ(g(k, 0), e.u(k, 0) - 0.0082);
}

TEST(EffectReading, NegligibleDeadBandInsideTheRangeIsAnOffset) {
  const LpvModel<double> m = with_input(StaticKind::kDeadZone, 5 - 2.5e-9, 5 + 2.5e-9);
  const std::string r = effect_reading("dead_zone", m, sweep(2, 9));
  EXPECT_NE(r.find("u' = u - 5"), std::string::npos) << r;
  EXPECT_NE(r.find("negligible"), std::string::npos) << r;
}

TEST(EffectReading, AUsedDeadZoneKeepsItsLabel) {
  EXPECT_EQ(effect_reading("dead_zone", with_input(StaticKind::kDeadZone, 4, 6), sweep(2, 9)), "");
}

TEST(EffectReading, SaturationNeverReachedIsTheIdentity) {
  const std::string r = effect_reading("input_saturation", with_input(StaticKind::kSaturation, -1, 10), sweep(2, 9));
  EXPECT_NE(r.find("the identity"), std::string::npos) << r;
  EXPECT_EQ(effect_reading("input_saturation", with_input(StaticKind::kSaturation, 3, 10), sweep(2, 9)), "");
}

TEST(EffectReading, AbsOfAOneSignedOutputIsTheIdentity) {
  // the argument D u + c = 16 u + 44 ranges 76 to 188 on u in [2, 9]
  LpvModel<double> m = static_gain(16, 44);
  m.statics.output.kind = StaticKind::kAbs;
  const Experiment<double> e = sweep(2, 9);
  const std::string r = effect_reading("abs_value", m, e);
  EXPECT_NE(r.find("the identity"), std::string::npos) << r;
  const Simulation<double> s = simulate(m, e);
  EXPECT_TRUE(s.output.isApprox(Mat<double>(s.yhat + s.offset)));  // the claim, checked
  // negative throughout: a sign change
  m.offset.values = {Vec<double>::Constant(1, -300)};
  EXPECT_NE(effect_reading("abs_value", m, e).find("sign change"), std::string::npos);
  // crossing zero: |.| is used
  m.offset.values = {Vec<double>::Constant(1, -100)};
  EXPECT_EQ(effect_reading("abs_value", m, e), "");
}

/// x+ = 0.5 x + u (one state, y = x), scheduled on "@<f>(x1-c)" with a
/// state-offset gain e = 0: the state run is the linear one, the reading
/// reads the function's argument along it.
LpvModel<double> state_function_model(const std::string& column) {
  LpvModel<double> m;
  m.nx = m.nu = m.ny = 1;
  m.scheduling = {"s"};
  m.columns = {{"u"}, {"y"}, {column}};
  const Monomial one = constant_monomial(1);
  m.A = ParamMatrix<double>(1, 1);
  m.A.add(one, Mat<double>::Constant(1, 1, 0.5));
  m.B = ParamMatrix<double>(1, 1);
  m.B.add(one, Mat<double>::Constant(1, 1, 1.0));
  m.C = ParamMatrix<double>(1, 1);
  m.C.add(one, Mat<double>::Constant(1, 1, 1.0));
  m.D = ParamMatrix<double>(1, 1);
  Monomial h = one;
  h.powers[0] = 1;
  m.state_offset.basis = {h};
  m.state_offset.values = {Vec<double>::Zero(1)};
  m.x0 = Vec<double>::Zero(1);
  return m;
}

/// The state run x+ = 0.5 x + u from 0, computed here again.
std::vector<double> state_run(const Experiment<double>& e) {
  std::vector<double> x(static_cast<size_t>(e.n()));
  double v = 0;
  for (Eigen::Index k = 0; k < e.n(); ++k) {
    x[static_cast<size_t>(k)] = v;
    v = 0.5 * v + e.u(k, 0);
  }
  return x;
}

TEST(EffectReading, AStateAbsWhoseArgumentNeverCrossesItsKinkIsALinearTerm) {
  // x starts at 0 and rises to at most 18 with u in [2, 9]: x1 + 1 > 0 throughout
  const Experiment<double> e = sweep(2, 9);
  const std::string col = "@abs(x1+1)";
  const std::string r = state_nonlinearity_reading(state_function_model(col), e, {col});
  EXPECT_NE(r.find("a linear term: |x1 + 1| = x1 + 1 on every sample"), std::string::npos) << r;
  // a hinge far above every state value is zero on the record
  const std::string h = "@hinge(x1-100)";
  EXPECT_NE(state_nonlinearity_reading(state_function_model(h), e, {h}).find("zero: max(x1 - 100, 0) = 0"),
            std::string::npos);
  // an outflow law sqrt(max(x - c, 0)) whose cut-off is never reached is a plain square root
  const std::string q = "@sqrtpos(x1+1)";
  EXPECT_NE(state_nonlinearity_reading(state_function_model(q), e, {q}).find("a square root on every sample"),
            std::string::npos);
}

TEST(EffectReading, AStateAbsThatCrossesItsKinkSaysOnWhichShare) {
  const Experiment<double> e = sweep(2, 9);
  const std::vector<double> x = state_run(e);
  const double below = static_cast<double>(std::count_if(x.begin(), x.end(), [](double v) { return v < 10; }));
  ASSERT_GT(below, 0);
  ASSERT_LT(below, static_cast<double>(x.size()));
  char share[32];
  std::snprintf(share, sizeof share, "%.3g", 100.0 * below / static_cast<double>(x.size()));
  const std::string col = "@abs(x1-10)";
  const std::string r = state_nonlinearity_reading(state_function_model(col), e, {col});
  EXPECT_NE(r.find("the kink is used: x1 - 10 is below 0 on " + std::string(share) + " % of the samples"),
            std::string::npos)
      << r;
}

// The share floor's figure (effect_ranking.h set_estimation_shares): for one
// output and one added signal s it is (r·s)² / (‖r‖²‖s‖²), r the current
// model's estimation residual; a candidate equal to the current model adds
// nothing and explains nothing.
TEST(EstimationShare, IsTheSquaredCosineOfTheResidualAndTheAddedSignal) {
  Experiment<double> e = sweep(2, 9);
  for (Eigen::Index k = 0; k < e.n(); ++k) e.y(k, 0) = e.u(k, 0) + 0.3 + std::sin(0.7 * static_cast<double>(k));
  RankingRound r;
  r.current = static_gain(1, 0);
  r.ranked.resize(3);
  r.ranked[0].model = static_gain(1, 0.5);  // adds the constant 0.5
  r.ranked[1].model = static_gain(1, 0);    // adds nothing
  r.ranked[2].model = static_gain(1.1, 0);  // adds 0.1 u
  set_estimation_shares(r, e);
  double rr = 0, rs0 = 0, ss0 = 0, rs2 = 0, ss2 = 0;
  for (Eigen::Index k = 0; k < e.n(); ++k) {
    const double res = e.y(k, 0) - e.u(k, 0);
    rr += res * res;
    rs0 += res * 0.5;
    ss0 += 0.25;
    rs2 += res * 0.1 * e.u(k, 0);
    ss2 += 0.01 * e.u(k, 0) * e.u(k, 0);
  }
  EXPECT_NEAR(r.ranked[0].estimation_share, rs0 * rs0 / (rr * ss0), 1e-12);
  EXPECT_EQ(r.ranked[1].estimation_share, 0.0);
  EXPECT_NEAR(r.ranked[2].estimation_share, rs2 * rs2 / (rr * ss2), 1e-12);
  EXPECT_GT(r.ranked[0].estimation_share, kMinEstimationShare);
}

TEST(EffectReading, OtherKindsHaveNoReading) {
  EXPECT_EQ(effect_reading("basis_term", static_gain(1, 0), sweep(2, 9)), "");
}

}  // namespace
}  // namespace lpvid
