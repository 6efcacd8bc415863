#include "toeplitz/toeplitz_gram.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "support/generators.h"
#include "toeplitz/signal_toeplitz.h"

namespace lpvid {
namespace {

// The O(n²) recursion equals the plain product T_aᵀ T_b exactly over ℚ.
RC_GTEST_PROP(ToeplitzGramProperty, EqualsPlainProduct, ()) {
  const int n = *rc::gen::inRange(1, 9);
  const int p = *rc::gen::inRange(1, 4);
  const Mat<Rational> a = *gen::rational_matrix(n, p, gen::small_rational());
  const Mat<Rational> b = *gen::rational_matrix(n, p, gen::small_rational());
  const Mat<Rational> plain = signal_toeplitz(a).transpose() * signal_toeplitz(b);
  RC_ASSERT(toeplitz_gram(a, b) == plain);
}

TEST(ToeplitzGramTest, KnownScalarCase) {
  // a = b = (1, 2): T = [1 0; 2 1], TᵀT = [5 2; 2 1].
  Mat<Rational> a(2, 1);
  a << Rational(1), Rational(2);
  Mat<Rational> G = toeplitz_gram(a, a);
  EXPECT_EQ(G(0, 0), Rational(5));
  EXPECT_EQ(G(0, 1), Rational(2));
  EXPECT_EQ(G(1, 0), Rational(2));
  EXPECT_EQ(G(1, 1), Rational(1));
}

}  // namespace
}  // namespace lpvid
