// FFT cross-correlation (toeplitz/correlation_2d.h) against the direct sum.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <random>

#include "core/helper_thread.h"
#include "toeplitz/correlation_2d.h"
#include "support/same_bits.h"

namespace lpvid {
namespace {

/// An L × L matrix of random multiples of 1/scale in [−1000, 1000]/scale.
Mat<double> random_square(int L, double scale) {
  Mat<double> X(L, L);
  for (int i = 0; i < L; ++i)
    for (int j = 0; j < L; ++j) X(i, j) = *rc::gen::inRange(-1000, 1001) / scale;
  return X;
}

RC_GTEST_PROP(Correlation2d, FftEqualsDirectSum, ()) {
  const int L = *rc::gen::inRange(1, 13);
  const int sign = *rc::gen::element(-1, 1);
  Mat<double> X(L, L), Y(L, L);
  for (int i = 0; i < L; ++i)
    for (int j = 0; j < L; ++j) {
      X(i, j) = *rc::gen::inRange(-1000, 1001) / 100.0;
      Y(i, j) = *rc::gen::inRange(-1000, 1001) / 100.0;
    }
  const CorrelationGrid grid(L);
  RC_ASSERT(grid.size() >= 2 * L);
  const Mat<double> fast = grid.correlate(grid.spectrum(X), grid.spectrum(Y), sign);
  const Mat<double> slow = correlate_direct(X, Y, sign);
  RC_ASSERT((fast - slow).cwiseAbs().maxCoeff() <= 1e-9 * (1.0 + slow.cwiseAbs().maxCoeff()));
}

RC_GTEST_PROP(Correlation2d, SumOfTwoEqualsTheDirectSums, ()) {
  const int L = *rc::gen::inRange(1, 11);
  const auto random = [L] { return random_square(L, 100.0); };
  const Mat<double> A = random(), B = random(), C = random(), D = random();
  const CorrelationGrid grid(L);
  const Mat<double> fast = grid.correlate_sum(grid.spectrum(A), grid.spectrum(B), grid.spectrum(C), grid.spectrum(D));
  const Mat<double> slow = correlate_direct(A, B, -1) + correlate_direct(C, D, +1);
  RC_ASSERT((fast - slow).cwiseAbs().maxCoeff() <= 1e-9 * (1.0 + slow.cwiseAbs().maxCoeff()));
}

// The workspace (buffers allocated once, reused across calls) computes the
// very numbers of the allocating calls, bit for bit, also on a strided
// sub-block and a transpose and when its buffers held other data before.
RC_GTEST_PROP(Correlation2d, WorkspaceIsBitIdenticalToTheAllocatingCalls, ()) {
  const int L = *rc::gen::inRange(1, 11);
  const auto random = [L](int rows, int cols) {
    Mat<double> X(rows, cols);
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j) X(i, j) = *rc::gen::inRange(-1000, 1001) / 7.0;
    return X;
  };
  const Mat<double> big = random(2 * L, 2 * L), B = random(L, L), C = random(L, L), D = random(L, L);
  const Mat<double> A = big(Eigen::seq(1, 2 * L - 1, 2), Eigen::seq(0, 2 * L - 2, 2));  // the sub-block read strided
  const CorrelationGrid grid(L);
  CorrelationWorkspace ws(grid);
  Spectrum a, b, c, d;
  Mat<double> out;
  ws.spectrum(random(L, L), a);  // earlier contents of the reused arrays must not matter
  ws.correlate_sum(a, a, a, a, out);
  ws.spectrum(Eigen::Map<const Mat<double>, 0, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>>(
                  big.data() + 1, L, L, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>(4 * L, 2)),
              a);
  ws.spectrum(B.transpose(), b);
  ws.spectrum(C, c);
  ws.spectrum(D, d);
  const Mat<double> expected = grid.correlate_sum(grid.spectrum(A), grid.spectrum(Mat<double>(B.transpose())), grid.spectrum(C),
                                                  grid.spectrum(D));
  ws.correlate_sum(a, b, c, d, out);
  RC_ASSERT(out.rows() == L && out.cols() == L);
  RC_ASSERT((out.array() == expected.array()).all());
  ws.correlate_sum(a, b, c, d, out, true);  // C's last use: the product in C's array
  RC_ASSERT((out.array() == expected.array()).all());
}

// One pair (SISO): the first term formed in A's array (rows u and −u
// swapped in place, odd and even grid sizes), C then added in C's array,
// is correlate_sum bit for bit, also after release() freed the buffers.
RC_GTEST_PROP(Correlation2d, ReflectedSumIsBitIdenticalToCorrelateSum, ()) {
  const int L = *rc::gen::inRange(1, 12);
  const auto random = [L] { return random_square(L, 7.0); };
  const Mat<double> A = random(), B = random(), C = random(), D = random();
  const CorrelationGrid grid(L);
  const Mat<double> expected =
      grid.correlate_sum(grid.spectrum(A), grid.spectrum(B), grid.spectrum(C), grid.spectrum(D));
  CorrelationWorkspace ws(grid);
  for (int round = 0; round < 2; ++round) {
    Spectrum a, b, d;
    Mat<double> out;
    ws.spectrum(A, a);
    ws.spectrum(B, b);
    ws.reflect_product(a, b);
    ws.spectrum(C, b);  // B's array takes C
    ws.spectrum(D, d);
    ws.correlate_reflected(a, b, d, out);
    RC_ASSERT(out.rows() == L && out.cols() == L);
    RC_ASSERT((out.array() == expected.array()).all());
    ws.release();
  }
}

// The Newton step's transforms (rows and columns written out, split with a
// helper thread, zero rows skipped, inverses in place) against FFTW's 2-D
// plans (CorrelationGrid::spectrum, correlate_sum): bit for bit, with and
// without a helper, at the sizes of the barrier (grids 2L rounded up to a
// 2-3-5-smooth size, even and odd, L up to 601).
TEST(Correlation2d, SplitTransformsAreBitForBitThe2dPlans) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  HelperThread helper;
  for (const int L : {1, 2, 3, 7, 31, 60, 101, 200, 243, 400, 512, 601}) {  // from M = 1024 on the helper takes part
    SCOPED_TRACE(::testing::Message() << "L = " << L);
    std::vector<Mat<double>> X(4, Mat<double>(L, L));
    for (Mat<double>& x : X)
      for (Eigen::Index i = 0; i < x.size(); ++i) x.data()[i] = u(rng);
    const CorrelationGrid grid(L);
    const Mat<double> expected =
        grid.correlate_sum(grid.spectrum(X[0]), grid.spectrum(X[1]), grid.spectrum(X[2]), grid.spectrum(X[3]));
    for (HelperThread* h : {static_cast<HelperThread*>(nullptr), &helper}) {
      CorrelationWorkspace ws(grid);
      ws.set_helper(h);
      std::vector<Spectrum> s(4);
      for (int k = 0; k < 4; ++k) ws.spectrum(X[static_cast<size_t>(k)], s[static_cast<size_t>(k)]);
      Mat<double> out;
      ws.correlate_sum(s[0], s[1], s[2], s[3], out);
      EXPECT_TRUE(test::same_bits(out, expected));
      ws.reflect_product(s[0], s[1]);  // the SISO path: A's array takes the first term, C's the sum
      ws.correlate_reflected(s[0], s[2], s[3], out);
      EXPECT_TRUE(test::same_bits(out, expected));
    }
  }
}

TEST(Correlation2d, KnownValue) {
  // X = Y = [[1, 2], [3, 4]]: shift (0, 0) is Σ x² = 30; (1, 0): X(1,·)·Y(0,·) = 3 + 8;
  // (0, −1): Σ X(i, j−1) Y(i, j) = X(0,0)Y(0,1) + X(1,0)Y(1,1) = 2 + 12.
  Mat<double> X(2, 2);
  X << 1, 2, 3, 4;
  const CorrelationGrid grid(2);
  const Mat<double> plus = grid.correlate(grid.spectrum(X), grid.spectrum(X), +1);
  const Mat<double> minus = grid.correlate(grid.spectrum(X), grid.spectrum(X), -1);
  EXPECT_NEAR(plus(0, 0), 30, 1e-12);
  EXPECT_NEAR(plus(1, 0), 11, 1e-12);
  EXPECT_NEAR(minus(0, 1), 14, 1e-12);
}

}  // namespace
}  // namespace lpvid
