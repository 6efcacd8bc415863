// SplitLlt (the Cholesky factor of the structured barrier's LMI matrix, its
// triangular solves and rank updates shared with a helper thread) against
// Eigen::LLT::compute itself: every factor entry and solve bit for bit.
#include <gtest/gtest.h>

#include <random>

#include "core/helper_thread.h"
#include "dense/split_llt.h"
#include "support/random_dense.h"
#include "support/same_bits.h"

namespace lpvid {
namespace {

using Dense = Eigen::MatrixXd;

/// SPD (BᵀB/n + I), or with `shift` subtracted from the diagonal (not positive definite for a large shift).
Dense random_spd(Eigen::Index n, double shift, std::mt19937_64& rng) {
  Dense A = test::random_spd(n, rng);
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

// lower_rank_update against Eigen's selfadjointView<Lower>().rankUpdate on
// blocks of a larger matrix (its outer stride), every remainder of the size
// modulo 4, depths around the kernels' steps, one thread or two; the upper
// triangle is left as it was.
TEST(SplitLlt, LowerRankUpdateIsEigensRankUpdateBitForBit) {
  std::mt19937_64 rng(31);
  HelperThread helper;
  for (const Eigen::Index size : {1, 4, 7, 130, 257, 1030})
    for (const Eigen::Index depth : {1, 3, 64, 256, 801}) {
      SCOPED_TRACE(::testing::Message() << "size = " << size << ", depth = " << depth);
      const Dense base = test::random_uniform(size + 3, size + depth + 2, rng);
      Dense eigen = base, one = base, two = base;
      const auto update = [&](Dense& m, HelperThread* h) {
        Eigen::Block<Dense> A22(m, 1, 2, size, size);
        const Eigen::Block<Dense> A21(m, 2, size + 2, size, depth);
        lower_rank_update(A22, A21, h);
      };
      Eigen::Block<Dense>(eigen, 1, 2, size, size).selfadjointView<Eigen::Lower>().rankUpdate(
          Eigen::Block<Dense>(eigen, 2, size + 2, size, depth), -1.0);
      update(one, nullptr);
      update(two, &helper);
      EXPECT_TRUE(test::same_bits(one, eigen));
      EXPECT_TRUE(test::same_bits(two, eigen));
    }
}

}  // namespace
}  // namespace lpvid
