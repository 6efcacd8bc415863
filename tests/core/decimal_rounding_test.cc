// Decimal rounding to exact rationals (core/decimal_rounding.h): the unit of
// the last kept digit is found here independently, by exact repeated
// multiplication, and the rounded value is checked to be on that grid, on the
// right side of q and within one unit of it.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "core/decimal_rounding.h"

namespace lpvid {
namespace {

Rational naive_power_of_ten(int e) {
  Rational r(1);
  for (int i = 0; i < (e < 0 ? -e : e); ++i) r *= 10;
  return e >= 0 ? r : Rational(1) / r;
}

/// 10^(e − digits + 1) where 10^e ≤ q < 10^(e+1) (q > 0).
Rational last_digit_unit(const Rational& q, int digits) {
  int e = 0;
  Rational p(1);
  while (p > q) p /= 10, --e;
  while (p * 10 <= q) p *= 10, ++e;
  return naive_power_of_ten(e - digits + 1);
}

bool is_integer(const Rational& q) { return q.denominator() == 1; }

TEST(DecimalRounding, PowersOfTenAreExact) {
  for (int e = -60; e <= 60; ++e) EXPECT_EQ(power_of_ten(e), naive_power_of_ten(e)) << e;
  EXPECT_EQ(power_of_ten(-4000) * power_of_ten(4000), Rational(1));
}

TEST(DecimalRounding, DoublesRoundToTheirShortDecimal) {
  EXPECT_EQ(round_to_digits(0.1, 12), Rational(1, 10));
  EXPECT_EQ(round_to_digits(-2.5e-3, 12), Rational(-25, 10000));
  EXPECT_EQ(round_to_digits(1.0 / 3.0, 3), Rational(333, 1000));
  EXPECT_THROW(round_to_digits(std::nan(""), 12), std::invalid_argument);
}

TEST(DecimalRounding, FarOutsideTheDoubleRange) {
  // 10^-5000/3 is 0 as a double: the decade comes from the bit lengths.
  const Rational q = power_of_ten(-5000) / 3;
  EXPECT_EQ(round_up_to_digits(q, 2), Rational(34) * power_of_ten(-5002));
  EXPECT_EQ(round_down_to_digits(q, 2), Rational(33) * power_of_ten(-5002));
  EXPECT_EQ(round_up_to_digits(Rational(3) * power_of_ten(4000), 5), Rational(3) * power_of_ten(4000));
}

RC_GTEST_PROP(DecimalRoundingProperty, UpAndDownBracketTheValueOnItsDigitGrid, ()) {
  const int a = *rc::gen::inRange(1, 1000000);
  const int b = *rc::gen::inRange(1, 1000000);
  const int s = *rc::gen::inRange(-300, 300);
  const int digits = *rc::gen::inRange(1, 16);
  const Rational q = Rational(a) / Rational(b) * naive_power_of_ten(s);
  const Rational unit = last_digit_unit(q, digits);
  const Rational up = round_up_to_digits(q, digits);
  const Rational down = round_down_to_digits(q, digits);
  RC_ASSERT(is_integer(up / unit));
  RC_ASSERT(is_integer(down / unit));
  RC_ASSERT(up >= q);
  RC_ASSERT(up - unit < q);
  RC_ASSERT(down <= q);
  RC_ASSERT(down + unit > q);
  RC_ASSERT(round_down_to_digits(-q, digits) == -up);
}

}  // namespace
}  // namespace lpvid
