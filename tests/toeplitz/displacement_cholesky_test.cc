// toeplitz/displacement_cholesky.h: the generalised Schur algorithm against
// the dense F = t·I − T_h T_hᵀ built entry by entry and Eigen's Cholesky.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "toeplitz/displacement_cholesky.h"

namespace lpvid {
namespace {

Eigen::MatrixXd dense_gram(const Eigen::VectorXd& h, double t) {
  const Eigen::Index L = h.size();
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(L, L);
  for (Eigen::Index j = 0; j < L; ++j) T.col(j).tail(L - j) = h.head(L - j);
  return t * Eigen::MatrixXd::Identity(L, L) - T * T.transpose();
}

Eigen::VectorXd random_taps(Eigen::Index L) {
  Eigen::VectorXd h(L);
  for (Eigen::Index i = 0; i < L; ++i) h(i) = *rc::gen::inRange(-1000, 1001) / 1000.0;
  return h;
}

RC_GTEST_PROP(DisplacementCholesky, FactorLogDetAndSolveAreTheDenseOnes, ()) {
  const Eigen::Index L = *rc::gen::inRange(1, 40);
  Eigen::VectorXd h = random_taps(L);
  const Eigen::MatrixXd G0 = dense_gram(h, 0.0);
  const double norm2 = -Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(G0).eigenvalues()(0);  // ‖T_h‖²
  // t above ‖T_h‖² by a drawn factor: well inside down to nearly singular.
  const double t = norm2 * (1 + std::pow(10.0, -*rc::gen::inRange(0, 9))) + 1e-12;
  const Eigen::MatrixXd F = dense_gram(h, t);
  DisplacementCholesky chol;
  RC_ASSERT(chol.factor(h, t, true));
  const Eigen::MatrixXd Lf = chol.dense_factor();
  const double scale = t + norm2;
  RC_ASSERT((Lf * Lf.transpose() - F).cwiseAbs().maxCoeff() <= 1e-12 * L * scale);
  Eigen::LLT<Eigen::MatrixXd> llt(F);
  double ld = 0;
  for (Eigen::Index i = 0; i < L; ++i) ld += 2 * std::log(llt.matrixL()(i, i));
  double ld_alone = 0;
  RC_ASSERT(displacement_log_det(h, t, &ld_alone));
  RC_ASSERT(ld_alone == chol.log_det());
  const double kappa = scale / (t - norm2);
  RC_ASSERT(std::fabs(chol.log_det() - ld) <= 1e-12 * L * kappa * (1 + std::fabs(ld)));
  const Eigen::VectorXd b = random_taps(L);
  const Eigen::VectorXd x = chol.solve(b);
  RC_ASSERT((F * x - b).norm() <= 1e-11 * L * kappa * (1 + b.norm()));
}

RC_GTEST_PROP(DisplacementCholesky, OutsideTheNormBallIsNotInterior, ()) {
  const Eigen::Index L = *rc::gen::inRange(1, 30);
  const Eigen::VectorXd h = random_taps(L);
  const double norm2 = -Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense_gram(h, 0.0)).eigenvalues()(0);
  RC_PRE(norm2 > 1e-6);
  const double t = norm2 * (1 - std::pow(10.0, -*rc::gen::inRange(1, 6)));  // below ‖T_h‖²
  double ld = 0;
  RC_ASSERT(!displacement_log_det(h, t, &ld));
  DisplacementCholesky chol;
  RC_ASSERT(!chol.factor(h, t, true));
}

RC_GTEST_PROP(DisplacementCholesky, NormByBisectionIsTheLargestEigenvalueFromAbove, ()) {
  const Eigen::Index L = *rc::gen::inRange(1, 40);
  const Eigen::VectorXd h = random_taps(L);
  const double norm2 = -Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense_gram(h, 0.0)).eigenvalues()(0);
  const double bisected = lower_toeplitz_norm2(h);
  RC_ASSERT(bisected >= norm2 * (1 - 1e-13));
  RC_ASSERT(bisected <= norm2 * (1 + 1e-9) + 1e-300);
}

}  // namespace
}  // namespace lpvid
