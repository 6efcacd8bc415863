// llt_inverse (P = F⁻¹ = L⁻ᵀ·L⁻¹ from the Cholesky factor, the structured
// barrier's P): by its meaning, P·F = I to rounding on well- and
// ill-conditioned SPD matrices; P exactly symmetric; the same bits with or
// without a helper thread; and P's lower triangle the Gram matrix XᵀX of
// X = L⁻¹ computed another way (Eigen's own triangular solve and product).
#include <gtest/gtest.h>

#include <random>

#include "core/helper_thread.h"
#include "dense/llt_inverse.h"
#include "support/same_bits.h"

namespace lpvid {
namespace {

using Dense = Eigen::MatrixXd;

/// An SPD matrix Q·diag(λ)·Qᵀ with eigenvalues from 1 down to 1/condition.
Dense spd_with_condition(Eigen::Index n, double condition, std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Dense B(n, n);
  for (Eigen::Index i = 0; i < B.size(); ++i) B.data()[i] = g(rng);
  const Dense Q = Eigen::HouseholderQR<Dense>(B).householderQ();
  Eigen::VectorXd lambda(n);
  for (Eigen::Index k = 0; k < n; ++k)
    lambda(k) = std::pow(condition, -static_cast<double>(k) / static_cast<double>(std::max<Eigen::Index>(n - 1, 1)));
  return Q * lambda.asDiagonal() * Q.transpose();
}

TEST(LltInverse, IsTheInverseSymmetricAndTheSameOnOneThreadOrTwo) {
  std::mt19937_64 rng(41);
  HelperThread helper;
  for (const Eigen::Index n : {1, 2, 5, 63, 64, 67, 255, 256, 257, 513, 1030})
    for (const double condition : {10.0, 1e8}) {
      SCOPED_TRACE(::testing::Message() << "n = " << n << ", condition " << condition);
      const Dense F = spd_with_condition(n, condition, rng);
      const Eigen::LLT<Dense> llt(F);
      ASSERT_EQ(llt.info(), Eigen::Success);
      Dense P = Dense::Constant(3, 3, 7.0), scratch;
      llt_inverse(llt, P, scratch, &helper);
      ASSERT_EQ(P.rows(), n);
      ASSERT_EQ(P.cols(), n);
      EXPECT_TRUE(test::same_bits(P, Dense(P.transpose())));
      // backward error of an inverse: ‖P·F − I‖ ≤ c·n·ε·κ(F)
      const double residual = (P * F - Dense::Identity(n, n)).norm();
      EXPECT_LT(residual, 1e-13 * static_cast<double>(n) * condition);
      Dense alone;
      llt_inverse(llt, alone, scratch, nullptr);
      EXPECT_TRUE(test::same_bits(alone, P));
    }
}

TEST(LltInverse, LowerTriangleIsTheGramOfTheInverseFactor) {
  std::mt19937_64 rng(43);
  for (const Eigen::Index n : {7, 300, 700}) {
    SCOPED_TRACE(::testing::Message() << "n = " << n);
    const Eigen::LLT<Dense> llt(spd_with_condition(n, 100.0, rng));
    Dense X = Dense::Identity(n, n);
    llt.matrixL().solveInPlace(X);
    const Dense gram = X.transpose() * X;
    Dense P, scratch;
    llt_inverse(llt, P, scratch, nullptr);
    EXPECT_LT((P - gram).cwiseAbs().maxCoeff(), 1e-12 * gram.cwiseAbs().maxCoeff());
  }
}

}  // namespace
}  // namespace lpvid
