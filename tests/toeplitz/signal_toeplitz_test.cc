#include "toeplitz/signal_toeplitz.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "support/gen_models.h"

namespace lpvid {
namespace {

using gen::exactly_equal;

/// Truncated convolution (a∗b)_k = Σ_{i=0..k} a_i b_{k−i}, written out
/// independently of any Toeplitz matrix. a is n × p, b is n × 1.
Mat<Rational> convolution(const Mat<Rational>& a, const Mat<Rational>& b) {
  Mat<Rational> c = Mat<Rational>::Zero(a.rows(), a.cols());
  for (Eigen::Index k = 0; k < a.rows(); ++k)
    for (Eigen::Index i = 0; i <= k; ++i) c.row(k) += b(k - i, 0) * a.row(i);
  return c;
}

TEST(SignalToeplitzTest, SmallExampleByHand) {
  Mat<Rational> h(3, 2);
  h << 1, 2, 3, 4, 5, 6;
  Mat<Rational> expected(6, 3);
  expected << 1, 0, 0,  //
      2, 0, 0,          //
      3, 1, 0,          //
      4, 2, 0,          //
      5, 3, 1,          //
      6, 4, 2;
  EXPECT_TRUE(exactly_equal(signal_toeplitz(h), expected));
  Vec<Rational> s(6);
  s << 1, 2, 3, 4, 5, 6;
  EXPECT_TRUE(exactly_equal(stack_rows(h), s));
}

TEST(SignalToeplitzTest, UnstackRejectsBadLength) {
  Vec<Rational> v(5);
  v.setZero();
  EXPECT_THROW(unstack_rows(v, 2), std::invalid_argument);
  EXPECT_THROW(unstack_rows(v, 0), std::invalid_argument);
}

// Eq. (3): block (k, j) = h_{k−j} for k ≥ j, zero above the diagonal.
RC_GTEST_PROP(SignalToeplitzProperty, BlocksAreDelayedSamples, ()) {
  const int n = *gen::sized_int(1, 8);
  const int p = *gen::sized_int(1, 3);
  const Mat<Rational> h = *gen::rational_matrix(n, p, gen::rational_entry(9, 9));
  const Mat<Rational> T = signal_toeplitz(h);
  RC_ASSERT(T.rows() == n * p);
  RC_ASSERT(T.cols() == n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j) {
      const Mat<Rational> block = T.block(k * p, j, p, 1);
      if (k >= j)
        RC_ASSERT(exactly_equal(block, h.row(k - j).transpose()));
      else
        RC_ASSERT(exactly_equal(block, Mat<Rational>::Zero(p, 1)));
    }
}

// T_a · T_b = T_{a∗b}: the Toeplitz matrices of causal signals multiply like
// their convolution (exact over ℚ). a may be vector valued (p ≥ 1), b scalar.
RC_GTEST_PROP(SignalToeplitzProperty, ProductOfSignalToeplitzIsToeplitzOfConvolution, ()) {
  const int n = *gen::sized_int(1, 8);
  const int p = *gen::sized_int(1, 2);
  const Mat<Rational> a = *gen::rational_matrix(n, p, gen::rational_entry(9, 9));
  const Mat<Rational> b = *gen::rational_matrix(n, 1, gen::rational_entry(9, 9));
  const Mat<Rational> lhs = signal_toeplitz(a) * signal_toeplitz(b);
  RC_ASSERT(exactly_equal(lhs, signal_toeplitz(convolution(a, b))));
  if (p == 1) {  // scalar signals commute
    RC_ASSERT(exactly_equal(lhs, signal_toeplitz(b) * signal_toeplitz(a)));
  }
}

// stack_rows / unstack_rows are inverse, and column 0 of T_h is stack(h);
// T_h · v = stack(h ∗ v) for any scalar signal v.
RC_GTEST_PROP(SignalToeplitzProperty, StackingMatchesFirstColumnAndProduct, ()) {
  const int n = *gen::sized_int(1, 8);
  const int p = *gen::sized_int(1, 3);
  const Mat<Rational> h = *gen::rational_matrix(n, p, gen::rational_entry(9, 9));
  const Vec<Rational> s = stack_rows(h);
  RC_ASSERT(exactly_equal(unstack_rows(s, p), h));
  const Mat<Rational> T = signal_toeplitz(h);
  RC_ASSERT(exactly_equal(T.col(0), s));
  const Mat<Rational> v = *gen::rational_matrix(n, 1, gen::rational_entry(9, 9));
  RC_ASSERT(exactly_equal(T * stack_rows(v), stack_rows(convolution(h, v))));
}

TEST(SignalToeplitzTest, DoubleAndRationalAgreeOnIntegers) {
  Mat<Rational> h(4, 1);
  h << 1, -2, 3, 0;
  const Mat<double> hd = gen::to_double_matrix(h);
  EXPECT_TRUE(exactly_equal(gen::exact_matrix(signal_toeplitz(hd)), signal_toeplitz(h)));
}

}  // namespace
}  // namespace lpvid
