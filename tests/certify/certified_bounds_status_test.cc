// CertifiedBounds keeps one status, its outcome: verified() and invalidated()
// are read from it, and before any certificate passed it is undecided (a
// default "not verified" would read like the answer of a failed check).
#include <gtest/gtest.h>

#include <string>

#include "certify/certify.h"

namespace lpvid {
namespace {

TEST(CertifiedBoundsStatus, DefaultIsUndecidedNeitherVerifiedNorInvalidated) {
  const CertifiedBounds b;
  EXPECT_EQ(b.outcome, CertifyOutcome::kUndecided);
  EXPECT_FALSE(b.verified());
  EXPECT_FALSE(b.invalidated());
  EXPECT_EQ(std::string(to_string(b.outcome)), "undecided");
}

TEST(CertifiedBoundsStatus, AccessorsFollowTheOutcome) {
  CertifiedBounds b;
  b.outcome = CertifyOutcome::kVerified;
  EXPECT_TRUE(b.verified());
  EXPECT_FALSE(b.invalidated());
  b.outcome = CertifyOutcome::kInvalidated;
  EXPECT_FALSE(b.verified());
  EXPECT_TRUE(b.invalidated());
  for (CertifyOutcome o : {CertifyOutcome::kUndecided, CertifyOutcome::kSolverFailed, CertifyOutcome::kNotVerified}) {
    b.outcome = o;
    EXPECT_FALSE(b.verified()) << to_string(o);
    EXPECT_FALSE(b.invalidated()) << to_string(o);
  }
}

// outcome_of keeps a passed certificate and decides the rest from the
// objective and the solve (fixed bounds: undecided; a failed backend: solver
// failed; otherwise not verified).
TEST(CertifiedBoundsStatus, OutcomeOfDecidesOnlyWhatNoCertificateDecided) {
  BoundObjective feasibility;
  feasibility.kind = BoundObjective::Kind::kFeasibility;
  BoundObjective minimise;
  minimise.kind = BoundObjective::Kind::kMinDmax;
  CertifiedBounds b;
  EXPECT_EQ(outcome_of(b, feasibility), CertifyOutcome::kUndecided);
  EXPECT_EQ(outcome_of(b, minimise), CertifyOutcome::kNotVerified);
  b.solve_status = SolveStatus::kIterationLimit;
  EXPECT_EQ(outcome_of(b, minimise), CertifyOutcome::kSolverFailed);
  b.outcome = CertifyOutcome::kVerified;
  EXPECT_EQ(outcome_of(b, minimise), CertifyOutcome::kVerified);
  b.outcome = CertifyOutcome::kInvalidated;
  EXPECT_EQ(outcome_of(b, feasibility), CertifyOutcome::kInvalidated);
}

}  // namespace
}  // namespace lpvid
