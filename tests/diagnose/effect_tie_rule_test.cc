/// The tie rule of diagnose's choice (diagnose/effect_ranking.h
/// effect_tie_rule): candidates the held-out data does not tell apart are
/// decided by parameters, then physical form, then label, and say so.

#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "diagnose/effect_ranking.h"

namespace lpvid {
namespace {

ScoredCandidate candidate(const std::string& kind, const std::string& label, double rms, int parameters) {
  ScoredCandidate c;
  c.kind = kind;
  c.label = label;
  c.rms_validation = rms;
  c.effect_parameters = parameters;
  return c;
}

TEST(EffectTieRule, ClearWinnerIsTakenWithoutATie) {
  const std::vector<ScoredCandidate> ranked = {candidate("basis_term", "b", 1.0, 3),
                                               candidate("input_delay", "d", 1.0 * (1 + 2 * kEffectTieTolerance), 1)};
  std::optional<EffectTie> tie;
  EXPECT_EQ(effect_tie_rule(ranked, {0, 1}, tie), 0);
  EXPECT_FALSE(tie.has_value());
}

TEST(EffectTieRule, FewerParametersWinsATie) {
  const std::vector<ScoredCandidate> ranked = {candidate("output_polynomial", "p", 1.0, 3),
                                               candidate("basis_term", "b", 1.004, 2),
                                               candidate("input_delay", "d", 1.5, 1)};
  std::optional<EffectTie> tie;
  EXPECT_EQ(effect_tie_rule(ranked, {0, 1, 2}, tie), 1);
  ASSERT_TRUE(tie.has_value());
  EXPECT_EQ(tie->tied, (std::vector<int>{0, 1}));
  EXPECT_NEAR(tie->margin, 0.004, 1e-12);
  EXPECT_EQ(tie->rule, "fewer parameters");
}

TEST(EffectTieRule, ThenThePhysicalFormThenTheLabel) {
  std::optional<EffectTie> tie;
  const std::vector<ScoredCandidate> forms = {candidate("basis_term", "b", 1.0, 2),
                                              candidate("input_saturation", "s", 1.001, 2)};
  EXPECT_EQ(effect_tie_rule(forms, {0, 1}, tie), 1);
  ASSERT_TRUE(tie.has_value());
  EXPECT_EQ(tie->rule, "physical form");
  const std::vector<ScoredCandidate> labels = {candidate("basis_term", "u^2 in C, D", 1.0, 2),
                                               candidate("basis_term", "u in B", 1.001, 2)};
  EXPECT_EQ(effect_tie_rule(labels, {0, 1}, tie), 1);
  ASSERT_TRUE(tie.has_value());
  EXPECT_EQ(tie->rule, "label order");
}

TEST(EffectTieRule, OnlyAcceptedCandidatesTakePart) {
  // rank 2 is within the tolerance but was not accepted (it lost the folds): no tie
  const std::vector<ScoredCandidate> ranked = {candidate("basis_term", "b", 1.0, 3),
                                               candidate("input_delay", "d", 1.001, 1)};
  std::optional<EffectTie> tie;
  EXPECT_EQ(effect_tie_rule(ranked, {0}, tie), 0);
  EXPECT_FALSE(tie.has_value());
  EXPECT_EQ(effect_tie_rule(ranked, {}, tie), -1);
}

TEST(EffectTieRule, PhysicalFormsComeBeforeGenericExpansions) {
  EXPECT_LT(physical_form_rank("input_delay"), physical_form_rank("state_nonlinearity"));
  EXPECT_LT(physical_form_rank("state_nonlinearity"), physical_form_rank("output_polynomial"));
  EXPECT_LT(physical_form_rank("output_piecewise_linear"), physical_form_rank("basis_term"));
  EXPECT_LT(physical_form_rank("basis_term"), physical_form_rank("an unknown kind"));
}

}  // namespace
}  // namespace lpvid
