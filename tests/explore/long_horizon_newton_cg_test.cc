// explore/long_horizon_newton_cg.h against independent dense computations:
// with an exact FIR inside the norm ball the optimum is the energy of the
// head rows (known by construction), which must lie between the path's
// lower estimate and the d_max² of its taps, close to both; with the ball
// active the taps are inside it (dense eigenvalues), their d_max² is the
// residual energy recomputed densely, and no point of the ball that we can
// write down (the least-squares FIR scaled into it) is below the lower
// estimate. Bad input is refused.
#include <gtest/gtest.h>

#include <cmath>

#include "explore/long_horizon_newton_cg.h"

namespace lpvid {
namespace {

using Vecd = Eigen::VectorXd;
using Dense = Eigen::MatrixXd;

struct Record {
  Vecd z, r;
  Eigen::Index m = 3;
  Dense Z;  ///< n × L, rows m … n−1 the lower-triangular Toeplitz matrix of z's tail
};

Record record(Eigen::Index n, double gain) {
  Record c;
  c.z = Vecd::Zero(n);
  c.r = Vecd::Zero(n);
  for (Eigen::Index k = c.m; k < n; ++k)
    c.z(k) = std::sin(0.9 * static_cast<double>(k)) + 0.5 * std::cos(2.3 * static_cast<double>(k) + 0.4) +
             0.3 * std::sin(0.17 * static_cast<double>(k * k));
  for (Eigen::Index k = 0; k < n; ++k)
    c.r(k) = (k >= c.m + 2 ? gain * c.z(k - 2) : 0.0) + 0.05 * std::cos(5.0 * static_cast<double>(k) + 1.0);
  const Eigen::Index L = n - c.m;
  c.Z = Dense::Zero(n, L);
  for (Eigen::Index j = 0; j < L; ++j) c.Z.col(j).tail(n - c.m - j) = c.z.segment(c.m, n - c.m - j);
  return c;
}

double toeplitz_norm(const Vecd& h) {
  const Eigen::Index L = h.size();
  Dense T = Dense::Zero(L, L);
  for (Eigen::Index j = 0; j < L; ++j) T.col(j).tail(L - j) = h.head(L - j);
  return std::sqrt(Eigen::SelfAdjointEigenSolver<Dense>(T * T.transpose()).eigenvalues()(L - 1));
}

TEST(LongHorizonNewtonCg, InactiveBallGivesTheHeadRowsEnergy) {
  // r = Z h_true + e with e on the head rows only (z = 0 there): Z is square
  // on the tail and invertible, so min ‖r − Z h‖² = ‖e‖², at h = h_true, which
  // is inside the ball for δ = 2‖T_h_true‖.
  const Eigen::Index n = 120;
  Record c = record(n, 0.0);
  Vecd h_true = Vecd::Zero(n - c.m);
  for (Eigen::Index l = 0; l < h_true.size(); ++l) h_true(l) = 0.3 * std::pow(0.8, static_cast<double>(l)) * std::cos(0.5 * static_cast<double>(l));
  c.r = c.Z * h_true;
  for (Eigen::Index k = 0; k < c.m; ++k) c.r(k) = 0.1 * static_cast<double>(k + 1);
  const double optimum = c.r.head(c.m).squaredNorm() / static_cast<double>(n);
  const LongHorizonAnswer a = solve_long_horizon(c.z, c.r, 2 * toeplitz_norm(h_true));
  EXPECT_TRUE(a.converged) << a.message;
  EXPECT_TRUE(a.inside);
  EXPECT_LE(a.lower_estimate, optimum * (1 + 1e-12));
  EXPECT_GE(a.dmax2, optimum * (1 - 1e-12));
  EXPECT_LE(a.dmax2, optimum * (1 + 1e-3));
}

TEST(LongHorizonNewtonCg, ActiveBallTapsInsideAndNothingKnownBelowTheLowerEstimate) {
  const Eigen::Index n = 80;
  const Record c = record(n, 0.6);
  const double delta = 0.3;
  const LongHorizonAnswer a = solve_long_horizon(c.z, c.r, delta);
  ASSERT_EQ(a.horizon, n - c.m);
  EXPECT_TRUE(a.converged) << a.message;
  EXPECT_TRUE(a.inside);
  EXPECT_LT(toeplitz_norm(a.taps), delta);
  const double dmax2 = (c.r - c.Z * a.taps).squaredNorm() / static_cast<double>(n);
  EXPECT_NEAR(a.dmax2, dmax2, 1e-12 + 1e-9 * dmax2);
  EXPECT_LT(a.dmax2, 0.5 * c.r.squaredNorm() / static_cast<double>(n));  // the delay is partly fitted
  EXPECT_LE(a.lower_estimate, a.dmax2);
  const Vecd h_ls = c.Z.colPivHouseholderQr().solve(c.r);
  const Vecd inside = h_ls * (0.999 * delta / toeplitz_norm(h_ls));
  EXPECT_LE(a.lower_estimate, (c.r - c.Z * inside).squaredNorm() / static_cast<double>(n));
}

TEST(LongHorizonNewtonCg, RefusesBadInput) {
  const Vecd z = Vecd::Ones(5), r = Vecd::Ones(4);
  EXPECT_THROW(solve_long_horizon(z, r, 0.5), std::invalid_argument);
  EXPECT_THROW(solve_long_horizon(z, z, 0.0), std::invalid_argument);
  Vecd bad = z;
  bad(2) = NAN;
  EXPECT_THROW(solve_long_horizon(bad, z, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace lpvid
