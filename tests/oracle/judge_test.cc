// The oracle's judging rules (oracle/judge.h) on hand-made references: each
// verdict at and across its boundary, in exact arithmetic (J, L, U are
// rationals; the tolerance is relative on the objective, with an absolute
// floor, and comes from the caller, never from the task).
#include <gtest/gtest.h>

#include <optional>

#include "core/number_text.h"
#include "oracle/judge.h"

namespace lpvid {
namespace {

OracleTask min_dmax_task() {
  OracleTask t;
  t.kind = TaskKind::kMinDmax;
  t.delta = "0.1";
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
  EXPECT_EQ(judge(min_dmax_task(), claims_dmax(Rational(23, 100)), ref, {}, {0.5, 0}).verdict, OracleVerdict::kConfirmed);
}

TEST(OracleJudge, TheToleranceIsTheCallersNotTheTasks) {
  // a task file saying 1e9 (written by the program under test) changes nothing
  OracleTask task = min_dmax_task();
  task.tolerance = 1e9;
  const ReferenceResult ref = interval(Rational(4, 100), Rational(5, 100));
  EXPECT_EQ(judge(task, claims_dmax(Rational(1)), ref, {}).verdict, OracleVerdict::kSuboptimal);
  EXPECT_EQ(judge(task, claims_dmax(Rational(1)), ref, {}, {1e9, 0}).verdict, OracleVerdict::kConfirmed);
}

TEST(OracleJudge, AnAbsoluteFloorKeepsACorrectAnswerToAZeroOptimumConfirmed) {
  // lpvid certifies d_max² ∈ [0, 1e-26]; a peer's solver stops at d_max² = 1e-11
  const ReferenceResult ref = interval(Rational(0), rational_from_text("1e-26"));
  const Rational dmax_1e11 = rational_from_text("3.16228e-6");  // squared ≈ 1.0000014e-11
  EXPECT_EQ(judge(min_dmax_task(), claims_dmax(dmax_1e11), ref, {}, {0.01, 0}).verdict, OracleVerdict::kSuboptimal);
  EXPECT_EQ(judge(min_dmax_task(), claims_dmax(dmax_1e11), ref, {}).verdict, OracleVerdict::kConfirmed);
  // the default floor is 1e-9 on the objective: 3.1623e-5² ≈ 1.00001e-9 is past it, 3.1622e-5² ≈ 0.99995e-9 is not
  EXPECT_EQ(judge(min_dmax_task(), claims_dmax(rational_from_text("3.1623e-5")), ref, {}).verdict, OracleVerdict::kSuboptimal);
  EXPECT_EQ(judge(min_dmax_task(), claims_dmax(rational_from_text("3.1622e-5")), ref, {}).verdict, OracleVerdict::kConfirmed);
}

TEST(OracleJudge, AWitnessDecidesFirst) {
  const ReferenceResult ref = interval(Rational(4, 100), Rational(5, 100));
  WitnessResult fails;
  fails.status = WitnessResult::kFails;
  fails.certificate = "witness.not_a_witness.json";
  // the claim 0.22² = 0.0484 is in [L, U]: right, but its witness is not
  const Judgement j = judge(min_dmax_task(), claims_dmax(Rational(22, 100)), ref, fails);
  EXPECT_EQ(j.verdict, OracleVerdict::kBadWitness);
  EXPECT_EQ(j.evidence, "witness.not_a_witness.json");
  // a claim below L is refuted by the lower end, whatever its witness
  const Judgement false_claim = judge(min_dmax_task(), claims_dmax(Rational(1, 10)), ref, fails);
  EXPECT_EQ(false_claim.verdict, OracleVerdict::kRefuted);
  EXPECT_EQ(false_claim.evidence, "lower.json");
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
  // a failing witness: the claim is still refuted when it is false, else only its witness is bad
  WitnessResult fails;
  fails.status = WitnessResult::kFails;
  fails.certificate = "witness.not_a_witness.json";
  EXPECT_EQ(judge(task, says_consistent, invalidated, fails).verdict, OracleVerdict::kRefuted);
  EXPECT_EQ(judge(task, says_consistent, consistent, fails).verdict, OracleVerdict::kBadWitness);
  EXPECT_EQ(judge(task, says_consistent, undecided, fails).verdict, OracleVerdict::kBadWitness);
  OracleAnswer failed;
  failed.failed = true;
  EXPECT_EQ(judge(task, failed, consistent, {}).verdict, OracleVerdict::kError);
}

/// An identify task (min d_max at δ) and a claim (θ, d_max).
OracleTask identify_task() {
  OracleTask t = min_dmax_task();
  t.kind = TaskKind::kIdentify;
  return t;
}
OracleAnswer claims_theta(const Rational& dmax, std::vector<Rational> theta) {
  OracleAnswer a = claims_dmax(dmax);
  a.theta = Vec<Rational>(static_cast<Eigen::Index>(theta.size()));
  for (size_t i = 0; i < theta.size(); ++i) a.theta(static_cast<Eigen::Index>(i)) = theta[i];
  return a;
}

/// lpvid's reference for an identify task: the fixed θ's d_max² ∈ [L, U] and
/// a class lower end L_class = 0.01 over 3 parameters (θ_out of 2 entries, one
/// offset φ, always free); `box`: θ_out in the box 1 ± 1/10, −2 ± 1/100.
ReferenceResult class_reference(bool box) {
  ReferenceResult r = interval(Rational(4, 100), Rational(5, 100));
  ClassReference& k = r.klass;
  k.verified = true;
  k.lower = Rational(1, 100);
  k.certificate = "class.json";
  k.whole_class = !box;
  k.center = Vec<Rational>::Zero(3);
  k.radius = Vec<Rational>::Zero(3);
  if (box) {
    k.center << Rational(1), Rational(-2), Rational(0);
    k.radius << Rational(1, 10), Rational(1, 100), Rational(0);
    k.free = {2};
  } else {
    k.free = {0, 1, 2};
  }
  return r;
}

TEST(OracleJudge, AnIdentifyClaimBelowTheClassLowerEndIsRefutedByTheClassCertificate) {
  const OracleTask task = identify_task();
  // whole class: any θ; J = 0.0099² … below L_class = 0.01 (d_max = 0.1): refuted with the class certificate
  const Judgement below = judge(task, claims_theta(Rational(99, 1000), {Rational(7), Rational(-3)}), class_reference(false), {});
  EXPECT_EQ(below.verdict, OracleVerdict::kRefuted);
  EXPECT_EQ(below.evidence, "class.json");
  EXPECT_NE(below.reason.find("class lower end"), std::string::npos) << below.reason;
  // at L_class it is not refuted by the class (here: by the fixed θ's lower end 0.04, its own certificate)
  const Judgement at = judge(task, claims_theta(Rational(1, 10), {Rational(7), Rational(-3)}), class_reference(false), {});
  EXPECT_EQ(at.verdict, OracleVerdict::kRefuted);
  EXPECT_EQ(at.evidence, "lower.json");
  // a claim in the fixed θ's interval is confirmed
  EXPECT_EQ(judge(task, claims_theta(Rational(21, 100), {Rational(7), Rational(-3)}), class_reference(false), {}).verdict,
            OracleVerdict::kConfirmed);
}

TEST(OracleJudge, AClassCertificateOverABoxRefutesOnlyTheThetaInsideIt) {
  const OracleTask task = identify_task();
  const ReferenceResult ref = class_reference(true);
  // on the box's corner (exact: |Δ| = radius): inside
  const Judgement inside = judge(task, claims_theta(Rational(99, 1000), {Rational(11, 10), Rational(-199, 100)}), ref, {});
  EXPECT_EQ(inside.verdict, OracleVerdict::kRefuted);
  EXPECT_EQ(inside.evidence, "class.json");
  EXPECT_NE(inside.reason.find("certified box"), std::string::npos) << inside.reason;
  // just outside along the second parameter: the class certificate cannot refute it, and says so;
  // the fixed θ's own lower end still does
  const Judgement outside = judge(task, claims_theta(Rational(99, 1000), {Rational(1), Rational(-2011, 1000)}), ref, {});
  EXPECT_EQ(outside.verdict, OracleVerdict::kRefuted);
  EXPECT_EQ(outside.evidence, "lower.json");
  EXPECT_NE(outside.reason.find("not refutable by the class certificate: theta outside the certified box"), std::string::npos)
      << outside.reason;
  // without the fixed θ's lower end, the same claim is undecided, never refuted
  ReferenceResult no_lower = ref;
  no_lower.lower_verified = false;
  EXPECT_EQ(judge(task, claims_theta(Rational(99, 1000), {Rational(1), Rational(-2011, 1000)}), no_lower, {}).verdict,
            OracleVerdict::kUndecided);
  // the class region never refutes other task kinds
  EXPECT_EQ(judge(min_dmax_task(), claims_theta(Rational(21, 100), {Rational(1), Rational(-2)}), ref, {}).verdict,
            OracleVerdict::kConfirmed);
}

}  // namespace
}  // namespace lpvid
