// The state_nonlinearity effect (docs/design.md §9, §11): candidates
// e·f(x_i − c) in the state equation, f = √|·|, |·|, max(·, 0), with the
// shift c and the state offset e as fit slots (fit/model_parameters.h).
//
// The two-tank analogue is built here, not taken from the program: levels
// h1, h2 (discrete time, one sample ~ 4 s)
//   h1+ = h1 − k1·√h1 + k4·u,   h2+ = h2 + k2·√h1 − k3·√h2,   y = h2 + noise,
// k1 = k2 = k3 = 0.2, k4 = 0.1: the steady state is h1 = h2 = (u/2)², so
// u ∈ [2, 8] gives levels 1 … 16, a static gain that grows 4× over the range
// (a linear model cannot follow it), and time constants 2√h/k = 10 … 40
// samples. A second-order linear model (fit/linear_fit.h) is the start; the
// √ candidate re-fitted by fit_slots must lower the free-run validation RMS
// (x0 from 5 samples, fit/output_error_fit.h) to ≤ 0.6 × the linear one on a
// separate record.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include <gtest/gtest.h>

#include "core/number_text.h"
#include "diagnose/effect_candidates.h"
#include "fit/linear_fit.h"
#include "fit/model_parameters.h"
#include "fit/output_error_fit.h"
#include "model/simulate.h"
#include "model/state_scheduling.h"

