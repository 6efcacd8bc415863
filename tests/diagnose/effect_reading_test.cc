// An effect's reading says what its fitted parameters make it on the record
// (diagnose/effect_reading.h). Known answers by construction: a dead zone
// the record never enters is exactly an input offset, one of width 5e-9 is
// within 2.5e-9 of one; |.| of a positive signal is exactly the identity; a
// saturation no sample reaches is the identity. Maps the record does use
// keep their label (empty reading).
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

TEST(EffectReading, OtherKindsHaveNoReading) {
  EXPECT_EQ(effect_reading("basis_term", static_gain(1, 0), sweep(2, 9)), "");
}

}  // namespace
}  // namespace lpvid
