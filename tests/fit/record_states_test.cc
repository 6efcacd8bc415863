// Each record its own initial state in fits over several records
// (fit/record_states.h, LpvModel::later_x0), against answers known by
// construction: records generated from one known system, each from its own
// initial state.
#include <gtest/gtest.h>

#include <cmath>

#include "data/experiment_builder.h"
#include "fit/output_error_fit.h"
#include "model/simulate.h"

namespace lpvid {
namespace {

/// x+ = A x + B u, y = C x: an observable second-order system (C A and C
/// are independent), so a record's initial state shows in its output.
LpvModel<double> plant() {
  LpvModel<double> m;
  m.nx = 2;
  m.nu = m.ny = 1;
  const Monomial one{{}};
  Mat<double> a(2, 2), b(2, 1), c(1, 2);
  a << 0.8, 0.1, 0.0, 0.7;
  b << 1.0, 0.5;
  c << 1.0, 0.0;
  m.A = ParamMatrix<double>(2, 2);
  m.A.add(one, a);
  m.B = ParamMatrix<double>(2, 1);
  m.B.add(one, b);
  m.C = ParamMatrix<double>(1, 2);
  m.C.add(one, c);
  m.D = ParamMatrix<double>(1, 1);
  m.x0 = Vec<double>::Zero(2);
  return m;
}

/// n samples of the plant from x0 under a deterministic multi-sine.
Experiment<double> record(const LpvModel<double>& m, const Vec<double>& x0, Eigen::Index n, double phase) {
  Experiment<double> e;
  e.u.resize(n, 1);
  for (Eigen::Index k = 0; k < n; ++k)
    e.u(k, 0) = std::sin(0.3 * static_cast<double>(k) + phase) + 0.5 * std::sin(1.1 * static_cast<double>(k));
  e.rho = Mat<double>(n, 0);
  LpvModel<double> p = m;
  p.x0 = x0;
  e.y = simulate(p, e).output;
  return e;
}

Vec<double> vec2(double a, double b) {
  Vec<double> v(2);
  v << a, b;
  return v;
}

// Two records of one system from different states: the fit of x0 over both
// finds each record's own state and leaves no error; their listed order only
// swaps the two states.
TEST(RecordStates, EachRecordGetsItsOwnInitialState) {
  const LpvModel<double> m = plant();
  const Vec<double> xa = vec2(2.0, -1.0), xb = vec2(-3.0, 4.0);
  const Experiment<double> ra = record(m, xa, 150, 0.0), rb = record(m, xb, 120, 0.7);
  const FitResult ab = fit_slots(m, x0_slots(m), stack_records<double>({ra, rb}));
  ASSERT_TRUE(ab.finite);
  EXPECT_LT(ab.rms, 1e-8);
  ASSERT_EQ(ab.model.later_x0.size(), 1u);
  EXPECT_LT((ab.model.x0 - xa).norm(), 1e-6);
  EXPECT_LT((ab.model.later_x0[0] - xb).norm(), 1e-6);

  const FitResult ba = fit_slots(m, x0_slots(m), stack_records<double>({rb, ra}));
  ASSERT_EQ(ba.model.later_x0.size(), 1u);
  EXPECT_LT((ba.model.x0 - xb).norm(), 1e-6);
  EXPECT_LT((ba.model.later_x0[0] - xa).norm(), 1e-6);
}

// One state for both records cannot fit them: the least-squares common x0
// (computed here from the output's affine dependence on x0, column by
// column) leaves an error that the per-record fit removes.
TEST(RecordStates, OneCommonStateLeavesTheErrorThePerRecordStatesRemove) {
  const LpvModel<double> m = plant();
  const Experiment<double> both = stack_records<double>({record(m, vec2(2.0, -1.0), 150, 0.0), record(m, vec2(-3.0, 4.0), 120, 0.7)});
  // output from x0 = 0 in every record, and the response to each unit state
  // started in every record (records restart: the same x0 in each)
  Experiment<double> zero = both;
  zero.record_x0 = {Vec<double>::Zero(2), Vec<double>::Zero(2)};
  const Mat<double> y0 = simulate(m, zero).output;
  Mat<double> g(both.n(), 2);
  for (int i = 0; i < 2; ++i) {
    Experiment<double> unit = zero;
    unit.record_x0 = {Vec<double>::Unit(2, i), Vec<double>::Unit(2, i)};
    g.col(i) = simulate(m, unit).output.col(0) - y0.col(0);
  }
  const Vec<double> r = both.y.col(0) - y0.col(0);
  const Vec<double> common = g.colPivHouseholderQr().solve(r);
  const double common_rms = std::sqrt((r - g * common).squaredNorm() / static_cast<double>(both.n()));
  EXPECT_GT(common_rms, 0.05);
  EXPECT_LT(fit_slots(m, x0_slots(m), both).rms, 1e-8);
}

// The fit sizes the states to the data: a record that the cost does not
// reach keeps its start (x0's start), and one record leaves no later state.
TEST(RecordStates, ARecordOutsideTheCostKeepsItsStartAndOneRecordHasNone) {
  const LpvModel<double> m = plant();
  const Vec<double> xa = vec2(2.0, -1.0);
  const Experiment<double> both = stack_records<double>({record(m, xa, 150, 0.0), record(m, vec2(-3.0, 4.0), 120, 0.7)});
  FitOptions first;
  first.last_sample = 100;  // rows of record 1 only
  const FitResult f = fit_slots(m, x0_slots(m), both, first);
  ASSERT_EQ(f.model.later_x0.size(), 1u);
  EXPECT_EQ(f.model.later_x0[0], m.x0);
  EXPECT_LT((f.model.x0 - xa).norm(), 1e-6);

  const FitResult one = fit_slots(f.model, x0_slots(f.model), record(m, xa, 150, 0.0));
  EXPECT_TRUE(one.model.later_x0.empty());
  EXPECT_LT((one.model.x0 - xa).norm(), 1e-6);
}

// simulate() starts record 2 from later_x0 unless the data give its state:
// the same outputs as each record simulated on its own from its state.
TEST(RecordStates, SimulateStartsEachRecordFromItsOwnState) {
  LpvModel<double> m = plant();
  m.x0 = vec2(1.0, 2.0);
  m.later_x0 = {vec2(-1.0, 0.5)};
  const Experiment<double> ra = record(m, vec2(0, 0), 40, 0.0), rb = record(m, vec2(0, 0), 30, 1.0);
  const Mat<double> y = simulate(m, stack_records<double>({ra, rb})).output;
  LpvModel<double> one = m;
  one.later_x0.clear();
  const Mat<double> ya = simulate(one, ra).output;
  one.x0 = m.later_x0[0];
  const Mat<double> yb = simulate(one, rb).output;
  EXPECT_EQ(Mat<double>(y.topRows(40)), ya);
  EXPECT_EQ(Mat<double>(y.bottomRows(30)), yb);

  Experiment<double> given = stack_records<double>({ra, rb});
  given.record_x0 = {m.x0, vec2(7.0, 7.0)};
  one.x0 = vec2(7.0, 7.0);
  EXPECT_EQ(Mat<double>(simulate(m, given).output.bottomRows(30)), simulate(one, rb).output);
}

}  // namespace
}  // namespace lpvid
