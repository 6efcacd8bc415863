// fit_slots' Jacobian columns of output-map slots from one state trajectory
// (FitOptions::reuse_state_trajectory) against every column simulated: the
// same fitted parameters, RMS and step count, bit for bit, on every effect
// case (input blocks, output blocks, an output offset, scheduling on the
// model's own state), with the joint A, B slots, x0, a late cost start and a
// held-out block.
#include <gtest/gtest.h>

#include <cstring>

#include "examples/effect_cases.h"
#include "fit/model_parameters.h"
#include "fit/output_error_fit.h"
#include "model/simulate.h"
#include "support/same_bits.h"

namespace lpvid {
namespace {

std::vector<ParameterSlot> all_slots(const LpvModel<double>& m) {
  std::vector<ParameterSlot> slots = output_map_slots(m);
  for (const auto& more : {offset_slots(m), static_map_slots(m), x0_slots(m), dynamics_slots(m)})
    slots.insert(slots.end(), more.begin(), more.end());
  return slots;
}

TEST(TrajectoryReuse, FitsAreBitForBitThoseWithEveryColumnSimulated) {
  int output_slot_cases = 0;
  for (const std::string& kind : effect_case_kinds()) {
    const EffectCase c = make_effect_case(kind, 120, 7, 0.02);
    LpvModel<double> start = convert_model<double, Rational>(c.truth);
    const Experiment<double> est = nearest_double(c.estimation);
    const std::vector<ParameterSlot> slots = all_slots(start);
    Vec<double> p = slot_values(start, slots);
    for (Eigen::Index j = 0; j < p.size(); ++j) p(j) *= (j % 2 == 0 ? 1.05 : 0.97);  // away from the truth
    start = with_slot_values(start, slots, p);
    int output_only = 0;
    for (const ParameterSlot& s : slots)
      output_only += s.where == ParameterSlot::Where::kC || s.where == ParameterSlot::Where::kD ||
                     s.where == ParameterSlot::Where::kOffset || s.where == ParameterSlot::Where::kOutputCoef ||
                     s.where == ParameterSlot::Where::kOutputLower || s.where == ParameterSlot::Where::kOutputUpper;
    output_slot_cases += output_only >= 2;
    for (int variant = 0; variant < 2; ++variant) {
      FitOptions o;
      o.max_iterations = 12;
      if (variant == 1) {
        o.first_sample = 10;
        o.skip_first = 40;
        o.skip_last = 70;
      }
      FitOptions every = o;
      every.reuse_state_trajectory = false;
      const FitResult a = fit_slots(start, slots, est, o), b = fit_slots(start, slots, est, every);
      SCOPED_TRACE(kind + (variant ? " (late start, held-out block)" : ""));
      EXPECT_TRUE(test::same_bits(slot_values(a.model, slots), slot_values(b.model, slots)));
      EXPECT_EQ(std::memcmp(&a.rms, &b.rms, sizeof a.rms), 0) << a.rms << " vs " << b.rms;
      EXPECT_EQ(a.iterations, b.iterations);
      EXPECT_EQ(a.finite, b.finite);
      EXPECT_GT(a.iterations, 0);
    }
  }
  EXPECT_GE(output_slot_cases, 8);  // the reuse was exercised, not skipped
}

/// output_on_trajectory with a changed output map (C, D, output offset)
/// is simulate_output of the changed model, bit for bit.
TEST(TrajectoryReuse, OutputPassOnAnotherModelsTrajectory) {
  for (const std::string& kind : effect_case_kinds()) {
    const EffectCase c = make_effect_case(kind, 80, 3, 0.02);
    const LpvModel<double> m = convert_model<double, Rational>(c.truth);
    const Experiment<double> est = nearest_double(c.estimation);
    const std::vector<ParameterSlot> slots = output_map_slots(m);
    Vec<double> p = slot_values(m, slots);
    p.array() += 0.125;
    const LpvModel<double> changed = with_slot_values(m, slots, p);
    const Simulation<double> trajectory = simulate_one_record(m, est, SimulationParts::kOutput);
    const Mat<double> got = output_on_trajectory(changed, trajectory, m.statics.model_input(est.u));
    const Mat<double> want = simulate_output(changed, est);
    EXPECT_TRUE(test::same_bits(got, want)) << kind;
    EXPECT_FALSE(test::same_bits(got, simulate_output(m, est))) << kind << ": the change moved nothing";
  }
}

}  // namespace
}  // namespace lpvid
