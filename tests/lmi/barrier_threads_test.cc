// The structured barrier with a helper thread (BarrierOptions::threads = 2)
// against one thread: every iterate is computed by the same operations, so
// the taps, bounds, dual matrices and Newton step count are identical bit
// for bit (the property that lets the machine's core count never change an
// answer). Sizes reach the split paths: SISO L = 520 (grid 1080 ≥ 1024, the
// split transforms; P and the LDLᵀ split), MIMO 2×2 and 3×2 (pair blocks
// and spectra shared out).
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "lmi/delta_form_barrier.h"

namespace lpvid {
namespace {

bool same_solution_bits(const Mat<double>& a, const Mat<double>& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         (a.size() == 0 || std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<size_t>(a.size())) == 0);
}

struct ThreadSignals {
  Mat<double> z, r;
};

/// r = a short FIR of z plus noise, so that a small δ explains part of it.
ThreadSignals thread_signals(int n, int ny, int nz, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  ThreadSignals s{Mat<double>(n, nz), Mat<double>::Zero(n, ny)};
  for (Eigen::Index k = 0; k < s.z.size(); ++k) s.z.data()[k] = g(rng);
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < ny; ++i) {
      for (int j = 0; j < nz; ++j)
        for (int l = 0; l < 3 && l <= k; ++l) s.r(k, i) += 0.2 / (1 + l + i + j) * s.z(k - l, j);
      s.r(k, i) += 0.1 * g(rng);
    }
  return s;
}

void expect_same_solution(const ThreadSignals& s, double delta) {
  BoundObjective obj;
  obj.kind = BoundObjective::Kind::kMinDmax;
  obj.delta = delta;
  BarrierOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const DeltaFormSolution a = solve_delta_form_barrier(s.z, s.r, obj, one);
  const DeltaFormSolution b = solve_delta_form_barrier(s.z, s.r, obj, two);
  ASSERT_EQ(a.solve.status, SolveStatus::kOptimal) << a.solve.message;
  ASSERT_EQ(b.solve.status, SolveStatus::kOptimal) << b.solve.message;
  EXPECT_EQ(a.solve.iterations, b.solve.iterations);
  EXPECT_EQ(std::memcmp(&a.dmax2, &b.dmax2, sizeof(double)), 0) << a.dmax2 << " vs " << b.dmax2;
  EXPECT_EQ(std::memcmp(&a.path_mu, &b.path_mu, sizeof(double)), 0);
  EXPECT_TRUE(same_solution_bits(a.taps, b.taps));
  EXPECT_TRUE(same_solution_bits(a.dual_c1, b.dual_c1));
  EXPECT_TRUE(same_solution_bits(a.dual_c2, b.dual_c2));
}

TEST(BarrierThreads, SisoSolutionIsBitForBitTheSameOnTwoThreads) { expect_same_solution(thread_signals(520, 1, 1, 1), 0.3); }

TEST(BarrierThreads, MimoSolutionsAreBitForBitTheSameOnTwoThreads) {
  expect_same_solution(thread_signals(60, 2, 2, 2), 0.5);
  expect_same_solution(thread_signals(40, 3, 2, 3), 0.5);
}

TEST(BarrierThreads, DerivativesAreBitForBitTheSameOnTwoThreads) {
  const ThreadSignals s = thread_signals(530, 1, 1, 4);
  BoundObjective obj;
  obj.kind = BoundObjective::Kind::kMinDmax;
  obj.delta = 0.3;
  const Eigen::VectorXd x = Eigen::VectorXd::Constant(530, 1e-4);
  const BarrierDerivatives a = barrier_derivatives(s.z, s.r, obj, x, 0.1, {}, {}, 1);
  const BarrierDerivatives b = barrier_derivatives(s.z, s.r, obj, x, 0.1, {}, {}, 2);
  ASSERT_TRUE(std::isfinite(a.value));
  EXPECT_TRUE(same_solution_bits(a.hessian, b.hessian));
  EXPECT_TRUE(same_solution_bits(a.gradient, b.gradient));
}

}  // namespace
}  // namespace lpvid
