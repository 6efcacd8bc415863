// Free regressors in Theorem 2.1's noise residual, d = r − Δ∗z − G q with q
// free (lmi/free_regressors.h, lmi/delta_form_barrier.h): the structured
// barrier, which eliminates q by projecting d, against the general SDP solver
// (CSDP), where q is a set of free variables of the program; the derivatives
// against finite differences; answers known by construction; zero and
// dependent columns; and the dual's Gᵀg = 0.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <stdexcept>

#include "lmi/delta_form_barrier.h"
#include "lmi/delta_form_lmi.h"
#include "lmi/free_regressors.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "toeplitz/fir.h"
#include "toeplitz/signal_toeplitz.h"
#include "toeplitz/tap_toeplitz.h"
#include "support/barrier_finite_differences.h"

namespace lpvid {
namespace {

/// z (n × nz), r (n × ny) and G ((n·ny) × P, full column rank).
struct FreeCase {
  Mat<double> z, r, G;
};

/// SISO or 2×2, n ≤ 24 (SISO) or ≤ 12 (2×2), P ∈ [1, 3] random columns.
rc::Gen<FreeCase> free_case() {
  return rc::gen::exec([] {
    const bool mimo = *rc::gen::arbitrary<bool>();
    const int ny = mimo ? 2 : 1, nz = mimo ? 2 : 1;
    const int n = *rc::gen::inRange(4, mimo ? 13 : 25), lead = *rc::gen::inRange(0, 3);
    const int P = *rc::gen::inRange(1, 4);
    const double zscale = std::pow(10.0, *rc::gen::inRange(-2, 3)), rscale = std::pow(10.0, *rc::gen::inRange(-2, 3));
    const auto entry = [] { return *rc::gen::inRange(-1000, 1001) / 1000.0; };
    FreeCase c;
    c.z = Mat<double>::Zero(n, nz);
    c.r = Mat<double>::Zero(n, ny);
    c.G = Mat<double>::Zero(n * ny, P);
    for (int k = 0; k < n; ++k) {
      for (int j = 0; j < nz; ++j) c.z(k, j) = k >= lead ? zscale * entry() : 0.0;
      for (int i = 0; i < ny; ++i) c.r(k, i) = rscale * entry();
    }
    c.z(lead, 0) = zscale * (0.5 + *rc::gen::inRange(0, 100) / 200.0);
    for (int p = 0; p < P; ++p)
      for (int k = 0; k < n * ny; ++k) c.G(k, p) = rscale * entry();
    RC_PRE(Eigen::JacobiSVD<Mat<double>>(c.G).singularValues().minCoeff() > 1e-3 * rscale);
    return c;
  });
}

/// P⊥r (stacked), by an orthonormal basis of range(G) from Householder QR
/// (independent of FreeRegressors' SVD).
Vec<double> projected_r(const FreeCase& c) {
  const Eigen::HouseholderQR<Mat<double>> qr(c.G);
  const Mat<double> Q = qr.householderQ() * Mat<double>::Identity(c.G.rows(), c.G.cols());
  const Vec<double> r = stack_rows(c.r);
  return r - Q * (Q.transpose() * r);
}

/// ‖Gᵀg‖ relative to ‖G‖‖g‖ for the dual of (C2), g its column 0 below the
/// corner (g ∝ d). When d is at the rounding of r (r nearly in range(G) plus
/// what the taps fit; a shrunk case had r and G constant and d = 1e-62·G,
/// parallel to G) the leak is measured against g's size at ‖d‖ = 1e-8·‖r‖:
/// g = −Y2(0, 0)·d in original units (Y2 = μ·C2⁻¹, lmi/delta_form_barrier.h).
double dual_leak(const DeltaFormSolution& s, const Mat<double>& G, const Mat<double>& r) {
  const Vec<double> g = s.dual_c2.block(1, 0, s.dual_c2.rows() - 1, 1);
  const double scale = std::max(g.norm(), s.dual_c2(0, 0) * 1e-8 * r.norm());
  return (G.transpose() * g).norm() / std::max(G.norm() * scale, 1e-300);
}

/// The answer's own consistency: q least squares for its taps, d = r − Z h − G q,
/// ‖T_h‖² ≤ δ², ‖d‖² ≤ N·d_max² (up to rounding).
void check_point(const FreeCase& c, const DeltaFormSolution& s) {
  const Eigen::Index ny = c.r.cols(), nz = c.z.cols();
  RC_ASSERT(s.free_coefficients.size() == c.G.cols());
  const Vec<double> e = stack_rows(Mat<double>(c.r - apply_fir(s.taps, c.z, ny, s.horizon))), d = e - c.G * s.free_coefficients;
  RC_ASSERT((d - stack_rows(s.noise_residual)).norm() <= 1e-12 * e.norm());
  RC_ASSERT((c.G.transpose() * d).norm() <= 1e-9 * c.G.norm() * (d.norm() + e.norm()));  // q is least squares
  const double norm = Eigen::JacobiSVD<Mat<double>>(tap_toeplitz_dense(s.taps, ny, nz)).singularValues()(0);
  RC_ASSERT(norm * norm <= s.delta2 * (1 + 1e-9) + 1e-300);
  RC_ASSERT(d.squaredNorm() <= static_cast<double>(c.r.size()) * s.dmax2 * (1 + 1e-8) + 1e-300);
}

RC_GTEST_PROP(DeltaFormFree, OptimumEqualsTheGeneralSdpSolverWithFreeVariables, ()) {
  const FreeCase c = *free_case();
  const double N = static_cast<double>(c.r.size());
  const Vec<double> pr = projected_r(c);
  const int which = *rc::gen::inRange(0, 3);
  BoundObjective obj;
  if (which == 0) {
    obj.kind = BoundObjective::Kind::kMinDmax;
    obj.delta = c.r.norm() / c.z.norm() * (*rc::gen::inRange(5, 200) / 100.0);
  } else if (which == 1) {
    obj.kind = BoundObjective::Kind::kWeighted;
    obj.lambda = *rc::gen::inRange(5, 96) / 100.0;
  } else {
    // min δ at a d_max below ‖P⊥r‖²/N (h = 0's), above what the rows before z starts leave
    obj.kind = BoundObjective::Kind::kMinDelta;
    obj.dmax = pr.norm() / std::sqrt(N) * (*rc::gen::inRange(5, 95) / 100.0);
    const Eigen::Index head = leading_zero_samples(c.z) * c.r.cols();
    RC_PRE(pr.head(head).squaredNorm() < 0.9 * N * obj.dmax.approx * obj.dmax.approx);
  }
  BarrierOptions tight;
  tight.rel_gap = 1e-7;
  const DeltaFormSolution fast = solve_delta_form_barrier(c.z, c.r, obj, tight, c.G);
  RC_LOG() << "ny " << c.r.cols() << " n " << c.z.rows() << " P " << c.G.cols() << ": " << fast.solve.message << "\n";
  RC_ASSERT(fast.solve.status == SolveStatus::kOptimal);
  auto csdp = make_solver("csdp");
  const DeltaFormSolution ref = solve_delta_form(c.z, c.r, obj, *csdp, SolverOptions{}, 0, c.G);
  RC_PRE(ref.solve.status == SolveStatus::kOptimal);
  const double a = obj.value(fast.delta2, fast.dmax2), b = obj.value(ref.delta2, ref.dmax2);
  RC_LOG() << "barrier " << a << " csdp " << b << "\n";
  // as in delta_form_barrier_test.cc: relative 1e-5 plus a floor at the problem's
  // scale, that of r (not P⊥r: the solvers scale by r's RMS, and a shrunk case
  // with r nearly in range(G) has an optimum at both solvers' absolute accuracy)
  const double floor = 1e-7 * obj.value(std::pow(c.r.norm() / c.z.norm(), 2), c.r.squaredNorm() / N);
  RC_ASSERT(a - b <= 1e-5 * std::max(std::abs(a), std::abs(b)) + floor);
  RC_ASSERT(b - a <= 1e-5 * std::max(std::abs(a), std::abs(b)) + 10.0 * floor);
  check_point(c, fast);
  RC_ASSERT(dual_leak(fast, c.G, c.r) <= 1e-9);
  // Without the free regressors the optimum cannot be lower (more freedom never
  // hurts); min δ at this d_max may have no solution without them.
  const DeltaFormSolution plain = solve_delta_form_barrier(c.z, c.r, obj, tight);
  RC_ASSERT(plain.solve.status == SolveStatus::kOptimal || which == 2);
  if (plain.solve.status == SolveStatus::kOptimal) RC_ASSERT(a <= obj.value(plain.delta2, plain.dmax2) * (1 + 1e-5) + floor);
}

RC_GTEST_PROP(DeltaFormFree, FixedBoundsAgreeWithTheGeneralSdpSolver, ()) {
  const FreeCase c = *free_case();
  BoundObjective opt;
  opt.kind = BoundObjective::Kind::kMinDmax;
  opt.delta = c.r.norm() / c.z.norm() * (*rc::gen::inRange(5, 200) / 100.0);
  auto csdp = make_solver("csdp");
  const DeltaFormSolution ref = solve_delta_form(c.z, c.r, opt, *csdp, SolverOptions{}, 0, c.G);
  RC_PRE(ref.solve.status == SolveStatus::kOptimal);
  // CSDP's d_max* is accurate to ~1e-8 of r's scale (delta_form_barrier_test.cc)
  RC_PRE(ref.dmax2 > 1e-5 * c.r.squaredNorm() / static_cast<double>(c.r.size()));
  const bool above = *rc::gen::arbitrary<bool>();
  BoundObjective fixed;
  fixed.kind = BoundObjective::Kind::kFeasibility;
  fixed.delta = opt.delta;
  fixed.dmax = std::sqrt(ref.dmax2) * (above ? 1.05 : 0.95);
  const DeltaFormSolution fast = solve_delta_form_barrier(c.z, c.r, fixed, {}, c.G);
  RC_LOG() << "above " << above << " " << to_string(fast.solve.status) << " " << fast.solve.message << "\n";
  RC_ASSERT(fast.solve.status == (above ? SolveStatus::kOptimal : SolveStatus::kPrimalInfeasible));
  RC_ASSERT(dual_leak(fast, c.G, c.r) <= 1e-9);
  if (above) check_point(c, fast);
}

// The closed-form gradient and Hessian with the projection against central
// finite differences of the barrier value.
RC_GTEST_PROP(DeltaFormFree, DerivativesMatchFiniteDifferences, ()) {
  const FreeCase c = *free_case();
  check_barrier_finite_differences(c.z, c.r, c.G);
}

/// A SISO record: z i.i.d.-like, r = a sum of two known signals plus a small part.
FreeCase known_case(int n) {
  FreeCase c;
  c.z = Mat<double>(n, 1);
  c.r = Mat<double>(n, 1);
  c.G = Mat<double>(n, 2);
  for (int k = 0; k < n; ++k) {
    c.z(k, 0) = std::cos(1.3 * k) + 0.5 * std::sin(0.37 * k * k);
    c.G(k, 0) = std::sin(0.2 * k);
    c.G(k, 1) = 1.0 + 0.01 * k;
    c.r(k, 0) = 3.0 * c.G(k, 0) - 2.0 * c.G(k, 1);
  }
  return c;
}

// Known answer by construction: r = G·(3, −2) lies in range(G), so d = 0 at
// h = 0 and min d_max² at any δ is 0 with q = (3, −2); without G it is not.
TEST(DeltaFormFree, ResidualInTheRangeOfTheRegressorsIsExplainedExactly) {
  const FreeCase c = known_case(30);
  BoundObjective obj;
  obj.kind = BoundObjective::Kind::kMinDmax;
  obj.delta = 0.01;
  const DeltaFormSolution s = solve_delta_form_barrier(c.z, c.r, obj, {}, c.G);
  ASSERT_EQ(s.solve.status, SolveStatus::kOptimal) << s.solve.message;
  EXPECT_LE(s.dmax2, 1e-12 * c.r.squaredNorm());
  ASSERT_EQ(s.free_coefficients.size(), 2);
  EXPECT_NEAR(s.free_coefficients(0), 3.0, 1e-6);
  EXPECT_NEAR(s.free_coefficients(1), -2.0, 1e-6);
  const DeltaFormSolution plain = solve_delta_form_barrier(c.z, c.r, obj);
  ASSERT_EQ(plain.solve.status, SolveStatus::kOptimal) << plain.solve.message;
  EXPECT_GT(plain.dmax2, 0.1 * c.r.squaredNorm() / 30.0);
}

// min δ at a fixed d_max with r = G q₀ + h₀∗z: the taps must explain only
// what G cannot; with G the optimum is at most ‖T_h₀‖² and the q found
// reproduces G q₀'s part of r.
TEST(DeltaFormFree, MinDeltaUsesTheRegressors) {
  FreeCase c = known_case(25);
  Mat<double> h0(3, 1);
  h0 << 0.2, -0.1, 0.05;
  c.r += apply_fir(h0, c.z, 1, c.z.rows());
  Mat<double> h0_full = Mat<double>::Zero(c.z.rows(), 1);
  h0_full.topRows(3) = h0;
  const double norm = Eigen::JacobiSVD<Mat<double>>(tap_toeplitz_dense(h0_full, 1, 1)).singularValues()(0);
  BoundObjective obj;
  obj.kind = BoundObjective::Kind::kMinDelta;
  obj.dmax = 0.01;
  const DeltaFormSolution s = solve_delta_form_barrier(c.z, c.r, obj, {}, c.G);
  ASSERT_EQ(s.solve.status, SolveStatus::kOptimal) << s.solve.message;
  EXPECT_LE(s.delta2, norm * norm * (1 + 1e-4));
  EXPECT_GT(s.delta2, 0.0);
  const DeltaFormSolution plain = solve_delta_form_barrier(c.z, c.r, obj);
  ASSERT_EQ(plain.solve.status, SolveStatus::kOptimal) << plain.solve.message;
  EXPECT_GT(plain.delta2, 2.0 * s.delta2);  // without G the taps must fit the G part too
  EXPECT_LE(dual_leak(s, c.G, c.r), 1e-9);
}

/// Bitwise equality of two answers (taps, bounds, objective, duals).
void expect_identical(const DeltaFormSolution& a, const DeltaFormSolution& b) {
  EXPECT_EQ(a.solve.status, b.solve.status);
  EXPECT_EQ(a.solve.objective, b.solve.objective);
  EXPECT_EQ(a.solve.iterations, b.solve.iterations);
  EXPECT_EQ(a.delta2, b.delta2);
  EXPECT_EQ(a.dmax2, b.dmax2);
  EXPECT_EQ(a.path_mu, b.path_mu);
  EXPECT_TRUE(a.taps == b.taps);
  EXPECT_TRUE(a.dual_c1 == b.dual_c1);
  EXPECT_TRUE(a.dual_c2 == b.dual_c2);
}

// P = 0 and an all-zero G are today's problem, bit for bit (q = 0 for zero columns).
TEST(DeltaFormFree, NoOrZeroRegressorsAreTheProblemWithout) {
  const FreeCase c = known_case(20);
  for (const auto kind : {BoundObjective::Kind::kMinDmax, BoundObjective::Kind::kWeighted, BoundObjective::Kind::kMinDelta,
                          BoundObjective::Kind::kFeasibility}) {
    BoundObjective obj;
    obj.kind = kind;
    obj.delta = 0.3;
    obj.lambda = 0.4;
    obj.dmax = 0.5;
    const DeltaFormSolution plain = solve_delta_form_barrier(c.z, c.r, obj);
    expect_identical(plain, solve_delta_form_barrier(c.z, c.r, obj, {}, Mat<double>(20, 0)));
    const DeltaFormSolution zero = solve_delta_form_barrier(c.z, c.r, obj, {}, Mat<double>::Zero(20, 2));
    expect_identical(plain, zero);
    EXPECT_TRUE(zero.free_coefficients == Vec<double>::Zero(2));
    EXPECT_EQ(plain.free_coefficients.size(), 0);
    EXPECT_TRUE(plain.noise_residual.isApprox(c.r - apply_fir(plain.taps, c.z, 1, plain.horizon)));
  }
}

// Zero and dependent columns add nothing: the same optimum as G alone, q of
// least norm (the zero column's coefficient 0, the combination's split evenly).
TEST(DeltaFormFree, ZeroAndDependentColumnsAddNothing) {
  FreeCase c = known_case(24);
  for (int k = 0; k < 24; ++k) c.r(k, 0) += 0.3 * std::cos(0.9 * k * k);
  Mat<double> wide(24, 4);
  wide << c.G, Mat<double>::Zero(24, 1), c.G.col(0) + c.G.col(1);
  for (const auto kind : {BoundObjective::Kind::kMinDmax, BoundObjective::Kind::kWeighted, BoundObjective::Kind::kMinDelta}) {
    BoundObjective obj;
    obj.kind = kind;
    obj.delta = 0.2;
    obj.lambda = 0.4;
    obj.dmax = 0.2;
    BarrierOptions tight;
    tight.rel_gap = 1e-8;
    const DeltaFormSolution a = solve_delta_form_barrier(c.z, c.r, obj, tight, c.G);
    const DeltaFormSolution b = solve_delta_form_barrier(c.z, c.r, obj, tight, wide);
    ASSERT_EQ(a.solve.status, SolveStatus::kOptimal) << a.solve.message;
    ASSERT_EQ(b.solve.status, SolveStatus::kOptimal) << b.solve.message;
    EXPECT_NEAR(a.solve.objective, b.solve.objective, 1e-6 * std::abs(a.solve.objective));
    ASSERT_EQ(b.free_coefficients.size(), 4);
    EXPECT_EQ(b.free_coefficients(2), 0.0);
    // least norm: orthogonal to the null vector (1, 1, 0, −1) of `wide`
    EXPECT_NEAR(b.free_coefficients(0) + b.free_coefficients(1) - b.free_coefficients(3), 0.0, 1e-8);
    EXPECT_LE((wide * b.free_coefficients - c.G * a.free_coefficients).norm(), 1e-4 * c.r.norm());
    EXPECT_LE(dual_leak(b, wide, c.r), 1e-9);
  }
}

// The basis and the least-norm coefficients against an SVD pseudo-inverse.
TEST(DeltaFormFree, RegressorBasisAndLeastNormCoefficients) {
  Mat<double> G(12, 4);
  for (int k = 0; k < 12; ++k) G(k, 0) = std::sin(k), G(k, 1) = 1e6 * std::cos(2.0 * k), G(k, 2) = 0.0;
  G.col(3) = 2.0 * G.col(0) - 1e-6 * G.col(1);
  const FreeRegressors f(G, 6, 2, "test");
  ASSERT_EQ(f.count(), 4);
  ASSERT_EQ(f.rank(), 2);
  EXPECT_LE((f.basis().transpose() * f.basis() - Mat<double>::Identity(2, 2)).norm(), 1e-12);
  Vec<double> g0 = G.col(0);
  f.project(g0);
  EXPECT_LE(g0.norm(), 1e-12);
  Vec<double> e(12);
  for (int k = 0; k < 12; ++k) e(k) = std::cos(0.7 * k * k);
  Eigen::JacobiSVD<Mat<double>> svd(G, Eigen::ComputeThinU | Eigen::ComputeThinV);
  svd.setThreshold(1e-10);
  const Vec<double> ref = svd.solve(e), q = f.coefficients(e);
  EXPECT_LE((q - ref).norm(), 1e-8 * ref.norm());
  EXPECT_EQ(q(2), 0.0);
  EXPECT_THROW(FreeRegressors(Mat<double>::Ones(11, 1), 6, 2, "test"), std::invalid_argument);
  Mat<double> bad = Mat<double>::Ones(12, 1);
  bad(3, 0) = std::nan("");
  EXPECT_THROW(FreeRegressors(bad, 6, 2, "test"), std::invalid_argument);
}

TEST(DeltaFormFree, RegressorsOfTheWrongLengthAreRefused) {
  const FreeCase c = known_case(20);
  BoundObjective obj;
  obj.kind = BoundObjective::Kind::kMinDmax;
  obj.delta = 0.1;
  EXPECT_THROW(solve_delta_form_barrier(c.z, c.r, obj, {}, Mat<double>::Ones(19, 1)), std::invalid_argument);
  auto csdp = make_solver("csdp");
  EXPECT_THROW(solve_delta_form(c.z, c.r, obj, *csdp, SolverOptions{}, 0, Mat<double>::Ones(21, 1)), std::invalid_argument);
}

}  // namespace
}  // namespace lpvid
