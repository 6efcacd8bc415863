// toeplitz/tap_norm_barrier.h: the generator form of P = F⁻¹, the gradient and Hessian–vector products of −log det(t·I − T_h T_hᵀ)
// against the dense matrices: P by Eigen's inverse, the gradient and the
// Hessian by the derivative formulas tr(P dF), tr(P dF P dF) − tr(P d²F)
// evaluated densely, and the value's central differences.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "toeplitz/tap_norm_barrier.h"

namespace lpvid {
namespace {

using Vecd = Eigen::VectorXd;
using Dense = Eigen::MatrixXd;

Dense lower_toeplitz(const Vecd& h) {
  const Eigen::Index L = h.size();
  Dense T = Dense::Zero(L, L);
  for (Eigen::Index j = 0; j < L; ++j) T.col(j).tail(L - j) = h.head(L - j);
  return T;
}

Vecd random_vector(Eigen::Index L) {
  Vecd h(L);
  for (Eigen::Index i = 0; i < L; ++i) h(i) = *rc::gen::inRange(-1000, 1001) / 1000.0;
  return h;
}

struct Case {
  Vecd h;
  double t = 1;
  Dense P;
  double kappa = 1;
};

Case draw_case() {
  Case c;
  const Eigen::Index L = *rc::gen::inRange(2, 48);
  c.h = random_vector(L);
  const Dense T = lower_toeplitz(c.h);
  const double norm2 = Eigen::SelfAdjointEigenSolver<Dense>(T * T.transpose()).eigenvalues()(L - 1);
  c.t = norm2 * (1 + std::pow(10.0, -*rc::gen::inRange(0, 6))) + 1e-9;
  c.P = (c.t * Dense::Identity(L, L) - T * T.transpose()).inverse();
  c.kappa = (c.t + norm2) / (c.t - norm2);
  return c;
}

RC_GTEST_PROP(TapNormBarrier, InverseIsTheDenseOne, ()) {
  const Case c = draw_case();
  const Eigen::Index L = c.h.size();
  TapNormBarrier barrier(L);
  RC_ASSERT(barrier.set_point(c.h, c.t));
  const Vecd w = random_vector(L);
  const Vecd Pw = c.P * w;
  RC_ASSERT((barrier.inverse_times(w) - Pw).norm() <= 1e-11 * L * c.kappa * c.kappa * (1 + Pw.norm()));
}

RC_GTEST_PROP(TapNormBarrier, GradientAndHessianAreTheDenseDerivatives, ()) {
  const Case c = draw_case();
  const Eigen::Index L = c.h.size();
  TapNormBarrier barrier(L);
  RC_ASSERT(barrier.set_point(c.h, c.t));
  const Dense T = lower_toeplitz(c.h);
  const Vecd v = random_vector(L);
  const Dense Tv = lower_toeplitz(v);
  const Dense Mv = Tv * T.transpose() + T * Tv.transpose();  // −dF[v]
  const Vecd Hv = barrier.hessian_times(v);
  const double scale = c.P.norm() * c.P.norm() * (1 + T.norm()) * (1 + T.norm()) * L;
  for (Eigen::Index l = 0; l < L; ++l) {
    Vecd e = Vecd::Unit(L, l);
    const Dense El = lower_toeplitz(e);
    const Dense Ml = El * T.transpose() + T * El.transpose();
    const double grad = (c.P * Ml).trace();  // −tr(P dF[e_l])
    RC_ASSERT(std::fabs(barrier.gradient()(l) - grad) <= 1e-11 * c.kappa * scale);
    const double hess = (c.P * Mv * c.P * Ml).trace() + (c.P * (Tv * El.transpose() + El * Tv.transpose())).trace();
    RC_ASSERT(std::fabs(Hv(l) - hess) <= 1e-10 * c.kappa * c.kappa * scale);
  }
}

TEST(TapNormBarrier, ValueIsMinusLogDetAndTheGradientItsDerivative) {
  const Eigen::Index L = 24;
  Vecd h(L);
  for (Eigen::Index i = 0; i < L; ++i) h(i) = 0.3 * std::cos(0.7 * static_cast<double>(i)) / (1.0 + static_cast<double>(i));
  TapNormBarrier barrier(L);
  ASSERT_TRUE(barrier.set_point(h, 1.0));
  const Dense T = lower_toeplitz(h);
  const double ld = Eigen::LLT<Dense>(Dense::Identity(L, L) - T * T.transpose()).matrixLLT().diagonal().array().log().sum() * 2;
  EXPECT_NEAR(barrier.value(), -ld, 1e-12 * L);
  const Vecd g = barrier.gradient();
  for (Eigen::Index l = 0; l < L; l += 5) {
    const double eps = 1e-6;
    TapNormBarrier b2(L);
    Vecd hp = h, hm = h;
    hp(l) += eps;
    hm(l) -= eps;
    ASSERT_TRUE(b2.set_point(hp, 1.0));
    const double fp = b2.value();
    ASSERT_TRUE(b2.set_point(hm, 1.0));
    const double fm = b2.value();
    EXPECT_NEAR(g(l), (fp - fm) / (2 * eps), 1e-6 * (1 + std::fabs(g(l))));
  }
}

}  // namespace
}  // namespace lpvid
