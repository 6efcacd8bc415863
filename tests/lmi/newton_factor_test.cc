// The Newton system's factorisation (lmi/newton_factor.h): Cholesky where H
// is numerically positive definite, the pivoted LDLᵀ where a Cholesky pivot
// is not positive or where the caller asks for it; the solve against H·x = b.
#include <gtest/gtest.h>

#include <random>

#include <Eigen/Dense>

#include "lmi/newton_factor.h"

namespace lpvid {
namespace {

using Dense = Eigen::MatrixXd;
using Vec = Eigen::VectorXd;

Dense random_gram(Eigen::Index n, Eigen::Index rank, std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Dense B(rank, n);
  for (Eigen::Index i = 0; i < B.size(); ++i) B.data()[i] = g(rng);
  return B.transpose() * B;
}

TEST(NewtonFactor, APositiveDefiniteSystemIsSolvedByCholesky) {
  std::mt19937_64 rng(51);
  const Dense H = random_gram(60, 80, rng) + Dense::Identity(60, 60);
  const Vec x = Vec::LinSpaced(60, -1.0, 2.0);
  NewtonFactor f;
  f.compute(H, nullptr);
  ASSERT_TRUE(f.positive());
  EXPECT_FALSE(f.pivoted());
  EXPECT_LT((f.solve(H * x) - x).norm(), 1e-10 * x.norm());
  f.compute(H, nullptr, true);  // asked for: the pivoted LDLᵀ, the same solution
  ASSERT_TRUE(f.positive());
  EXPECT_TRUE(f.pivoted());
  EXPECT_LT((f.solve(H * x) - x).norm(), 1e-10 * x.norm());
}

TEST(NewtonFactor, AnIndefiniteSystemIsNotPositiveEitherWay) {
  std::mt19937_64 rng(53);
  Dense H = random_gram(40, 60, rng);
  H(17, 17) = -1.0;
  NewtonFactor f;
  f.compute(H, nullptr);
  EXPECT_TRUE(f.pivoted());  // the Cholesky pivot at 17 was not positive
  EXPECT_FALSE(f.positive());
}

TEST(NewtonFactor, ASingularSemidefiniteSystemFallsBackToThePivotedFactor) {
  std::mt19937_64 rng(57);
  const Dense H = random_gram(30, 10, rng);  // rank 10: Cholesky meets a zero (or negative) pivot
  NewtonFactor f;
  f.compute(H, nullptr);
  EXPECT_TRUE(f.pivoted());
  Eigen::LDLT<Dense> ldlt(H);
  EXPECT_EQ(f.positive(), ldlt.info() == Eigen::Success && ldlt.isPositive());
  f.release();
  EXPECT_FALSE(f.pivoted());
}

}  // namespace
}  // namespace lpvid
