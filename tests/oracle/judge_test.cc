// The oracle's judging rules (oracle/judge.h) on hand-made references: each
// verdict at and across its boundary, in exact arithmetic (J, L, U are
// rationals; the tolerance is relative on the objective).
#include <gtest/gtest.h>

#include <optional>

#include "oracle/judge.h"

namespace lpvid {
namespace {

OracleTask min_dmax_task(double tolerance = 0.01) {
  OracleTask t;
  t.kind = TaskKind::kMinDmax;
  t.delta = "0.1";
  t.tolerance = tolerance;
  return t;
}

/// lpvid certified d_max² ∈ [L, U] (either end may be missing).
ReferenceResult interval(std::optional<Rational> lower, std::optional<Rational> upper) {
  ReferenceResult r;
  r.outcome = upper ? CertifyOutcome::kVerified : CertifyOutcome::kNotVerified;
  if (lower) {
    r.lower_verified = true;
    r.lower = *lower;
    r.lower_certificate = "lower.json";
  }
  if (upper) {
    r.upper_verified = true;
    r.upper = *upper;
    r.upper_certificate = "upper.json";
  }
  return r;
}

OracleAnswer claims_dmax(const Rational& dmax) {
  OracleAnswer a;
  a.dmax = dmax;
  return a;
}

TEST(OracleJudge, ABoundIsJudgedAgainstTheCertifiedInterval) {
  const ReferenceResult ref = interval(Rational(4, 100), Rational(5, 100));  // d_max² ∈ [0.04, 0.05]
  const OracleTask task = min_dmax_task();
  // J = d_max²: 0.2² = 0.04 = L is possible; just below it is not
  EXPECT_EQ(judge(task, claims_dmax(Rational(2, 10)), ref, {}).verdict, OracleVerdict::kConfirmed);
  const Judgement below = judge(task, claims_dmax(Rational(199999, 1000000)), ref, {});
  EXPECT_EQ(below.verdict, OracleVerdict::kRefuted);
  EXPECT_EQ(below.evidence, "lower.json");
  ASSERT_TRUE(below.claimed.has_value());
  EXPECT_EQ(*below.claimed, Rational(199999, 1000000) * Rational(199999, 1000000));
  // U·(1 + 0.01) = 0.0505 is within the tolerance; above it is suboptimal, with lpvid's primal certificate
  EXPECT_EQ(judge(task, claims_dmax(Rational(0)), interval(Rational(0), Rational(0)), {}).verdict, OracleVerdict::kConfirmed);
  // √0.0505 is irrational: claims on both sides of it
  const Rational just_above = Rational(2248, 10000);  // 0.2248² = 0.05053504 > 0.0505
  const Rational just_below = Rational(2247, 10000);  // 0.2247² = 0.05049009 ≤ 0.0505
  EXPECT_EQ(judge(task, claims_dmax(just_below), ref, {}).verdict, OracleVerdict::kConfirmed);
  const Judgement worse = judge(task, claims_dmax(just_above), ref, {});
  EXPECT_EQ(worse.verdict, OracleVerdict::kSuboptimal);
  EXPECT_EQ(worse.evidence, "upper.json");
}

TEST(OracleJudge, WithoutALowerEndATooGoodClaimIsUndecidedNeverRefuted) {
  const ReferenceResult ref = interval(std::nullopt, Rational(5, 100));
  EXPECT_EQ(judge(min_dmax_task(), claims_dmax(Rational(1, 10)), ref, {}).verdict, OracleVerdict::kUndecided);
  // a claim at or above U is attained: lpvid's certificate holds there
  // 0.23² = 0.0529: above U·1.01 = 0.0505 (suboptimal), within U·1.5 and ≥ U (attained: confirmed)
  EXPECT_EQ(judge(min_dmax_task(), claims_dmax(Rational(23, 100)), ref, {}).verdict, OracleVerdict::kSuboptimal);
  EXPECT_EQ(judge(min_dmax_task(0.5), claims_dmax(Rational(23, 100)), ref, {}).verdict, OracleVerdict::kConfirmed);
}

TEST(OracleJudge, AWitnessDecidesFirst) {
  const ReferenceResult ref = interval(Rational(4, 100), Rational(5, 100));
  WitnessResult fails;
  fails.status = WitnessResult::kFails;
  fails.certificate = "witness.not_a_witness.json";
  const Judgement j = judge(min_dmax_task(), claims_dmax(Rational(22, 100)), ref, fails);
  EXPECT_EQ(j.verdict, OracleVerdict::kRefuted);
  EXPECT_EQ(j.evidence, "witness.not_a_witness.json");
  WitnessResult malformed;
  malformed.status = WitnessResult::kMalformed;
  EXPECT_EQ(judge(min_dmax_task(), claims_dmax(Rational(22, 100)), ref, malformed).verdict, OracleVerdict::kError);
  // a witness that holds confirms a claim lpvid cannot bound from below
  WitnessResult holds;
  holds.status = WitnessResult::kHolds;
  // (J = 0.0025, below lpvid's own upper end 0.01: attained, and better than lpvid's answer)
  EXPECT_EQ(judge(min_dmax_task(), claims_dmax(Rational(5, 100)), interval(std::nullopt, Rational(1, 100)), holds).verdict,
            OracleVerdict::kConfirmed);
  EXPECT_EQ(judge(min_dmax_task(), claims_dmax(Rational(5, 100)), interval(std::nullopt, Rational(1, 100)), {}).verdict,
            OracleVerdict::kUndecided);
}

TEST(OracleJudge, AVerdictIsJudgedAgainstLpvidsCertifiedOne) {
  OracleTask task;
  task.kind = TaskKind::kDecide;
  ReferenceResult invalidated;
  invalidated.outcome = CertifyOutcome::kInvalidated;
  invalidated.invalidation_certificate = "invalidated.json";
  ReferenceResult consistent;
  consistent.outcome = CertifyOutcome::kVerified;
  consistent.upper_certificate = "consistent.json";
  ReferenceResult undecided;
  undecided.outcome = CertifyOutcome::kUndecided;
  OracleAnswer says_consistent, says_invalidated;
  says_consistent.verdict = "consistent";
  says_invalidated.verdict = "invalidated";
  const Judgement wrong = judge(task, says_consistent, invalidated, {});
  EXPECT_EQ(wrong.verdict, OracleVerdict::kRefuted);
  EXPECT_EQ(wrong.evidence, "invalidated.json");
  EXPECT_EQ(judge(task, says_invalidated, consistent, {}).evidence, "consistent.json");
  EXPECT_EQ(judge(task, says_invalidated, consistent, {}).verdict, OracleVerdict::kRefuted);
  EXPECT_EQ(judge(task, says_consistent, consistent, {}).verdict, OracleVerdict::kConfirmed);
  EXPECT_EQ(judge(task, says_invalidated, invalidated, {}).verdict, OracleVerdict::kConfirmed);
  EXPECT_EQ(judge(task, says_invalidated, undecided, {}).verdict, OracleVerdict::kUndecided);
  OracleAnswer failed;
  failed.failed = true;
  EXPECT_EQ(judge(task, failed, consistent, {}).verdict, OracleVerdict::kError);
}

}  // namespace
}  // namespace lpvid
