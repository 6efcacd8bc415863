// fit/mimo_arx.h and fit/local_lpv.h (part 1 of the paper's Example 2,
// Section 4.2): the MIMO ARX least squares recovers a noise-free ARX system,
// the entrywise interpolation over operating points recovers matrices that
// are exactly affine in ρ, and the assembled LPV model (block observer
// realisation) reproduces the ARX recursion at a frozen ρ.
#include <gtest/gtest.h>

#include <vector>

#include "examples/random_stream.h"
#include "fit/local_lpv.h"
#include "model/simulate.h"

namespace lpvid {
namespace {

Mat<double> random_matrix(RandomStream& rng, Eigen::Index r, Eigen::Index c, double scale) {
  Mat<double> m(r, c);
  for (Eigen::Index i = 0; i < r; ++i)
    for (Eigen::Index j = 0; j < c; ++j) m(i, j) = scale * (2 * rng.uniform() - 1);
  return m;
}

/// A stable 3×3 order-2 ARX system: P1 = 0.5 I + small, P2 = −0.1 I + small.
MimoArx random_arx(RandomStream& rng, double scale) {
  MimoArx m;
  m.P = {0.5 * scale * Mat<double>::Identity(3, 3) + random_matrix(rng, 3, 3, 0.05 * scale),
         -0.1 * scale * Mat<double>::Identity(3, 3) + random_matrix(rng, 3, 3, 0.05 * scale)};
  m.Q = {random_matrix(rng, 3, 3, scale), random_matrix(rng, 3, 3, scale)};
  m.c = random_matrix(rng, 3, 1, 0.1 * scale);
  return m;
}

/// y_k = Σ P_i y_{k−i} + Σ Q_i u_{k−i} + c from zero initial conditions.
Mat<double> run_arx(const MimoArx& m, const Mat<double>& u, bool constant) {
  Mat<double> y = Mat<double>::Zero(u.rows(), m.P[0].rows());
  for (Eigen::Index k = 0; k < u.rows(); ++k) {
    Vec<double> v = constant ? m.c : Vec<double>::Zero(y.cols());
    for (int i = 1; i <= m.order() && i <= k; ++i)
      v += m.P[i - 1] * y.row(k - i).transpose() + m.Q[i - 1] * u.row(k - i).transpose();
    y.row(k) = v.transpose();
  }
  return y;
}

TEST(MimoArx, LeastSquaresRecoversANoiseFreeSystem) {
  RandomStream rng(7);
  const MimoArx truth = random_arx(rng, 1.0);
  const Mat<double> u = random_matrix(rng, 200, 3, 1.0);
  const MimoArx fit = fit_mimo_arx(u, run_arx(truth, u, true), 2);
  for (int i = 0; i < 2; ++i) {
    EXPECT_LT((fit.P[i] - truth.P[i]).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LT((fit.Q[i] - truth.Q[i]).cwiseAbs().maxCoeff(), 1e-9);
  }
  EXPECT_LT((fit.c - truth.c).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(LocalLpv, InterpolationRecoversAffineMatricesAndTheModelReproducesTheArx) {
  RandomStream rng(11);
  const std::vector<Monomial> basis = {Monomial{{0, 0, 0}}, Monomial{{1, 0, 0}}, Monomial{{0, 1, 0}},
                                       Monomial{{0, 0, 1}}};
  std::vector<MimoArx> truth = {random_arx(rng, 1.0)};
  for (int j = 1; j < 4; ++j) truth.push_back(random_arx(rng, 0.1));
  auto at = [&](const std::vector<MimoArx>& terms, const Vec<double>& rho) {
    MimoArx m = terms[0];
    for (size_t j = 1; j < terms.size(); ++j) {
      const double f = basis[j].eval<double>(rho);
      for (int i = 0; i < 2; ++i) {
        m.P[i] += f * terms[j].P[i];
        m.Q[i] += f * terms[j].Q[i];
      }
      m.c += f * terms[j].c;
    }
    return m;
  };
  std::vector<OperatingPointFit> points;
  for (int p = 0; p < 9; ++p) {
    const Vec<double> rho = random_matrix(rng, 3, 1, 0.4);
    points.push_back({rho, at(truth, rho)});
  }
  const std::vector<MimoArx> terms = interpolate_arx(points, basis);
  ASSERT_EQ(terms.size(), 4u);
  for (size_t j = 0; j < 4; ++j)
    for (int i = 0; i < 2; ++i) {
      EXPECT_LT((terms[j].P[i] - truth[j].P[i]).cwiseAbs().maxCoeff(), 1e-10) << j;
      EXPECT_LT((terms[j].Q[i] - truth[j].Q[i]).cwiseAbs().maxCoeff(), 1e-10) << j;
    }

  // At a frozen ρ the LPV model (no offset: c is Φ's business) is the ARX recursion.
  const LpvModel<Rational> model = lpv_from_arx_terms(terms, basis, Rational(1, 100), 15);
  EXPECT_EQ(model.nx, 6);
  Experiment<double> e;
  e.u = random_matrix(rng, 60, 3, 1.0);
  const Vec<double> rho = random_matrix(rng, 3, 1, 0.4);
  e.rho = rho.transpose().replicate(60, 1);
  e.y = Mat<double>::Zero(60, 3);
  const Simulation<double> sim = simulate(convert_model<double>(model), e);
  const Mat<double> expected = run_arx(at(truth, rho), e.u, false);
  EXPECT_LT((sim.yhat - expected).cwiseAbs().maxCoeff(), 1e-9 * (1 + expected.cwiseAbs().maxCoeff()));
}

}  // namespace
}  // namespace lpvid
