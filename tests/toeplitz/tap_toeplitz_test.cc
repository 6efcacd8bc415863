// toeplitz/tap_toeplitz.h: the fast products against the dense block Toeplitz
// matrix built entry by entry from its definition T(a·ny + i, b·nz + j) =
// h_ij(a − b) (tap_toeplitz_dense) and Eigen's plain products.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include "toeplitz/tap_toeplitz.h"

namespace lpvid {
namespace {


Mat<double> random(Eigen::Index r, Eigen::Index c) {
  Mat<double> m(r, c);
  for (Eigen::Index i = 0; i < r; ++i)
    for (Eigen::Index j = 0; j < c; ++j) m(i, j) = *rc::gen::inRange(-1000, 1001) / 100.0;
  return m;
}

RC_GTEST_PROP(TapToeplitz, GramAndProductEqualTheDenseOnes, ()) {
  const Eigen::Index L = *rc::gen::inRange(1, 12), ny = *rc::gen::inRange(1, 4), nz = *rc::gen::inRange(1, 4);
  const Mat<double> taps = random(L, ny * nz);
  const Mat<double> T = tap_toeplitz_dense(taps, ny, nz);
  const Mat<double> G = T * T.transpose();
  RC_ASSERT((tap_gram(taps, ny, nz) - G).cwiseAbs().maxCoeff() <= 1e-9 * (1.0 + G.cwiseAbs().maxCoeff()));
  // up to 20 rows: blocks of 8 and a remainder
  const Mat<double> X = random(*rc::gen::inRange(1, 21), L * ny), Y = random(L * ny, *rc::gen::inRange(1, 21));
  const Mat<double> XT = X * T, TtY = T.transpose() * Y;
  const ToeplitzProduct times_T(taps, ny, nz);
  const Mat<double> fast = times_T.right(X);
  RC_ASSERT((fast - XT).cwiseAbs().maxCoeff() <= 1e-9 * (1.0 + XT.cwiseAbs().maxCoeff()));
  Mat<double> left;
  times_T.left_into(Y, left);
  RC_ASSERT((left - TtY).cwiseAbs().maxCoeff() <= 1e-9 * (1.0 + TtY.cwiseAbs().maxCoeff()));
  for (Eigen::Index k = 0; k < X.rows(); ++k)  // rows gathered together are transformed alone: bit for bit
    RC_ASSERT((times_T.right(Mat<double>(X.row(k))).array() == fast.row(k).array()).all());
}

// The reusing calls of a solver's Newton steps (new taps on the same plans,
// results into existing matrices, Tᵀ·Y gathered column-wise) give the numbers
// of a fresh ToeplitzProduct, bit for bit.
RC_GTEST_PROP(TapToeplitz, ReusedProductIsBitIdenticalToAFreshOne, ()) {
  const Eigen::Index L = *rc::gen::inRange(1, 12), ny = *rc::gen::inRange(1, 4), nz = *rc::gen::inRange(1, 4);
  const Mat<double> taps = random(L, ny * nz), X = random(*rc::gen::inRange(1, 6), L * ny), Y = random(L * ny, 3);
  ToeplitzProduct reused(random(L, ny * nz), ny, nz);
  Mat<double> out = random(2, 2);
  reused.right_into(X, out);
  reused.set_taps(taps);
  const ToeplitzProduct fresh(taps, ny, nz);
  reused.right_into(X, out);
  RC_ASSERT((out.array() == fresh.right(X).array()).all());
  reused.left_into(Y, out);
  const Mat<double> expected = fresh.right(Y.transpose()).transpose();
  RC_ASSERT(out.rows() == expected.rows() && out.cols() == expected.cols());
  RC_ASSERT((out.array() == expected.array()).all());
  Mat<double> G = random(1, 1);
  tap_gram_into(taps, ny, nz, G);
  RC_ASSERT((G.array() == tap_gram(taps, ny, nz).array()).all());
}

}  // namespace
}  // namespace lpvid
