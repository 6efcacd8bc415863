// explore/long_horizon_dual.h and the final centering of
// explore/long_horizon_newton_cg.h against dense computations that share no
// code with them:
//  - U = μ·(t·I − T_h T_hᵀ)⁻¹ by a dense inverse, K(U)_ij = Σ_a U(a+i, a+j)
//    (so that ⟨U, T_h T_hᵀ⟩ = hᵀK h), and the Lagrangian lower bound
//      θ(U) = −t·tr U + min_h ‖r − Z h‖²/N + hᵀK h
//    by a dense solve. At an exactly centred point h minimises the
//    Lagrangian, so q(h) − θ(U) = ⟨U, t·I − T_hT_hᵀ⟩ = μ·L exactly; weak
//    duality gives θ(U) ≤ q(h) at any point;
//  - the dual equality's residual Zᵀg + Ω(U T_h) with Z and Ω written out.
#include <gtest/gtest.h>

#include <cmath>

#include "explore/long_horizon_dual.h"
#include "explore/long_horizon_newton_cg.h"

namespace lpvid {
namespace {

using Vecd = Eigen::VectorXd;
using Dense = Eigen::MatrixXd;

/// z (nonzero from sample 0), r = 0.9·z delayed by 2 + a cosine: with δ = 0.5 the ball is active.
void record(Eigen::Index n, Vecd* z, Vecd* r) {
  *z = Vecd(n);
  *r = Vecd(n);
  for (Eigen::Index k = 0; k < n; ++k)
    (*z)(k) = std::sin(0.9 * static_cast<double>(k) + 0.3) + 0.5 * std::cos(2.3 * static_cast<double>(k) + 0.4);
  for (Eigen::Index k = 0; k < n; ++k)
    (*r)(k) = (k >= 2 ? 0.9 * (*z)(k - 2) : 0.0) + 0.05 * std::cos(5.0 * static_cast<double>(k) + 1.0);
}

Dense lower_toeplitz(const Vecd& v, Eigen::Index rows, Eigen::Index cols) {
  Dense T = Dense::Zero(rows, cols);
  for (Eigen::Index i = 0; i < rows; ++i)
    for (Eigen::Index j = 0; j <= i && j < cols; ++j) T(i, j) = v(i - j);
  return T;
}

struct DenseDual {
  double gap_minus_muL = 0;  ///< q(h) − θ(U) − μL
  double theta = 0;
  double residual = 0;       ///< ‖Zᵀg + Ω(U T_h)‖ / ‖Ω(U T_h)‖
};

DenseDual dense_dual(const Vecd& z, const Vecd& r, const Vecd& h, double t, double mu, const Vecd& g) {
  const Eigen::Index n = z.size(), L = h.size();
  const double N = static_cast<double>(n);
  const Dense Z = lower_toeplitz(z, n, L), T = lower_toeplitz(h, L, L);
  const Dense U = mu * (t * Dense::Identity(L, L) - T * T.transpose()).inverse();
  Dense K = Dense::Zero(L, L);
  for (Eigen::Index i = 0; i < L; ++i)
    for (Eigen::Index j = 0; j < L; ++j)
      for (Eigen::Index a = 0; a + std::max(i, j) < L; ++a) K(i, j) += U(a + i, a + j);
  const Dense Q = Z.transpose() * Z / N + K;
  const Vecd b = Z.transpose() * r / N;
  DenseDual d;
  d.theta = -t * U.trace() + r.squaredNorm() / N - b.dot(Q.llt().solve(b));
  const double q = (r - Z * h).squaredNorm() / N;
  d.gap_minus_muL = q - d.theta - mu * static_cast<double>(L);
  const Dense UT = U * T;
  Vecd omega = Vecd::Zero(L);
  for (Eigen::Index l = 0; l < L; ++l)
    for (Eigen::Index b2 = 0; b2 + l < L; ++b2) omega(l) += UT(b2 + l, b2);
  d.residual = (Z.transpose() * g + omega).norm() / omega.norm();
  return d;
}

TEST(LongHorizonDual, FinalCentringMakesTheDualPointExact) {
  const Eigen::Index n = 90;
  const double delta = 0.5;
  Vecd z, r;
  record(n, &z, &r);
  LongHorizonOptions o;
  o.final_centering = 40;
  o.final_dense = true;
  const LongHorizonAnswer a = solve_long_horizon(z, r, delta, o);
  ASSERT_TRUE(a.converged) << a.message;
  ASSERT_EQ(a.horizon, n);
  EXPECT_LT(a.final_decrement2, 1e-12);
  const LongHorizonDualSignal s = long_horizon_dual_signal(z, r, a.taps, delta * delta, a.mu);
  ASSERT_TRUE(s.ok);
  const DenseDual d = dense_dual(z, r, a.taps, delta * delta, a.mu, s.g);
  const double muL = a.mu * static_cast<double>(n);
  EXPECT_LT(std::fabs(d.gap_minus_muL), 1e-6 * muL) << "q - theta - mu L = " << d.gap_minus_muL << ", mu L = " << muL;
  EXPECT_LE(d.theta, a.dmax2);  // weak duality
  EXPECT_LT(d.residual, 1e-6);
  EXPECT_NEAR(s.relative_residual, d.residual, 1e-6);
}

TEST(LongHorizonDual, RefusesPointsOutsideTheBall) {
  Vecd z, r;
  record(20, &z, &r);
  EXPECT_FALSE(long_horizon_dual_signal(z, r, Vecd::Constant(20, 1.0), 0.25, 1e-3).ok);  // ‖T_h‖ ≥ 1 > 0.5
  EXPECT_FALSE(long_horizon_dual_signal(z, r, Vecd::Zero(21), 0.25, 1e-3).ok);          // L > n
  EXPECT_FALSE(long_horizon_dual_signal(z, r, Vecd::Zero(20), 0.25, 0.0).ok);           // μ = 0
}

}  // namespace
}  // namespace lpvid
