// column_gram (verify/certificate/column_gram.h) against the plain rational product TᵀT,
// on matrices with leading zero rows in some columns and mixed denominators.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include "support/gen_numbers.h"
#include "verify/certificate/column_gram.h"

namespace lpvid {
namespace {

RC_GTEST_PROP(VerifyColumnGram, EqualsThePlainProduct, ()) {
  const int rows = *rc::gen::inRange(1, 8), cols = *rc::gen::inRange(1, 6);
  Mat<Rational> T = *gen::rational_matrix(rows, cols, gen::small_rational());
  for (int j = 0; j < cols; ++j) T.col(j).head(*rc::gen::inRange(0, rows + 1)).setZero();
  if (*rc::gen::arbitrary<bool>()) T(0, 0) = Rational(1, 3) / Rational(1000000007);
  const Mat<Rational> expected = T.transpose() * T;
  RC_ASSERT(column_gram(T) == expected);
}

}  // namespace
}  // namespace lpvid
