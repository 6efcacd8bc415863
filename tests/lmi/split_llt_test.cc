// SplitLlt (the Cholesky factor of the structured barrier's LMI matrix, its
// triangular solves and rank updates shared with a helper thread) against
// Eigen::LLT::compute itself: every factor entry and solve bit for bit.
#include <gtest/gtest.h>

#include <random>

#include "core/helper_thread.h"
#include "lmi/split_llt.h"
#include "support/same_bits.h"

namespace lpvid {
namespace {

using Dense = Eigen::MatrixXd;

/// SPD (BᵀB/n + I), or with `shift` subtracted from the diagonal (not positive definite for a large shift).
Dense random_spd(Eigen::Index n, double shift, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Dense B(n, n);
  for (Eigen::Index i = 0; i < B.size(); ++i) B.data()[i] = u(rng);
  Dense A = B.transpose() * B / static_cast<double>(n) + Dense::Identity(n, n);
  A.diagonal().array() -= shift;
  return A;
}

void expect_llt_identical(const Dense& A, HelperThread* helper) {
  const Eigen::LLT<Dense> eigen(A);
  SplitLlt split;
  split.compute_split(A, helper);
  ASSERT_EQ(split.info(), eigen.info());
  EXPECT_TRUE(test::same_bits(split.matrixLLT(), eigen.matrixLLT()));
  EXPECT_EQ(split.rcond(), eigen.rcond());
  if (eigen.info() == Eigen::Success) {
    const Dense rhs = Dense::Ones(A.rows(), 3);
    EXPECT_TRUE(test::same_bits(split.solve(rhs), eigen.solve(rhs)));
  }
}

// Shared out from 1 024 rows on (one thread below): sizes around it, every
// remainder modulo 4.
TEST(SplitLlt, BitForBitEigensFactorWithAndWithoutAHelper) {
  std::mt19937_64 rng(23);
  HelperThread helper;
  for (const Eigen::Index n : {0, 1, 2, 31, 32, 33, 100, 257, 300, 513, 1023, 1024, 1025, 1026, 1027, 1203}) {
    SCOPED_TRACE(::testing::Message() << "n = " << n);
    const Dense A = random_spd(n, 0.0, rng);
    expect_llt_identical(A, &helper);
    expect_llt_identical(A, nullptr);
  }
}

// A matrix that is not positive definite: the factorisation stops at the
// same column as Eigen's, with the same partial factor in memory.
TEST(SplitLlt, AFailureStopsWhereEigensDoes) {
  std::mt19937_64 rng(29);
  HelperThread helper;
  for (const Eigen::Index n : {40, 301, 1100}) {
    SCOPED_TRACE(::testing::Message() << "n = " << n);
    Dense A = random_spd(n, 0.0, rng);
    A(n - 5, n - 5) = -1.0;  // fails late, after the shared statements ran
    expect_llt_identical(A, &helper);
    expect_llt_identical(random_spd(n, 1.5, rng), &helper);
  }
}

}  // namespace
}  // namespace lpvid
