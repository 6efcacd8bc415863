#include "core/number_text.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/input_error.h"

namespace lpvid {
namespace {

TEST(NumberTextTest, DecimalsAreExact) {
  EXPECT_EQ(rational_from_text("0.1"), Rational(1) / Rational(10));
  EXPECT_EQ(rational_from_text("-2.5e-3"), Rational(-1) / Rational(400));
  EXPECT_EQ(rational_from_text("1E3"), Rational(1000));
  EXPECT_EQ(rational_from_text("1/3"), Rational(1) / Rational(3));
  EXPECT_EQ(rational_from_text(" -4/6 "), Rational(-2) / Rational(3));
  EXPECT_EQ(rational_from_text(".5"), Rational(1) / Rational(2));
  EXPECT_EQ(rational_from_text("5."), Rational(5));
}

TEST(NumberTextTest, RejectsNonNumbers) {
  for (const char* bad : {"", "nan", "NaN", "inf", "-inf", "0x10", "1e", "1.2.3", "1/0", "1/-0", "1/2/3",
                          "abc", "1,5", "--1", "1e99999", "1/2.5", "+", "."}) {
    EXPECT_THROW(rational_from_text(bad), InputError) << bad;
    EXPECT_THROW(double_from_text(bad), InputError) << bad;
  }
}

TEST(NumberTextTest, DoubleIsNearest) {
  EXPECT_EQ(double_from_text("0.1"), 0.1);
  EXPECT_EQ(double_from_text("1/3"), 1.0 / 3.0);
}

RC_GTEST_PROP(NumberTextProperty, RationalTextRoundTrips, (long p, long q)) {
  RC_PRE(q != 0);
  Rational r = Rational(p) / Rational(q);
  RC_ASSERT(rational_from_text(rational_to_text(r)) == r);
}

RC_GTEST_PROP(NumberTextProperty, DoubleTextRoundTrips, (double x)) {
  RC_PRE(std::isfinite(x));
  RC_ASSERT(double_from_text(double_to_text(x)) == x);
  // The exact value of the printed decimal rounds back to x as well.
  RC_ASSERT(nearest_double(rational_from_text(double_to_text(x))) == x);
  RC_ASSERT(nearest_double(exact_rational_of_double(x)) == x);
}

}  // namespace
}  // namespace lpvid
