#include "toeplitz/uncertainty_toeplitz.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/input_error.h"
#include "model/simulate.h"
#include "support/gen_models.h"
#include "support/gen_numbers.h"
#include "toeplitz/signal_toeplitz.h"

namespace lpvid {
namespace {

using gen::exactly_equal;

using gen::scalar_matrix;

/// Scalar model with one scheduling variable: A(ρ) = a·ρ, B = b, C = c,
/// D(ρ) = d·ρ; multiplicative uncertainty with W = 1, so z = ŷ.
LpvModel<Rational> scalar_lpv(int a, int b, int c, int d) {
  LpvModel<Rational> m;
  m.nx = m.nu = m.ny = 1;
  m.scheduling = {"rho1"};
  const Monomial one{{0}}, rho{{1}};
  m.A = ParamMatrix<Rational>(1, 1);
  m.A.add(rho, scalar_matrix(a));
  m.B = ParamMatrix<Rational>(1, 1);
  m.B.add(one, scalar_matrix(b));
  m.C = ParamMatrix<Rational>(1, 1);
  m.C.add(one, scalar_matrix(c));
  m.D = ParamMatrix<Rational>(1, 1);
  m.D.add(rho, scalar_matrix(d));
  return m;
}

Experiment<Rational> scalar_experiment(std::vector<int> u, std::vector<int> rho) {
  Experiment<Rational> e;
  const auto n = static_cast<Eigen::Index>(u.size());
  e.u.resize(n, 1);
  e.rho.resize(n, 1);
  e.y = Mat<Rational>::Zero(n, 1);
  for (Eigen::Index k = 0; k < n; ++k) {
    e.u(k, 0) = u[static_cast<size_t>(k)];
    e.rho(k, 0) = rho[static_cast<size_t>(k)];
  }
  return e;
}

Mat<Rational> matrix(int rows, int cols, std::vector<int> v) {
  Mat<Rational> m(rows, cols);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) m(i, j) = v[static_cast<size_t>(i * cols + j)];
  return m;
}

TEST(UncertaintyToeplitzTest, ModeNamesRoundTrip) {
  for (ToeplitzMode m : {ToeplitzMode::kSignal, ToeplitzMode::kPaper})
    EXPECT_EQ(toeplitz_mode_from_string(to_string(m)), m);
  EXPECT_STREQ(to_string(ToeplitzMode::kSignal), "signal");
  EXPECT_STREQ(to_string(ToeplitzMode::kPaper), "paper");
  EXPECT_EQ(kDefaultToeplitzMode, ToeplitzMode::kSignal);
  EXPECT_THROW(toeplitz_mode_from_string("Paper"), InputError);
  EXPECT_THROW(toeplitz_mode_from_string(""), InputError);
}

// docs/design.md §6.3: an LPV case where the modes differ. Static z_k = ρ_k u_k along
// ρ = (1, 2), u = (1, 0): paper-mode T_z = T_G12 T_u = diag(1, 2) is not
// Toeplitz; its last column is D(ρ_{n−1}) u_0 = 2, not D(ρ_0) u_0 = 1.
TEST(UncertaintyToeplitzTest, PaperAndSignalDifferForStaticLpvGain) {
  const LpvModel<Rational> m = scalar_lpv(0, 0, 0, 1);
  const Experiment<Rational> e = scalar_experiment({1, 0}, {1, 2});
  const Mat<Rational> signal = T_z(m, e, ToeplitzMode::kSignal);
  const Mat<Rational> paper = T_z(m, e, ToeplitzMode::kPaper);
  EXPECT_TRUE(exactly_equal(signal, matrix(2, 2, {1, 0, 0, 1})));
  EXPECT_TRUE(exactly_equal(paper, matrix(2, 2, {1, 0, 0, 2})));
  EXPECT_FALSE(exactly_equal(signal, paper));
}

// A dynamic case: x_{k+1} = ρ_k x_k + u_k, z_k = x_k along ρ = (2, 3, 5, 7),
// u = (1, 1, 0, 0). z = (0, 1, 4, 20). Paper column 1 is the response to u
// delayed once along the same ρ: x = (0, 0, 1, 5·1 + 1 = 6).
TEST(UncertaintyToeplitzTest, PaperAndSignalDifferForDynamicLpv) {
  const LpvModel<Rational> m = scalar_lpv(1, 1, 1, 0);
  const Experiment<Rational> e = scalar_experiment({1, 1, 0, 0}, {2, 3, 5, 7});
  EXPECT_TRUE(exactly_equal(T_z(m, e, ToeplitzMode::kSignal),
                            matrix(4, 4, {0, 0, 0, 0, 1, 0, 0, 0, 4, 1, 0, 0, 20, 4, 1, 0})));
  EXPECT_TRUE(exactly_equal(T_z(m, e, ToeplitzMode::kPaper),
                            matrix(4, 4, {0, 0, 0, 0, 1, 0, 0, 0, 4, 1, 0, 0, 20, 6, 1, 0})));
}

// Paper mode has no term for x_0: it refuses a non-zero x0; signal mode
// includes the free response.
TEST(UncertaintyToeplitzTest, PaperModeRejectsNonZeroInitialState) {
  LpvModel<Rational> m = scalar_lpv(1, 1, 1, 0);
  m.x0 = Vec<Rational>::Constant(1, Rational(1));
  const Experiment<Rational> e = scalar_experiment({0, 0, 0}, {2, 3, 5});
  EXPECT_THROW(T_z(m, e, ToeplitzMode::kPaper), std::invalid_argument);
  EXPECT_TRUE(exactly_equal(T_z(m, e, ToeplitzMode::kSignal), matrix(3, 3, {1, 0, 0, 2, 1, 0, 6, 2, 1})));
  m.x0 = Vec<Rational>::Zero(1);  // an explicit zero x0 is fine
  EXPECT_NO_THROW(T_z(m, e, ToeplitzMode::kPaper));
}

// docs/design.md §6.3: the modes coincide for an LTI G12 (x_0 = 0), exactly.
RC_GTEST_PROP(UncertaintyToeplitzProperty, PaperEqualsSignalForLtiModels, ()) {
  gen::ModelOptions o;
  o.entry = gen::rational_entry(3, 3);
  o.zero_x0 = true;
  o.lti = true;
  const auto md = *gen::model_and_data(o, gen::rational_entry(2, 2));
  const Mat<Rational> signal = T_z(md.model, md.data, ToeplitzMode::kSignal);
  RC_ASSERT(signal.rows() == md.data.n() * md.model.nz());
  RC_ASSERT(signal.cols() == md.data.n());
  RC_ASSERT(exactly_equal(T_z(md.model, md.data, ToeplitzMode::kPaper), signal));
}

// …and for an LPV model along a trajectory where ρ is constant (then G12 is
// LTI along it).
RC_GTEST_PROP(UncertaintyToeplitzProperty, PaperEqualsSignalWhenRhoIsConstant, ()) {
  gen::ModelOptions o;
  o.entry = gen::rational_entry(3, 3);
  o.zero_x0 = true;
  const auto md = *gen::model_and_data(o, gen::rational_entry(2, 2), /*constant_rho=*/true);
  RC_ASSERT(exactly_equal(T_z(md.model, md.data, ToeplitzMode::kPaper),
                          T_z(md.model, md.data, ToeplitzMode::kSignal)));
}

// Independent description of both modes for any LPV model (x_0 = 0):
// paper-mode column j is the z response to u delayed by j samples along the
// undelayed ρ; signal-mode column j is z itself delayed by j samples.
RC_GTEST_PROP(UncertaintyToeplitzProperty, ColumnsAreResponsesToDelayedInputs, ()) {
  gen::ModelOptions o;
  o.entry = gen::rational_entry(3, 3);
  o.zero_x0 = true;
  const auto md = *gen::model_and_data(o, gen::rational_entry(2, 2));
  const Eigen::Index n = md.data.n(), nz = md.model.nz(), nu = md.model.nu;
  const Mat<Rational> paper = T_z(md.model, md.data, ToeplitzMode::kPaper);
  const Mat<Rational> signal = T_z(md.model, md.data, ToeplitzMode::kSignal);
  const Mat<Rational> z = simulate(md.model, md.data).z;
  for (Eigen::Index j = 0; j < n; ++j) {
    Experiment<Rational> delayed = md.data;
    delayed.u = Mat<Rational>::Zero(n, nu);
    delayed.u.bottomRows(n - j) = md.data.u.topRows(n - j);
    const Mat<Rational> zj = simulate(md.model, delayed).z;
    RC_ASSERT(exactly_equal(paper.col(j), stack_rows(zj)));
    Mat<Rational> z_shifted = Mat<Rational>::Zero(n, nz);
    z_shifted.bottomRows(n - j) = z.topRows(n - j);
    RC_ASSERT(exactly_equal(signal.col(j), stack_rows(z_shifted)));
  }
}

}  // namespace
}  // namespace lpvid
