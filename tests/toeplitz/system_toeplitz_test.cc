#include "toeplitz/system_toeplitz.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "model/simulate.h"
#include "support/gen_models.h"
#include "support/gen_numbers.h"
#include "toeplitz/signal_toeplitz.h"
#include "toeplitz/uncertainty_toeplitz.h"

namespace lpvid {
namespace {

using gen::exactly_equal;

using gen::scalar_matrix;

/// x_{k+1} = ρ_k x_k + u_k, ŷ_k = x_k (scalar, one scheduling variable).
LpvModel<Rational> scalar_lpv() {
  LpvModel<Rational> m;
  m.nx = m.nu = m.ny = 1;
  m.scheduling = {"rho1"};
  m.A = ParamMatrix<Rational>(1, 1);
  m.A.add(Monomial{{1}}, scalar_matrix(1));
  m.B = ParamMatrix<Rational>(1, 1);
  m.B.add(Monomial{{0}}, scalar_matrix(1));
  m.C = ParamMatrix<Rational>(1, 1);
  m.C.add(Monomial{{0}}, scalar_matrix(1));
  m.D = ParamMatrix<Rational>(1, 1);
  return m;
}

// Eq. (2) by hand: block (k, j) = C(ρ_k) A(ρ_{k−1}) ⋯ A(ρ_{j+1}) B(ρ_j).
TEST(SystemToeplitzTest, ScalarLpvByHand) {
  const LpvModel<Rational> m = scalar_lpv();
  Mat<Rational> rho(4, 1);
  rho << 2, 3, 5, 7;
  Mat<Rational> expected(4, 4);
  expected << 0, 0, 0, 0,  //
      1, 0, 0, 0,          //
      3, 1, 0, 0,          // C A(ρ_1) B = 3
      15, 5, 1, 0;         // C A(ρ_2) A(ρ_1) B = 5·3, C A(ρ_2) B = 5
  EXPECT_TRUE(exactly_equal(system_toeplitz(m, rho), expected));
}

TEST(SystemToeplitzTest, RejectsInconsistentSizes) {
  ParamMatrix<Rational> A(2, 2), B(2, 1), C(1, 2), D(1, 2);  // D should be 1x1
  EXPECT_THROW(system_toeplitz(A, B, C, D, Mat<Rational>(3, 0)), std::invalid_argument);
  const LpvModel<Rational> m = scalar_lpv();
  EXPECT_THROW(system_toeplitz(m, Mat<Rational>(3, 2)), std::invalid_argument);  // nρ = 2 ≠ 1
  ParamMatrix<Rational> A2(1, 1);
  A2.add(Monomial{{1, 1}}, scalar_matrix(1));  // basis in 2 variables, ρ has 1
  EXPECT_THROW(system_toeplitz(A2, m.B, m.C, m.D, Mat<Rational>(3, 1)), std::invalid_argument);
}

// docs/design.md §6.2: the model output from x_0 = 0 is ŷ = T_G u, for random LPV models
// (with fixed correction A_i, B_i), exactly over ℚ. Likewise z = T_G12 u.
// T_G is block lower triangular (causal).
RC_GTEST_PROP(SystemToeplitzProperty, SystemToeplitzTimesInputIsSimulatedOutput, ()) {
  gen::ModelOptions o;
  o.entry = gen::rational_entry(3, 3);
  o.zero_x0 = true;
  const auto md = *gen::model_and_data(o, gen::rational_entry(2, 2));
  const Simulation<Rational> sim = simulate(md.model, md.data);
  const Vec<Rational> u = stack_rows(md.data.u);
  const Mat<Rational> TG = system_toeplitz(md.model, md.data, SystemChannel::kOutput);
  const Eigen::Index n = md.data.n(), nu = md.model.nu, ny = md.model.ny;
  RC_ASSERT(TG.rows() == n * ny);
  RC_ASSERT(TG.cols() == n * nu);
  RC_ASSERT(exactly_equal(TG * u, stack_rows(sim.yhat)));
  for (Eigen::Index k = 0; k < n; ++k)
    for (Eigen::Index j = k + 1; j < n; ++j)
      RC_ASSERT(exactly_equal(TG.block(k * ny, j * nu, ny, nu), Mat<Rational>::Zero(ny, nu)));
  const Mat<Rational> TG12 = system_toeplitz(md.model, md.data, SystemChannel::kUncertainty);
  RC_ASSERT(TG12.rows() == n * md.model.nz());
  RC_ASSERT(exactly_equal(TG12 * u, stack_rows(sim.z)));
}

// For an LTI G (every term constant, nρ possibly > 0): T_G · T_u = T_{Gu},
// the signal Toeplitz of the output, exactly. (False for LPV along a varying
// ρ, docs/design.md §6.3.) Also for the uncertainty channel: T_G12 · T_u = T_z.
RC_GTEST_PROP(SystemToeplitzProperty, LtiSystemToeplitzTimesInputToeplitzIsOutputToeplitz, ()) {
  gen::ModelOptions o;
  o.entry = gen::rational_entry(3, 3);
  o.zero_x0 = true;
  o.lti = true;
  const auto md = *gen::model_and_data(o, gen::rational_entry(2, 2));
  const Simulation<Rational> sim = simulate(md.model, md.data);
  const Mat<Rational> Tu = signal_toeplitz(md.data.u);
  RC_ASSERT(exactly_equal(system_toeplitz(md.model, md.data) * Tu, signal_toeplitz(sim.yhat)));
  RC_ASSERT(exactly_equal(system_toeplitz(md.model, md.data, SystemChannel::kUncertainty) * Tu,
                          signal_toeplitz(sim.z)));
}

// The double and Rational instantiations agree exactly on small-integer
// data (every intermediate value is an integer far below 2^53): simulation,
// T_G (both channels), T_z (both modes), the output and offset Jacobians.
RC_GTEST_PROP(SystemToeplitzProperty, DoubleAndRationalAgreeOnSmallIntegers, ()) {
  gen::ModelOptions o;
  o.entry = gen::int_entry(1);
  const auto md = *gen::model_and_data(o, gen::int_entry(1));
  const LpvModel<double> md_d = convert_model<double, Rational>(md.model);
  const Experiment<double> data_d = gen::to_double_experiment(md.data);

  const Simulation<Rational> sim = simulate(md.model, md.data);
  const Simulation<double> sim_d = simulate(md_d, data_d);
  RC_ASSERT(exactly_equal(gen::exact_matrix(sim_d.x), sim.x));
  RC_ASSERT(exactly_equal(gen::exact_matrix(sim_d.yhat), sim.yhat));
  RC_ASSERT(exactly_equal(gen::exact_matrix(sim_d.z), sim.z));
  RC_ASSERT(exactly_equal(gen::exact_matrix(sim_d.offset), sim.offset));

  for (SystemChannel ch : {SystemChannel::kOutput, SystemChannel::kUncertainty})
    RC_ASSERT(exactly_equal(gen::exact_matrix(system_toeplitz(md_d, data_d, ch)),
                            system_toeplitz(md.model, md.data, ch)));

  RC_ASSERT(exactly_equal(gen::exact_matrix(T_z(md_d, data_d, ToeplitzMode::kSignal)),
                          T_z(md.model, md.data, ToeplitzMode::kSignal)));
  const bool x0_zero = md.model.x0.size() == 0 || md.model.x0 == Vec<Rational>::Zero(md.model.nx);
  if (x0_zero) {
    RC_ASSERT(exactly_equal(gen::exact_matrix(T_z(md_d, data_d, ToeplitzMode::kPaper)),
                            T_z(md.model, md.data, ToeplitzMode::kPaper)));
  }
  RC_ASSERT(exactly_equal(gen::exact_matrix(output_jacobian(md_d, data_d, sim_d)),
                          output_jacobian(md.model, md.data, sim)));
  RC_ASSERT(exactly_equal(gen::exact_matrix(offset_jacobian(md_d, data_d)), offset_jacobian(md.model, md.data)));
}

}  // namespace
}  // namespace lpvid
