// Decimal rounding to exact rationals (core/decimal_rounding.h): the unit of
// the last kept digit is found here independently, by exact repeated
// multiplication, and the rounded value is checked to be on that grid, on the
// right side of q and within one unit of it.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cfloat>
#include <cmath>

#include "core/decimal_rounding.h"
#include "core/number_text.h"

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

// Printed = certified: the text of an upper end, read back exactly, is never
// below the certified value, that of a lower end never above, and each has at
// most the requested significant digits (on the digit grid of round_*).
RC_GTEST_PROP(DecimalRoundingProperty, PrintedEndsAreOnTheSafeSide, ()) {
  const int a = *rc::gen::inRange(1, 1000000);
  const int b = *rc::gen::inRange(1, 1000000);
  const int s = *rc::gen::inRange(-30, 30);
  const int digits = *rc::gen::inRange(1, 10);
  const bool negative = *rc::gen::arbitrary<bool>();
  const Rational q = (negative ? -1 : 1) * Rational(a) / Rational(b) * naive_power_of_ten(s);
  const Rational up = rational_from_text(upper_text(q, digits)), down = rational_from_text(lower_text(q, digits));
  RC_ASSERT(up >= q);
  RC_ASSERT(down <= q);
  const Rational unit = last_digit_unit(q < 0 ? Rational(-q) : q, digits);
  RC_ASSERT(is_integer(up / unit) || is_integer(up / (unit * 10)));  // a carry may add a digit (9.99 -> 10.0)
  RC_ASSERT(up - down <= unit);
  if (q >= 0) {
    // the displayed square roots: (printed δ)² ≥ δ² ≥ (printed lower)²
    const Rational r_up = rational_from_text(upper_sqrt_text(q, digits));
    const Rational r_down = rational_from_text(lower_sqrt_text(q, digits));
    RC_ASSERT(r_up * r_up >= q);
    RC_ASSERT(r_down >= 0);
    RC_ASSERT(r_down * r_down <= q);
  }
}

// The case of the report: a certified 0.0095480146 printed to the nearest
// with 6 digits was 0.00954801, below what was proved.
// double_up / double_down: the neighbouring doubles bracket q exactly.
RC_GTEST_PROP(DecimalRoundingProperty, DirectedDoublesBracketTheValue, ()) {
  const long p = *rc::gen::inRange<long>(-1000000000, 1000000000);
  const long q = *rc::gen::inRange<long>(1, 1000000000);
  const int e = *rc::gen::inRange(-1100, 1100);
  const Rational x = Rational(p) / Rational(q) * (e >= 0 ? naive_power_of_ten(e / 4) : Rational(1) / naive_power_of_ten(-e / 4));
  const double up = double_up(x), down = double_down(x);
  RC_ASSERT(std::isfinite(up) && std::isfinite(down));
  RC_ASSERT(Rational(up) >= x);
  RC_ASSERT(Rational(std::nextafter(up, -INFINITY)) < x);
  RC_ASSERT(Rational(down) <= x);
  RC_ASSERT(Rational(std::nextafter(down, INFINITY)) > x);
}

TEST(DecimalRounding, DirectedDoublesBeyondTheRange) {
  const Rational huge = naive_power_of_ten(400);
  EXPECT_EQ(double_up(huge), INFINITY);
  EXPECT_EQ(double_down(huge), DBL_MAX);
  EXPECT_EQ(double_up(-huge), -DBL_MAX);
  EXPECT_EQ(double_down(-huge), -INFINITY);
  EXPECT_EQ(double_up(Rational(1, 3)), std::nextafter(1.0 / 3, 1.0));
  EXPECT_EQ(double_down(Rational(1, 3)), 1.0 / 3);
}

TEST(DecimalRounding, TheReportedCaseRoundsUp) {
  const Rational certified = rational_from_text("0.0095480146");
  EXPECT_EQ(upper_text(certified), "0.00954802");
  // and a lower end 9.11597968e-05 printed to the nearest was 9.11598e-05, above it
  EXPECT_EQ(rational_from_text(lower_text(rational_from_text("0.0000911597968"))), Rational(911597) * power_of_ten(-10));
}

}  // namespace
}  // namespace lpvid