namespace lpvid {
namespace {

/// One record of the tank analogue: a staircase u (levels uniform in [2, 8],
/// held 60 … 150 samples), starting at the steady state of the first level.
Experiment<double> tank_record(int n, unsigned seed, double noise) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> level(2.0, 8.0);
  std::uniform_int_distribution<int> hold(60, 150);
  std::normal_distribution<double> e(0.0, noise);
  Experiment<double> x;
  x.u.resize(n, 1);
  x.y.resize(n, 1);
  x.rho.resize(n, 0);
  for (int k = 0; k < n;) {
    const double u = level(rng);
    for (int j = hold(rng); j > 0 && k < n; --j) x.u(k++, 0) = u;
  }
  const double k1 = 0.2, k2 = 0.2, k3 = 0.2, k4 = 0.1;
  double h1 = std::pow(x.u(0, 0) / 2, 2), h2 = h1;
  for (int k = 0; k < n; ++k) {
    x.y(k, 0) = h2 + e(rng);
    const double n1 = h1 - k1 * std::sqrt(h1) + k4 * x.u(k, 0);
    const double n2 = h2 + k2 * std::sqrt(h1) - k3 * std::sqrt(h2);
    h1 = std::max(n1, 0.0);
    h2 = std::max(n2, 0.0);
  }
  return x;
}

TEST(StateNonlinearity, SqrtCandidateExplainsTheTanks) {
  const Experiment<double> est = tank_record(1500, 1, 0.02), val = tank_record(1500, 2, 0.02);
  const ColumnMap columns{{"u1"}, {"y1"}, {}};
  LinearFitOptions lo;
  lo.order = 2;
  lo.offset = true;
  const LinearFit lin = fit_linear(est, columns, lo);
  const double rms_lin = validation_rms(lin.model, val, kValidationInitSamples);
  std::cout << "linear: estimation RMS " << lin.rms_estimation << ", validation RMS " << rms_lin << "\n";

  CandidateOptions co;
  const std::vector<EffectCandidate> all = candidate_effects(lin.model, est, co);
  int n_state = 0;
  double best = std::numeric_limits<double>::infinity();
  std::string best_label;
  int n_store = 0;
  for (const EffectCandidate& c : all) {
    if (c.kind != "state_nonlinearity") continue;
    if (c.label.rfind("store cascade", 0) == 0) {  // the two-store family (tests/diagnose/store_cascade_test.cc)
      ++n_store;
      continue;
    }
    ++n_state;
    if (c.label.rfind("state_nonlinearity sqrt", 0) != 0) continue;
    // the start is the linear model itself (e = 0), c below x_i's range
    EXPECT_NEAR(prediction_rms(c.starts.front(), est), prediction_rms(lin.model, est), 1e-9) << c.label;
    const FitResult f = fit_slots(c.starts.front(), c.slots, est);
    const double v = validation_rms(f.model, val, kValidationInitSamples);
    std::cout << c.label << ": estimation RMS " << f.rms << ", validation RMS " << v << ", column "
              << f.model.columns.rho.back() << ", " << c.slots.size() << " slots\n";
    if (v < best) {
      best = v;
      best_label = c.label;
    }
  }
  EXPECT_EQ(n_state, 3 * 2 + 2 * 2);  // sqrt, abs, hinge for x1 and x2; sqrt, hinge on both cascade levels
  EXPECT_EQ(n_store, 1);
  std::cout << "best: " << best_label << " " << best << " = " << best / rms_lin << " x linear\n";
  EXPECT_LE(best, 0.6 * rms_lin);

  CandidateOptions off;
  off.state_functions = false;
  for (const EffectCandidate& c : candidate_effects(lin.model, est, off)) EXPECT_NE(c.kind, "state_nonlinearity");
}

TEST(StateNonlinearity, CandidateShapeAndShiftSlot) {
  const Experiment<double> est = tank_record(400, 3, 0.0);
  LinearFitOptions lo;
  lo.offset = true;
  const LinearFit lin = fit_linear(est, ColumnMap{{"u1"}, {"y1"}, {}}, lo);
  for (const EffectCandidate& c : candidate_effects(lin.model, est, CandidateOptions{})) {
    if (c.kind != "state_nonlinearity" || c.label.rfind("store cascade", 0) == 0) continue;
    const LpvModel<double>& s = c.starts.front();
    const StateColumn col = parse_state_column(s.columns.rho.back());
    ASSERT_GE(col.state, 0) << c.label;
    ASSERT_EQ(s.state_offset.basis.size(), 1u);
    EXPECT_EQ(s.state_offset.basis[0].powers.back(), 1);
    EXPECT_TRUE(s.state_offset.values[0].isZero());
    const double shift = double_from_text(col.shift);
    const Vec<double> xi = simulate(s, est).x.col(col.state);  // e = 0: the start's own realisation
    if (col.function == StateFunction::kHinge) {
      EXPECT_GT(shift, xi.minCoeff());
      EXPECT_LT(shift, xi.maxCoeff());
    } else {
      EXPECT_LT(shift, xi.minCoeff()) << c.label;  // √ stays real-valued: x_i − c > 0 along the trajectory
    }
    // slots: e (nx entries), c, and the dynamics (A, B)
    int n_e = 0, n_c = 0, n_a = 0, n_b = 0;
    for (const ParameterSlot& p : c.slots) {
      n_e += p.where == ParameterSlot::Where::kStateOffset;
      n_c += p.where == ParameterSlot::Where::kStateShift;
      n_a += p.where == ParameterSlot::Where::kA;
      n_b += p.where == ParameterSlot::Where::kB;
    }
    EXPECT_EQ(n_e, s.nx);
    EXPECT_EQ(n_c, 1);
    EXPECT_GT(n_a, 0);
    EXPECT_GT(n_b, 0);
    // the shift slot reads the column text and re-renders it exactly
    const Vec<double> p = slot_values(s, c.slots);
    Vec<double> q = p;
    for (size_t i = 0; i < c.slots.size(); ++i)
      if (c.slots[i].where == ParameterSlot::Where::kStateShift) {
        EXPECT_EQ(p(static_cast<Eigen::Index>(i)), shift);
        q(static_cast<Eigen::Index>(i)) = -1.0 / 3.0;
      }
    const LpvModel<double> moved = with_slot_values(s, c.slots, q);
    EXPECT_EQ(double_from_text(parse_state_column(moved.columns.rho.back()).shift), -1.0 / 3.0);
    EXPECT_EQ(slot_values(moved, c.slots), q);
    EXPECT_EQ(slot_values(with_slot_values(s, c.slots, p), c.slots), p);
  }
}

}  // namespace
}  // namespace lpvid
