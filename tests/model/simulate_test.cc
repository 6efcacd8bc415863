#include "model/simulate.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "core/number_text.h"
#include "model/lpv_model.h"
#include "model/uncertainty_channel.h"
#include "support/gen_models.h"
#include "toeplitz/signal_toeplitz.h"
#include "support/same_bits.h"

namespace lpvid {
namespace {

using gen::exactly_equal;

Rational q(int p, int d = 1) { return Rational(p) / Rational(d); }
Mat<Rational> scalar_matrix(const Rational& v) { return Mat<Rational>::Constant(1, 1, v); }
Mat<Rational> column(std::vector<Rational> v) {
  Mat<Rational> m(static_cast<Eigen::Index>(v.size()), 1);
  for (size_t k = 0; k < v.size(); ++k) m(static_cast<Eigen::Index>(k), 0) = v[k];
  return m;
}

/// x_{k+1} = ρ_k x_k + u_k, ŷ_k = x_k + 2 u_k, x_0 = 1, z = W·ŷ with W = 1/2,
/// offset Φ(ρ) = 1 + 10 ρ.
LpvModel<Rational> hand_model() {
  LpvModel<Rational> m;
  m.nx = m.nu = m.ny = 1;
  m.scheduling = {"rho1"};
  const Monomial one{{0}}, rho{{1}};
  m.A = ParamMatrix<Rational>(1, 1);
  m.A.add(rho, scalar_matrix(1));
  m.B = ParamMatrix<Rational>(1, 1);
  m.B.add(one, scalar_matrix(1));
  m.C = ParamMatrix<Rational>(1, 1);
  m.C.add(one, scalar_matrix(1));
  m.D = ParamMatrix<Rational>(1, 1);
  m.D.add(one, scalar_matrix(2));
  m.uncertainty.weight = q(1, 2);
  m.offset.basis = {one, rho};
  m.offset.values = {Vec<Rational>::Constant(1, q(1)), Vec<Rational>::Constant(1, q(10))};
  m.x0 = Vec<Rational>::Constant(1, q(1));
  return m;
}

Experiment<Rational> hand_experiment() {
  Experiment<Rational> e;
  e.u = column({q(1), q(0), q(1)});
  e.rho = column({q(2), q(3), q(0)});
  e.y = column({q(0), q(0), q(0)});
  return e;
}

TEST(SimulateTest, ScalarLpvByHand) {
  const Simulation<Rational> s = simulate(hand_model(), hand_experiment());
  // x_1 = 2·1 + 1 = 3, x_2 = 3·3 + 0 = 9.
  EXPECT_TRUE(exactly_equal(s.x, column({q(1), q(3), q(9)})));
  EXPECT_TRUE(exactly_equal(s.yhat, column({q(3), q(3), q(11)})));
  EXPECT_TRUE(exactly_equal(s.z, column({q(3, 2), q(3, 2), q(11, 2)})));  // W·ŷ, no offset
  EXPECT_TRUE(exactly_equal(s.offset, column({q(21), q(31), q(1)})));
}

TEST(SimulateTest, FixedCorrectionAbActOnTheState) {
  LpvModel<Rational> m = hand_model();
  m.correction.basis = {Monomial{{2}}};          // f_1 = ρ²
  m.correction.A = {scalar_matrix(q(1, 3))};     // A(ρ) = ρ + ρ²/3
  m.correction.B = {scalar_matrix(q(0))};
  const Simulation<Rational> s = simulate(m, hand_experiment());
  // x_1 = (2 + 4/3)·1 + 1 = 13/3, x_2 = (3 + 3)·13/3 + 0 = 26.
  EXPECT_TRUE(exactly_equal(s.x, column({q(1), q(13, 3), q(26)})));
}

TEST(SimulateTest, AdditiveAndGeneralChannels) {
  LpvModel<Rational> m = hand_model();
  m.uncertainty.structure = UncertaintyStructure::kAdditive;
  m.uncertainty.weight = q(3);
  EXPECT_EQ(m.nz(), 1);
  EXPECT_TRUE(exactly_equal(simulate(m, hand_experiment()).z, column({q(3), q(0), q(3)})));  // z = W·u

  m.uncertainty.structure = UncertaintyStructure::kGeneral;
  m.uncertainty.C1 = ParamMatrix<Rational>(2, 1);
  m.uncertainty.C1.add(Monomial{{0}}, column({q(1), q(0)}));
  m.uncertainty.D1 = ParamMatrix<Rational>(2, 1);
  m.uncertainty.D1.add(Monomial{{1}}, column({q(0), q(1)}));  // D1(ρ) = [0; ρ]
  EXPECT_EQ(m.nz(), 2);
  Mat<Rational> z(3, 2);
  z << 1, 2,  // x_0, ρ_0 u_0
      3, 0,   //
      9, 0;
  EXPECT_TRUE(exactly_equal(simulate(m, hand_experiment()).z, z));

  m.uncertainty.D1 = ParamMatrix<Rational>(3, 1);  // nz disagrees with C1
  EXPECT_THROW(m.nz(), std::invalid_argument);
}

TEST(SimulateTest, UncertaintyStructureNames) {
  EXPECT_STREQ(to_string(UncertaintyStructure::kMultiplicative), "multiplicative");
  EXPECT_STREQ(to_string(UncertaintyStructure::kAdditive), "additive");
  EXPECT_STREQ(to_string(UncertaintyStructure::kGeneral), "general");
}

TEST(SimulateTest, SizeMismatchesThrow) {
  const LpvModel<Rational> m = hand_model();
  const Experiment<Rational> e = hand_experiment();
  {
    Experiment<Rational> bad = e;
    bad.u = Mat<Rational>::Zero(3, 2);
    EXPECT_THROW(simulate(m, bad), std::invalid_argument);
  }
  {
    Experiment<Rational> bad = e;
    bad.y = Mat<Rational>::Zero(3, 2);
    EXPECT_THROW(simulate(m, bad), std::invalid_argument);
  }
  {
    Experiment<Rational> bad = e;
    bad.rho = Mat<Rational>::Zero(3, 2);
    EXPECT_THROW(simulate(m, bad), std::invalid_argument);
  }
  {
    Experiment<Rational> bad = e;
    bad.rho = Mat<Rational>::Zero(2, 1);
    EXPECT_THROW(simulate(m, bad), std::invalid_argument);
  }
  {
    Experiment<Rational> no_y = e;
    no_y.y.resize(0, 0);  // simulation does not need y
    EXPECT_NO_THROW(simulate(m, no_y));
  }
  {
    LpvModel<Rational> bad = m;
    bad.x0 = Vec<Rational>::Zero(2);
    EXPECT_THROW(simulate(bad, e), std::invalid_argument);
  }
  {
    LpvModel<Rational> bad = m;
    bad.correction.basis = {Monomial{{1}}, Monomial{{2}}};
    bad.correction.A = {scalar_matrix(q(1))};  // one A_i for two basis functions
    EXPECT_THROW(simulate(bad, e), std::invalid_argument);
  }
  {
    LpvModel<Rational> bad = m;
    bad.A.terms[0].basis = Monomial{{1, 0}};  // two powers, one scheduling variable
    EXPECT_THROW(simulate(bad, e), std::invalid_argument);
  }
  {
    LpvModel<Rational> bad = m;
    bad.B.terms[0].value = Mat<Rational>::Zero(2, 1);
    EXPECT_THROW(simulate(bad, e), std::invalid_argument);
  }
  {
    LpvModel<Rational> bad = m;
    bad.offset.values[1] = Vec<Rational>::Zero(2);
    EXPECT_THROW(simulate(bad, e), std::invalid_argument);
  }
  {
    LpvModel<Rational> absent = m;  // 0×0 matrices without terms read as zero
    absent.D = ParamMatrix<Rational>();
    EXPECT_TRUE(exactly_equal(simulate(absent, e).yhat, column({q(1), q(3), q(9)})));
  }
}

TEST(ConvertModelTest, RationalToDoubleRoundsToNearest) {
  LpvModel<Rational> m = hand_model();
  m.A.terms[0].value(0, 0) = q(1, 3);
  const LpvModel<double> d = convert_model<double, Rational>(m);
  EXPECT_EQ(d.A.terms[0].value(0, 0), 1.0 / 3.0);
  EXPECT_EQ(d.uncertainty.weight, 0.5);
  const LpvModel<Rational> back = convert_model<Rational, double>(d);
  EXPECT_EQ(back.A.terms[0].value(0, 0), exact_rational_of_double(1.0 / 3.0));
  EXPECT_NE(back.A.terms[0].value(0, 0), q(1, 3));
}

// ŷ(θ) = ŷ_0 + J θ exactly over ℚ (Theorem 3.1, eq. 15): simulating the
// model with the correction C_i, D_i added as extra C/D terms f_i(ρ)·C_i,
// f_i(ρ)·D_i equals the affine prediction. θ is read here with the
// documented layout (basis i major, C_i row-major, then D_i row-major),
// written out independently of CorrectionLayout. Also: the state does not
// move, z follows W·J θ (multiplicative) or stays (additive), the
// regressors give the same ŷ(θ), and fold_correction agrees. For the
// general structure correction_jacobian(…, nz) does the same for C1_i, D1_i.
RC_GTEST_PROP(SimulateProperty, OutputIsAffineInTheCorrection, ()) {
  gen::ModelOptions o;
  o.entry = gen::rational_entry(3, 3);
  const auto md = *gen::model_and_data(o, gen::rational_entry(2, 2));
  const LpvModel<Rational>& m = md.model;
  const Eigen::Index N = static_cast<Eigen::Index>(m.correction.basis.size());
  const Eigen::Index nx = m.nx, nu = m.nu, ny = m.ny, n = md.data.n();
  const Vec<Rational> theta = *gen::rational_matrix(static_cast<int>(N * ny * (nx + nu)), 1, gen::rational_entry(5, 4));

  const Simulation<Rational> sim0 = simulate(m, md.data);
  const Mat<Rational> J = output_jacobian(m, md.data, sim0);
  RC_ASSERT(J.rows() == n * ny);
  RC_ASSERT(J.cols() == N * ny * (nx + nu));
  RC_ASSERT(output_correction_layout(m).size() == J.cols());

  LpvModel<Rational> m1 = m;
  std::vector<Mat<Rational>> Cs, Ds;
  for (Eigen::Index i = 0; i < N; ++i) {
    Mat<Rational> Ci(ny, nx), Di(ny, nu);
    const Eigen::Index base = i * ny * (nx + nu);
    for (Eigen::Index r = 0; r < ny; ++r) {
      for (Eigen::Index c = 0; c < nx; ++c) Ci(r, c) = theta(base + r * nx + c);
      for (Eigen::Index c = 0; c < nu; ++c) Di(r, c) = theta(base + ny * nx + r * nu + c);
    }
    m1.C.add(m.correction.basis[static_cast<size_t>(i)], Ci);
    m1.D.add(m.correction.basis[static_cast<size_t>(i)], Di);
    Cs.push_back(Ci);
    Ds.push_back(Di);
  }
  const Simulation<Rational> sim1 = simulate(m1, md.data);
  RC_ASSERT(exactly_equal(sim1.x, sim0.x));
  const Vec<Rational> predicted = stack_rows(sim0.yhat) + J * theta;
  RC_ASSERT(exactly_equal(stack_rows(sim1.yhat), predicted));
  RC_ASSERT(exactly_equal(simulate(fold_correction(m, theta), md.data).yhat, sim1.yhat));

  const std::vector<Mat<Rational>> reg = correction_regressors(m, md.data, sim0);
  RC_ASSERT(static_cast<Eigen::Index>(reg.size()) == N);
  for (Eigen::Index k = 0; k < n; ++k) {
    Vec<Rational> yk = sim0.yhat.row(k).transpose();
    for (Eigen::Index i = 0; i < N; ++i) {
      Mat<Rational> CD(ny, nx + nu);
      CD << Cs[static_cast<size_t>(i)], Ds[static_cast<size_t>(i)];
      yk += CD * reg[static_cast<size_t>(i)].row(k).transpose();
    }
    RC_ASSERT(exactly_equal(yk, sim1.yhat.row(k).transpose()));
  }

  switch (m.uncertainty.structure) {
    case UncertaintyStructure::kMultiplicative:
      RC_ASSERT(exactly_equal(stack_rows(sim1.z), Vec<Rational>(stack_rows(sim0.z) + m.uncertainty.weight * (J * theta))));
      break;
    case UncertaintyStructure::kAdditive:
      RC_ASSERT(exactly_equal(sim1.z, sim0.z));
      break;
    case UncertaintyStructure::kGeneral: {
      const Eigen::Index nz = m.nz();
      const Vec<Rational> theta_z =
          *gen::rational_matrix(static_cast<int>(N * nz * (nx + nu)), 1, gen::rational_entry(5, 4));
      const Mat<Rational> Jz = correction_jacobian(m, md.data, sim0, nz);
      LpvModel<Rational> m2 = m;
      for (Eigen::Index i = 0; i < N; ++i) {
        Mat<Rational> C1i(nz, nx), D1i(nz, nu);
        const Eigen::Index base = i * nz * (nx + nu);
        for (Eigen::Index r = 0; r < nz; ++r) {
          for (Eigen::Index c = 0; c < nx; ++c) C1i(r, c) = theta_z(base + r * nx + c);
          for (Eigen::Index c = 0; c < nu; ++c) D1i(r, c) = theta_z(base + nz * nx + r * nu + c);
        }
        m2.uncertainty.C1.add(m.correction.basis[static_cast<size_t>(i)], C1i);
        m2.uncertainty.D1.add(m.correction.basis[static_cast<size_t>(i)], D1i);
      }
      RC_ASSERT(exactly_equal(stack_rows(simulate(m2, md.data).z), Vec<Rational>(stack_rows(sim0.z) + Jz * theta_z)));
      break;
    }
  }
}

// The fixed correction A_i, B_i are part of the state equation: the model
// behaves exactly like the one with f_i(ρ)·A_i, f_i(ρ)·B_i written as extra
// A/B terms and no correction matrices.
RC_GTEST_PROP(SimulateProperty, FixedCorrectionEqualsExtraStateTerms, ()) {
  gen::ModelOptions o;
  o.entry = gen::rational_entry(3, 3);
  const auto md = *gen::model_and_data(o, gen::rational_entry(2, 2));
  LpvModel<Rational> flat = md.model;
  flat.correction.A.clear();
  flat.correction.B.clear();
  for (size_t i = 0; i < md.model.correction.A.size(); ++i) {
    flat.A.add(md.model.correction.basis[i], md.model.correction.A[i]);
    flat.B.add(md.model.correction.basis[i], md.model.correction.B[i]);
  }
  const Simulation<Rational> a = simulate(md.model, md.data);
  const Simulation<Rational> b = simulate(flat, md.data);
  RC_ASSERT(exactly_equal(a.x, b.x));
  RC_ASSERT(exactly_equal(a.yhat, b.yhat));
  RC_ASSERT(exactly_equal(a.z, b.z));
  RC_ASSERT(a.x.rows() == md.data.n());
  RC_ASSERT(a.z.cols() == md.model.nz());
  // x_0 is the model's x0 (zero if empty).
  const Vec<Rational> x0 = md.model.x0.size() == 0 ? Vec<Rational>(Vec<Rational>::Zero(md.model.nx)) : md.model.x0;
  RC_ASSERT(exactly_equal(a.x.row(0).transpose(), x0));
}

// Φ = J_Φ [φ_1; …; φ_M] (paper eq. 20) for the offset values the model holds.
RC_GTEST_PROP(SimulateProperty, OffsetIsLinearInItsValues, ()) {
  gen::ModelOptions o;
  o.entry = gen::rational_entry(3, 3);
  const auto md = *gen::model_and_data(o, gen::rational_entry(2, 2));
  LpvModel<Rational> m = md.model;
  m.offset.values.clear();
  Vec<Rational> phi(static_cast<Eigen::Index>(m.offset.basis.size()) * m.ny);
  for (size_t j = 0; j < m.offset.basis.size(); ++j) {
    const Vec<Rational> v = *gen::rational_matrix(m.ny, 1, gen::rational_entry(5, 4));
    phi.segment(static_cast<Eigen::Index>(j) * m.ny, m.ny) = v;
  }
  const Mat<Rational> J = offset_jacobian(m, md.data);  // values unknown here
  for (size_t j = 0; j < m.offset.basis.size(); ++j)
    m.offset.values.push_back(phi.segment(static_cast<Eigen::Index>(j) * m.ny, m.ny));
  RC_ASSERT(exactly_equal(stack_rows(simulate(m, md.data).offset), Vec<Rational>(J * phi)));
}

// convert_model: Rational → double → Rational is the identity on dyadic
// entries (every one is a double exactly); same-type conversions are the
// identity on any model.
RC_GTEST_PROP(ConvertModelProperty, RoundTripThroughDoubleIsIdentityOnDyadics, ()) {
  gen::ModelOptions o;
  o.entry = gen::dyadic_entry();
  const LpvModel<Rational> m = *gen::lpv_model(o);
  const LpvModel<double> d = convert_model<double, Rational>(m);
  RC_ASSERT(gen::models_equal(convert_model<Rational, double>(d), m));
  RC_ASSERT(gen::models_equal(convert_model<Rational, double>(convert_model<double, double>(d)), m));

  gen::ModelOptions r;
  r.entry = gen::rational_entry(9, 9);
  const LpvModel<Rational> mr = *gen::lpv_model(r);
  RC_ASSERT(gen::models_equal(convert_model<Rational, Rational>(mr), mr));
}

/// The per-sample formulas of the simulation written out as expressions
/// with their own temporaries (how simulate_one_record computed them before
/// it kept its per-sample matrices in one workspace): the reference the
/// workspace version must match bit for bit in double.
Simulation<double> per_sample_reference(const LpvModel<double>& model, const Experiment<double>& exp) {
  const SystemMatrices<double> s = system_matrices(model);
  const Eigen::Index n = exp.n();
  Simulation<double> sim;
  sim.x = Mat<double>::Zero(n, model.nx);
  sim.yhat = Mat<double>::Zero(n, model.ny);
  sim.z = Mat<double>::Zero(n, model.nz());
  sim.offset = Mat<double>::Zero(n, model.ny);
  const Mat<double> u_model = model.statics.model_input(exp.u);
  Vec<double> x = model.x0.size() == 0 ? Vec<double>(Vec<double>::Zero(model.nx)) : model.x0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const Vec<double> rho = detail::rho_at(exp.rho, k);
    const Vec<double> u = u_model.row(k).transpose();
    sim.x.row(k) = x.transpose();
    sim.yhat.row(k) = (s.C.at(rho) * x + s.D.at(rho) * u).transpose();
    sim.z.row(k) = (s.C1.at(rho) * x + s.D1.at(rho) * u).transpose();
    sim.offset.row(k) = offset_at(model, rho).transpose();
    if (k + 1 < n) x = (s.A.at(rho) * x + s.B.at(rho) * u).eval();
  }
  sim.output = model.statics.output.apply(Mat<double>(sim.yhat + sim.offset));
  return sim;
}

// The simulation without per-sample allocations gives exactly the numbers of
// the per-sample expressions (construction: the same Eigen operations on the
// same values), on random models whose entries are not dyadic (so every
// product rounds and a changed order of operations would show).
/// A random model and experiment with small rational entries, in doubles.
std::pair<LpvModel<double>, Experiment<double>> draw_double_case() {
  gen::ModelOptions o;
  o.entry = gen::rational_entry(3, 7);
  const LpvModel<Rational> mr = *gen::lpv_model(o);
  const Experiment<Rational> er =
      *gen::experiment(mr.nu, mr.ny, mr.n_rho(), gen::rational_entry(5, 9), gen::rational_entry(1, 7));
  return {convert_model<double, Rational>(mr), nearest_double(er)};
}

RC_GTEST_PROP(SimulateProperty, WorkspaceSimulationEqualsPerSampleExpressionsBitForBit, ()) {
  const auto [m, e] = draw_double_case();
  const Simulation<double> got = simulate(m, e), want = per_sample_reference(m, e);
  RC_ASSERT(got.x == want.x);
  RC_ASSERT(got.yhat == want.yhat);
  RC_ASSERT(got.z == want.z);
  RC_ASSERT(got.offset == want.offset);
  RC_ASSERT(got.output == want.output);
}

/// simulate_output (no uncertainty channel z) gives simulate(...).output bit
/// for bit, on one record and on the same rows split into two records (each
/// from its own x0), and leaves z empty.
RC_GTEST_PROP(SimulateProperty, OutputOnlySimulationIsTheFullOnesOutputBitForBit, ()) {
  const auto [m, e0] = draw_double_case();
  Experiment<double> e = e0;
  RC_ASSERT(test::same_bits(simulate_output(m, e), simulate(m, e).output));
  RC_ASSERT(simulate(m, e, SimulationParts::kOutput).z.rows() == 0);
  if (e.n() >= 2) {
    const Eigen::Index first = *rc::gen::inRange<Eigen::Index>(1, e.n());
    e.records = {first, e.n() - first};
    e.record_x0 = {Vec<double>(), Vec<double>::Constant(m.nx, 0.25)};
    RC_ASSERT(test::same_bits(simulate_output(m, e), simulate(m, e).output));
  }
}

}  // namespace
}  // namespace lpvid
