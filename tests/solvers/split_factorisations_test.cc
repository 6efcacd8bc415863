// SplitLdlt (the LDLᵀ of the structured barrier's Newton system, its column
// updates shared with a helper thread) against Eigen::LDLT::compute itself:
// every factor entry, pivot and solve bit for bit, with and without a helper.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "core/helper_thread.h"
#include "lmi/split_factorisations.h"

namespace lpvid {
namespace {

using Dense = Eigen::MatrixXd;

bool same_bits(const Dense& a, const Dense& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         (a.size() == 0 || std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<size_t>(a.size())) == 0);
}

/// kind 0: SPD (BᵀB/n + I); 1: symmetric indefinite; 2: SPD with a zero row and column (singular).
Dense random_symmetric(Eigen::Index n, int kind, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Dense B(n, n);
  for (Eigen::Index i = 0; i < B.size(); ++i) B.data()[i] = u(rng);
  Dense A = kind == 1 ? Dense(B + B.transpose()) : Dense(B.transpose() * B / static_cast<double>(n) + Dense::Identity(n, n));
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
  EXPECT_TRUE(same_bits(split.matrixLDLT(), eigen.matrixLDLT()));
  EXPECT_EQ(split.isPositive(), eigen.isPositive());
  EXPECT_EQ(split.isNegative(), eigen.isNegative());
  for (Eigen::Index k = 0; k < A.rows(); ++k) EXPECT_EQ(split.transpositionsP().indices()(k), eigen.transpositionsP().indices()(k));
  const Dense rhs = Dense::Ones(A.rows(), 2);
  EXPECT_TRUE(same_bits(split.solve(rhs), eigen.solve(rhs)));
}

TEST(SplitLdlt, BitForBitEigensFactorisationWithAndWithoutAHelper) {
  std::mt19937_64 rng(7);
  HelperThread helper;
  for (const Eigen::Index n : {0, 1, 2, 3, 17, 64, 65, 129, 300, 513})
    for (int kind = 0; kind < 3; ++kind) {
      SCOPED_TRACE(::testing::Message() << "n = " << n << ", kind " << kind);
      const Dense A = random_symmetric(n, kind, rng);
      expect_identical(A, nullptr);
      expect_identical(A, &helper);
    }
}

TEST(SplitLdlt, TheZeroMatrixIsReportedAsEigenDoes) {
  HelperThread helper;
  expect_identical(Dense::Zero(200, 200), &helper);
}

TEST(LltInverseSplit, BitForBitTheWholeSolve) {
  std::mt19937_64 rng(11);
  HelperThread helper;
  for (const Eigen::Index n : {1, 5, 63, 64, 65, 66, 67, 130, 257, 400, 601}) {
    SCOPED_TRACE(::testing::Message() << "n = " << n);
    const Eigen::LLT<Dense> llt(random_symmetric(n, 0, rng));
    const Dense whole = llt.solve(Dense::Identity(n, n));
    Dense P = Dense::Constant(3, 3, 7.0);  // resized
    llt_inverse_split(llt, P, &helper);
    EXPECT_TRUE(same_bits(P, whole));
    llt_inverse_split(llt, P, nullptr);
    EXPECT_TRUE(same_bits(P, whole));
  }
}

}  // namespace
}  // namespace lpvid
