// The declared dynamics are WRONG the way real data makes
// them wrong: the LPV part (A, B, C, D, x0) is fitted by output error
// through the undeclared effect, not given exactly. The joint re-fit of the
// dynamics with each candidate must still rank the right
// kind first and choose it, and the control case must answer `none`.
// Known answers by construction (examples/effect_cases.h).
#include <gtest/gtest.h>

#include <tuple>

#include "diagnose/effect_ranking.h"
#include "examples/effect_cases.h"

namespace lpvid {
namespace {

/// The declared model with its dynamics and output map fitted to `est`,
/// which contains the effect (the way a linear part is fitted to real data).
LpvModel<double> fitted_through_effect(const LpvModel<double>& declared, const Experiment<double>& est) {
  const LpvModel<double> m = explicit_model(declared);
  const FitResult f = fit_slots(m, with_dynamics_slots(refit_slots(m), m), est);
  EXPECT_TRUE(f.finite);
  return f.model;
}

class WrongDynamicsTest : public ::testing::TestWithParam<std::tuple<std::string, int>> {};

TEST_P(WrongDynamicsTest, RightKindFirstAndControlAnswersNone) {
  const auto& [kind, seed] = GetParam();
  const EffectCase c = make_effect_case(kind, 300, static_cast<uint64_t>(seed), 0.02);
  const LpvModel<double> plain = convert_model<double>(c.declared);
  const LpvModel<double> scheduled = with_input_scheduling(plain);
  const Experiment<double> est = with_input_scheduling(nearest_double(c.estimation), plain, scheduled);
  const Experiment<double> val = with_input_scheduling(nearest_double(c.validation), plain, scheduled);
  const LpvModel<double> wrong = fitted_through_effect(scheduled, est);
  RankingOptions o;
  o.max_effects = 1;
  const RankingResult r = rank_effects(wrong, est, val, o);
  ASSERT_EQ(r.rounds.size(), 1u);
  const RankingRound& first = r.rounds.front();
  ASSERT_FALSE(first.ranked.empty());
  const ScoredCandidate& best = first.ranked.front();
  std::string table;  // the top of the ranking, for failure messages
  for (size_t i = 0; i < first.ranked.size(); ++i)
    table += "\n  " + first.ranked[i].label + ": val " + std::to_string(first.ranked[i].rms_validation) + " est " + std::to_string(first.ranked[i].rms_estimation);
  table += "\n  reference " + std::to_string(first.reference_validation) + ", before " + std::to_string(r.before_validation) + " (est " + std::to_string(r.before_estimation) + ")";
  SCOPED_TRACE(table);
  if (kind == "none") {
    EXPECT_LT(first.chosen, 0) << "best: " << best.label << " val " << best.rms_validation << " vs "
                               << first.reference_validation;
    return;
  }
  ASSERT_EQ(first.chosen, 0) << kind << ": nothing chosen; best " << best.label << " val " << best.rms_validation
                             << " vs reference " << first.reference_validation;
  EXPECT_EQ(best.kind, reported_effect_kind(kind)) << "ranked first: " << best.label;
  if (kind == "state_feedback") {
    EXPECT_NE(best.label.find("in A"), std::string::npos) << best.label;
  }
  EXPECT_LE(r.after_validation, 0.7 * r.before_validation)
      << kind << ": validation RMS " << r.before_validation << " -> " << r.after_validation;
}

std::string case_name(const ::testing::TestParamInfo<std::tuple<std::string, int>>& info) {
  return std::get<0>(info.param) + "_seed" + std::to_string(std::get<1>(info.param));
}

// Every generated kind, seed 5.
INSTANTIATE_TEST_SUITE_P(Generated, WrongDynamicsTest,
                         ::testing::Combine(::testing::ValuesIn(effect_case_kinds()), ::testing::Values(5)), case_name);

// The even output maps once more on another seed: their linear part fitted
// through the map carries no sign (best linear approximation ~0 for |.|), so
// they depend on the quadratic-kernel start (fit/wiener_starts.h); without
// it both fail (measured: abs_value ranks input_polynomial first,
// output_polynomial ranks "basis_term u1 in B" first). Seeds 7, 11, 23, 31
// passed for every kind when this was written.
INSTANTIATE_TEST_SUITE_P(EvenMaps, WrongDynamicsTest,
                         ::testing::Combine(::testing::Values("abs_value", "output_polynomial"), ::testing::Values(23)),
                         case_name);

}  // namespace
}  // namespace lpvid
