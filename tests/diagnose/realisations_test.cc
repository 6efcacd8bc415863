// Realisations that keep the input–output map (diagnose/order_variants.h,
// diagnose/cascade_form.h): the raised-order model and the two cascade
// realisations simulate the same output as the observer-form model they
// come from, from the same initial condition; the cascade's A is lower
// triangular with the poles on its diagonal (the upstream store first).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "diagnose/cascade_form.h"
#include "diagnose/order_variants.h"
#include "examples/random_stream.h"
#include "fit/observer_form.h"
#include "model/simulate.h"

namespace lpvid {
namespace {

Experiment<double> random_input(int n, uint64_t seed) {
  RandomStream rs(seed);
  Experiment<double> e;
  e.u = Mat<double>(n, 1);
  for (int k = 0; k < n; ++k) e.u(k, 0) = rs.normal();
  e.rho = Mat<double>(n, 0);
  return e;
}

/// An observer-form model with real poles p1, p2 in (−0.95, 0.95), offset and x0.
LpvModel<double> second_order(double p1, double p2, double b1, double b2, double d) {
  ObserverForm f = zero_observer_form(2, 1, true);
  f.a(0) = -(p1 + p2);
  f.a(1) = p1 * p2;
  f.B(0, 0) = b1;
  f.B(1, 0) = b2;
  f.D(0, 0) = d;
  f.x0 = Vec<double>(2);
  f.x0 << 0.3, -0.2;
  f.offset = 1.5;
  return to_lpv_model(f, ColumnMap{{"u1"}, {"y1"}, {}});
}

RC_GTEST_PROP(Realisations, CascadeKeepsTheOutputAndIsTriangular, ()) {
  const double p1 = *rc::gen::inRange(-95, 96) / 100.0, p2 = *rc::gen::inRange(-95, 96) / 100.0;
  const double b1 = *rc::gen::inRange(-100, 101) / 50.0, b2 = *rc::gen::inRange(-100, 101) / 50.0;
  const LpvModel<double> m = second_order(p1, p2, b1, b2, 0.1);
  const Experiment<double> e = random_input(80, 5);
  const Mat<double> y = simulate(m, e).output;
  const std::vector<LpvModel<double>> c = cascade_realisations(m);
  RC_ASSERT(c.size() == 2u);
  for (size_t k = 0; k < c.size(); ++k) {
    const Mat<double>& A = c[k].A.terms[0].value;
    RC_ASSERT(std::abs(A(0, 1)) < 1e-12);  // z1 does not see z2: upstream
    const double pu = k == 0 ? std::max(p1, p2) : std::min(p1, p2), pd = k == 0 ? std::min(p1, p2) : std::max(p1, p2);
    RC_ASSERT(std::abs(A(0, 0) - pu) < 1e-9);
    RC_ASSERT(std::abs(A(1, 1) - pd) < 1e-9);
    RC_ASSERT(std::abs(A(1, 0) - (1 - pd)) < 1e-9);
    const Mat<double> yc = simulate(c[k], e).output;
    RC_ASSERT((yc - y).cwiseAbs().maxCoeff() < 1e-8 * (1 + y.cwiseAbs().maxCoeff()));
  }
}

TEST(Realisations, CascadeNeedsRealPoles) {
  // z² − 2·0.9 cos(0.5) z + 0.81: a complex pair has no real cascade
  LpvModel<double> m = second_order(0.5, 0.5, 1, 0.5, 0);
  m.A.terms[0].value(0, 0) = 2 * 0.9 * std::cos(0.5);
  m.A.terms[0].value(1, 0) = -0.81;
  EXPECT_TRUE(cascade_realisations(m).empty());
}

RC_GTEST_PROP(Realisations, RaisedOrderKeepsTheOutput, ()) {
  const double p1 = *rc::gen::inRange(-95, 96) / 100.0, p2 = *rc::gen::inRange(-95, 96) / 100.0;
  const LpvModel<double> m = second_order(p1, p2, 1.0, -0.4, 0.2);
  const auto r = raise_order(m);
  RC_ASSERT(r.has_value());
  RC_ASSERT(r->nx == 3);
  const Experiment<double> e = random_input(60, 9);
  const Mat<double> y = simulate(m, e).output, yr = simulate(*r, e).output;
  RC_ASSERT((yr - y).cwiseAbs().maxCoeff() < 1e-10 * (1 + y.cwiseAbs().maxCoeff()));
}

}  // namespace
}  // namespace lpvid
