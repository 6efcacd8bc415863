// The rigid-body analogue of the paper's Example 2 (examples/rigid_body_3x3.h)
// checked from outside: equilibria by Newton's method on the step map, the
// analytic linearisation against finite differences, the closed loop's
// stability over the range, and the part-1 ARX fit (fit/mimo_arx.h,
// fit/local_lpv.h) against the exact ARX form of the linearisation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

#include "examples/rigid_body_3x3.h"
#include "fit/local_lpv.h"

namespace lpvid {
namespace {

/// Central finite-difference Jacobian of the step map x ↦ step(x, r) (6 × 6).
Mat<double> step_jacobian(const Vec<double>& x, const Vec<double>& r, double eps = 1e-6) {
  Mat<double> j(6, 6);
  for (int c = 0; c < 6; ++c) {
    Vec<double> xp = x, xm = x;
    xp(c) += eps;
    xm(c) -= eps;
    j.col(c) = (rigid_body_step(xp, r) - rigid_body_step(xm, r)) / (2 * eps);
  }
  return j;
}

/// The equilibrium x* = step(x*, r) by Newton's method from the origin.
Vec<double> equilibrium(const Vec<double>& r) {
  Vec<double> x = Vec<double>::Zero(6);
  for (int it = 0; it < 50; ++it) {
    const Vec<double> f = rigid_body_step(x, r) - x;
    if (f.norm() < 1e-14) break;
    x -= (step_jacobian(x, r) - Mat<double>::Identity(6, 6)).fullPivLu().solve(f);
  }
  return x;
}

Vec<double> vec3(double a, double b, double c) {
  Vec<double> v(3);
  v << a, b, c;
  return v;
}

bool is_integer(const Rational& q) { return q.denominator() == 1; }

double spectral_radius(const Mat<double>& a) {
  return Eigen::EigenSolver<Mat<double>>(a).eigenvalues().cwiseAbs().maxCoeff();
}

TEST(RigidBody3x3, ClosedLoopIsStableAndSettlesAtTheNewtonEquilibrium) {
  const Mat<double> points = rigid_body_corner_points();
  for (Eigen::Index p = 0; p < points.rows(); ++p) {
    const Vec<double> r = points.row(p).transpose();
    const Vec<double> x = equilibrium(r);
    ASSERT_LT((rigid_body_step(x, r) - x).norm(), 1e-12) << "Newton failed at point " << p;
    EXPECT_LT(x.tail(3).norm(), 1e-12);  // at rest
    EXPECT_LT(spectral_radius(step_jacobian(x, r)), 0.95) << "point " << p;
    // The simulation from the origin under a constant reference settles there.
    const Mat<double> theta = rigid_body_simulate(r.transpose().replicate(400, 1), Vec<double>::Zero(6));
    EXPECT_LT((theta.bottomRows(1).transpose() - x.head(3)).norm(), 1e-9) << "point " << p;
  }
}

TEST(RigidBody3x3, StaticGainIsNonlinear) {
  // Φ(r) at the corners is not an affine function of r: the midpoint rule fails.
  const Vec<double> a = vec3(0.4, 0.4, 0.4), b = -a;
  const Vec<double> mid = equilibrium(Vec<double>::Zero(3)).head(3);
  const Vec<double> ends = 0.5 * (equilibrium(a).head(3) + equilibrium(b).head(3));
  EXPECT_GT((ends - mid).norm(), 1e-2);
  // The origin is an equilibrium with θ* = 0 (the feed-forward is linear).
  EXPECT_LT(mid.norm(), 1e-12);
}

TEST(RigidBody3x3, LinearisationMatchesFiniteDifferences) {
  const Vec<double> r = vec3(0.3, -0.2, 0.35);
  const Vec<double> x = equilibrium(r);
  const RigidBodyJacobians j = rigid_body_linearisation(x.head(3), r);
  const Mat<double> fd = step_jacobian(x, r);
  const double h = kRigidBodyStep;
  // ω update: ω + h·f(θ, ω, r), so its Jacobian rows are h·J_θ and I + h·J_ω.
  EXPECT_LT((fd.block(3, 0, 3, 3) - h * j.theta).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LT((fd.block(3, 3, 3, 3) - Mat<double>::Identity(3, 3) - h * j.omega).cwiseAbs().maxCoeff(), 1e-8);
  Mat<double> fd_ref(6, 3);
  for (int c = 0; c < 3; ++c) {
    Vec<double> rp = r, rm = r;
    rp(c) += 1e-6;
    rm(c) -= 1e-6;
    fd_ref.col(c) = (rigid_body_step(x, rp) - rigid_body_step(x, rm)) / 2e-6;
  }
  EXPECT_LT(fd_ref.topRows(3).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((fd_ref.bottomRows(3) - h * j.ref).cwiseAbs().maxCoeff(), 1e-8);
}

TEST(RigidBody3x3, ArxFitOnNoiseFreePartOneRecoversTheLinearisation) {
  RigidBodyOptions o;
  o.noise_variance = 0;
  o.pulse_amplitude = 0.002;  // small signal: the nonlinearity's effect is O(amplitude)
  o.ramps = 1;
  o.n = 10;
  const Experiment<double> e = nearest_double(rigid_body_experiment(o).local);
  const auto points = fit_operating_points(e, 2, o.settle);
  ASSERT_EQ(points.size(), 9u);
  const double h = kRigidBodyStep;
  const Mat<double> eye = Mat<double>::Identity(3, 3);
  for (const OperatingPointFit& p : points) {
    const Vec<double> x = equilibrium(p.rho);
    const RigidBodyJacobians j = rigid_body_linearisation(x.head(3), p.rho);
    // θ̂_{k} = (2I + hJ_ω) θ̂_{k−1} − (I + hJ_ω − h²J_θ) θ̂_{k−2} + h² J_r û_{k−2}
    const Mat<double> p1 = 2 * eye + h * j.omega, p2 = -(eye + h * j.omega - h * h * j.theta);
    const Mat<double> q2 = h * h * j.ref;
    EXPECT_LT((p.arx.P[0] - p1).cwiseAbs().maxCoeff(), 1e-3) << p.rho.transpose();
    EXPECT_LT((p.arx.P[1] - p2).cwiseAbs().maxCoeff(), 1e-3) << p.rho.transpose();
    EXPECT_LT(p.arx.Q[0].cwiseAbs().maxCoeff(), 1e-3 * q2.cwiseAbs().maxCoeff() + 1e-6) << p.rho.transpose();
    EXPECT_LT((p.arx.Q[1] - q2).cwiseAbs().maxCoeff(), 1e-2 * q2.cwiseAbs().maxCoeff()) << p.rho.transpose();
    // The constant makes the fit's equilibrium the true one: (I − P1 − P2)⁻¹ c = θ*.
    const Vec<double> theta_eq = (eye - p.arx.P[0] - p.arx.P[1]).lu().solve(p.arx.c);
    EXPECT_LT((theta_eq - x.head(3)).cwiseAbs().maxCoeff(), 1e-3) << p.rho.transpose();
  }
}

TEST(RigidBody3x3, StaticGainFitOnNoiseFreePartTwoMatchesTheEquilibria) {
  RigidBodyOptions o;
  o.noise_variance = 0;
  o.n = 10;
  const Experiment<double> gain = nearest_double(rigid_body_experiment(o).gain);
  std::vector<Monomial> quadratic;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int c = 0; c < 3; ++c)
        if (a + b + c <= 2) quadratic.push_back(Monomial{{a, b, c}});
  const Mat<double> phi = fit_static_gain(gain, quadratic);
  double worst = 0;
  for (int k = 0; k < 20; ++k) {  // operating points spread over the range
    const Vec<double> r = vec3(0.4 * std::sin(1.3 * k), 0.4 * std::cos(2.1 * k), 0.4 * std::sin(0.7 * k + 1));
    Vec<double> fitted = Vec<double>::Zero(3);
    for (size_t j = 0; j < quadratic.size(); ++j)
      fitted += quadratic[j].eval<double>(r) * phi.row(static_cast<Eigen::Index>(j)).transpose();
    worst = std::max(worst, (fitted - equilibrium(r).head(3)).cwiseAbs().maxCoeff());
  }
  // A quadratic is not Φ (sin, cos and the couplings), and the ramps lag
  // behind u* by ~0.003 rad/sample × ~3 samples: 0.02 covers both; with 12
  // ramps instead of 40 (poor coverage of the cube) this was 0.09.
  EXPECT_LT(worst, 0.02);
}

TEST(RigidBody3x3, ExperimentIsExactShortDecimalsInRange) {
  RigidBodyOptions o;
  o.n = 50;
  const RigidBodyParts parts = rigid_body_experiment(o);
  const Rational range(2, 5);
  ASSERT_EQ(Rational(kRigidBodyRange), Rational(0.4));
  EXPECT_EQ(parts.validation.n(), 50);
  for (const Experiment<Rational>* e : {&parts.local, &parts.gain, &parts.validation}) {
    ASSERT_EQ(e->nu(), 3);
    ASSERT_EQ(e->ny(), 3);
    ASSERT_EQ(e->n_rho(), 3);
    for (Eigen::Index k = 0; k < e->n(); ++k)
      for (int i = 0; i < 3; ++i) {
        EXPECT_LE(e->rho(k, i), range);
        EXPECT_GE(e->rho(k, i), -range);
        EXPECT_TRUE(is_integer(e->rho(k, i) * 10000));
        EXPECT_TRUE(is_integer(e->u(k, i) * 10000));
        EXPECT_TRUE(is_integer(e->y(k, i) * Rational(10000000000.0)));
      }
  }
  // Part 2 has û ≡ 0; part 1 holds ρ at the 9 operating points.
  EXPECT_TRUE(parts.gain.u.isZero());
  EXPECT_EQ(fit_operating_points(nearest_double(parts.local), 2, o.settle).size(), 9u);
}

}  // namespace
}  // namespace lpvid
