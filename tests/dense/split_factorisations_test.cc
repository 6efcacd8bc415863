// SplitLdlt (the LDLᵀ of the structured barrier's Newton system, its column
// updates shared with a helper thread) against Eigen::LDLT::compute itself:
// every factor entry, pivot and solve bit for bit, with and without a helper;
// the forward solve L⁻¹·I that skips the identity's zeros against Eigen's.
#include <gtest/gtest.h>

#include <random>

#include "core/helper_thread.h"
#include "dense/identity_forward_solve.h"
#include "dense/split_factorisations.h"
#include "support/random_dense.h"
#include "support/same_bits.h"

namespace lpvid {
namespace {

using Dense = Eigen::MatrixXd;

/// kind 0: SPD (BᵀB/n + I); 1: symmetric indefinite; 2: SPD with a zero row and column (singular);
/// 3: symmetric indefinite with tied diagonal entries (±1, 2, the pivot order decided by position).
Dense random_symmetric(Eigen::Index n, int kind, std::mt19937_64& rng) {
  const Dense B = test::random_uniform(n, n, rng);
  Dense A = kind == 1 ? Dense(B + B.transpose()) : Dense(B.transpose() * B / static_cast<double>(n) + Dense::Identity(n, n));
  if (kind == 3)
    for (Eigen::Index k = 0; k < n; ++k) A(k, k) = k % 3 == 0 ? 2.0 : k % 3 == 1 ? -1.0 : 1.0;
  if (kind == 2 && n > 2) {
    A.row(n / 2).setZero();
    A.col(n / 2).setZero();
  }
  return A;
}

void expect_identical(const Dense& A, HelperThread* helper) {
  Eigen::LDLT<Dense> eigen(A);
  SplitLdlt split;
  split.compute_split(A, helper);
  ASSERT_EQ(split.info(), eigen.info());
  EXPECT_TRUE(test::same_bits(split.matrixLDLT(), eigen.matrixLDLT()));
  EXPECT_EQ(split.isPositive(), eigen.isPositive());
  EXPECT_EQ(split.isNegative(), eigen.isNegative());
  for (Eigen::Index k = 0; k < A.rows(); ++k) EXPECT_EQ(split.transpositionsP().indices()(k), eigen.transpositionsP().indices()(k));
  const Dense rhs = Dense::Ones(A.rows(), 2);
  EXPECT_TRUE(test::same_bits(split.solve(rhs), eigen.solve(rhs)));
}

TEST(SplitLdlt, BitForBitEigensFactorisationWithAndWithoutAHelper) {
  std::mt19937_64 rng(7);
  HelperThread helper;
  for (const Eigen::Index n : {0, 1, 2, 3, 17, 64, 65, 129, 255, 256, 257, 300, 513, 1000})
    for (int kind = 0; kind < 4; ++kind) {
      SCOPED_TRACE(::testing::Message() << "n = " << n << ", kind " << kind);
      const Dense A = random_symmetric(n, kind, rng);
      expect_identical(A, nullptr);
      expect_identical(A, &helper);
    }
}

TEST(SplitLdlt, TheZeroMatrixIsReportedAsEigenDoes) {
  HelperThread helper;
  expect_identical(Dense::Zero(200, 200), &helper);
  expect_identical(Dense::Zero(300, 300), &helper);
}

// The panels start at column 128 and end two columns before the last; sizes
// around those edges, and a zero pivot met inside a panel.
TEST(SplitLdlt, PanelEdgesAndAZeroPivotInsideAPanel) {
  std::mt19937_64 rng(19);
  HelperThread helper;
  for (const Eigen::Index n : {258, 259, 270, 271, 272, 273, 290}) {
    SCOPED_TRACE(::testing::Message() << "n = " << n);
    const Dense A = random_symmetric(n, 1, rng);
    expect_identical(A, &helper);
    expect_identical(A, nullptr);
  }
  Dense S = random_symmetric(400, 0, rng);  // rank-deficient: S = B Bᵀ with B 400 × 150
  Dense B = S.leftCols(150);
  S = B * B.transpose();
  expect_identical(S, &helper);
  expect_identical(S, nullptr);
}

TEST(IdentityForwardSolve, BitForBitEigensSolveOnEveryColumnRange) {
  if (!identity_forward_solve_available()) GTEST_SKIP() << "a build with fused multiply-adds uses Eigen's solve itself";
  std::mt19937_64 rng(11);
  for (const Eigen::Index n : {1, 2, 3, 4, 5, 63, 64, 65, 66, 67, 130, 257, 400, 601, 1000, 1283}) {
    SCOPED_TRACE(::testing::Message() << "n = " << n);
    const Eigen::LLT<Dense> llt(random_symmetric(n, 0, rng));
    Dense whole = Dense::Identity(n, n);
    llt.matrixL().solveInPlace(whole);
    for (const Eigen::Index c0 : {Eigen::Index{0}, n / 4 * 2, n - 1}) {
      Dense X = Dense::Constant(n, n, 7.0);
      identity_forward_solve(llt.matrixLLT(), c0, X.middleCols(c0, n - c0));
      EXPECT_TRUE(test::same_bits(X.rightCols(n - c0), whole.rightCols(n - c0))) << "from column " << c0;
    }
  }
}

}  // namespace
}  // namespace lpvid
