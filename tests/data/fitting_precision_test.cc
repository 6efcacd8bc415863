/// The precision at which the fits read data (data/fitting_precision.h):
/// checked against glibc's printf/strtod (another implementation than the
/// std::to_chars/std::from_chars it uses), and the property it exists for: a
/// sample moved by one ulp reads as the same number.

#include <cfloat>
#include <clocale>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/integer_power.h"
#include "data/fitting_precision.h"

namespace lpvid {
namespace {

/// x rounded to 10 significant digits by glibc: "%.9e" prints the exact
/// binary value correctly rounded, strtod reads it correctly rounded.
double glibc_rounding(double x) {
  char text[64];
  std::snprintf(text, sizeof text, "%.9e", x);
  return std::strtod(text, nullptr);
}

/// A finite double with a random sign, 53-bit mantissa and exponent in [-300, 300].
double random_double() {
  const auto mantissa = *rc::gen::inRange<long long>(1LL << 52, 1LL << 53);
  const int exponent = *rc::gen::inRange(-300, 300);
  const double x = std::ldexp(static_cast<double>(mantissa), exponent - 52);
  return *rc::gen::arbitrary<bool>() ? -x : x;
}

RC_GTEST_PROP(FittingPrecision, AgreesWithGlibcRounding, ()) {
  const double x = random_double();
  RC_ASSERT(at_fitting_precision(x) == glibc_rounding(x));
}

RC_GTEST_PROP(FittingPrecision, IsIdempotent, ()) {
  const double y = at_fitting_precision(random_double());
  RC_ASSERT(at_fitting_precision(y) == y);
}

RC_GTEST_PROP(FittingPrecision, ASampleMovedByOneUlpReadsTheSame, ()) {
  // a sample as a measurement writes it: at most 9 significant digits
  const auto digits = *rc::gen::inRange(1, 10);
  const auto mantissa = *rc::gen::inRange<long long>(1, static_cast<long long>(integer_power(10.0, digits)));
  const int exponent = *rc::gen::inRange(-12, 12);
  const std::string text = std::to_string(mantissa) + "e" + std::to_string(exponent);
  const double x = std::strtod(text.c_str(), nullptr);
  RC_ASSERT(at_fitting_precision(x) == x);
  RC_ASSERT(at_fitting_precision(std::nextafter(x, INFINITY)) == x);
  RC_ASSERT(at_fitting_precision(std::nextafter(x, -INFINITY)) == x);
}

TEST(FittingPrecision, SpecialValuesAndTheMeasuredRecordsDigits) {
  EXPECT_EQ(at_fitting_precision(0.0), 0.0);
  EXPECT_TRUE(std::isinf(at_fitting_precision(INFINITY)));
  EXPECT_TRUE(std::isnan(at_fitting_precision(NAN)));
  // 1.797693135e308 is beyond the largest double: a finite sample stays finite, as it was
  EXPECT_TRUE(std::isinf(glibc_rounding(DBL_MAX)));
  EXPECT_EQ(at_fitting_precision(DBL_MAX), DBL_MAX);
  EXPECT_EQ(at_fitting_precision(5.205), 5.205);  // the cascaded tanks record's first yEst
  EXPECT_EQ(at_fitting_precision(1.0 / 3.0), 0.3333333333);
  EXPECT_EQ(at_fitting_precision(2.0 / 3.0), 0.6666666667);
}

TEST(FittingPrecision, AnExperimentKeepsItsRecordsAndRoundsEverySample) {
  Experiment<double> e;
  e.source = "x.csv";
  e.u = Mat<double>::Constant(3, 1, 1.0 / 3.0);
  e.y = Mat<double>::Constant(3, 2, 2.0 / 3.0);
  e.rho = Mat<double>::Constant(3, 1, 0.1 + 0.2);  // 0.30000000000000004
  e.records = {1, 2};
  e.record_x0 = {Vec<double>::Constant(1, 1.0 / 7.0), Vec<double>()};
  const Experiment<double> r = at_fitting_precision(e);
  EXPECT_EQ(r.source, "x.csv");
  EXPECT_EQ(r.records, e.records);
  EXPECT_TRUE((r.u.array() == 0.3333333333).all());
  EXPECT_TRUE((r.y.array() == 0.6666666667).all());
  EXPECT_TRUE((r.rho.array() == 0.3).all());
  EXPECT_EQ(r.record_x0[0](0), 0.1428571429);
  EXPECT_EQ(r.record_x0[1].size(), 0);
}

TEST(IntegerPower, ExactWhereTheProductIsAndCorrectlyRoundedPowersOfTen) {
  EXPECT_EQ(integer_power(3.0, 0), 1.0);
  EXPECT_EQ(integer_power(3.0, 5), 243.0);
  EXPECT_EQ(integer_power(-2.0, 3), -8.0);
  EXPECT_EQ(integer_power(0.5, 10), 1.0 / 1024.0);
  for (int e = -22; e <= 22; ++e) {  // 10^|e| is exact up to 22: one correctly rounded division
    char text[16];
    std::snprintf(text, sizeof text, "1e%d", e);
    EXPECT_EQ(double_power_of_ten(e), std::strtod(text, nullptr)) << e;
  }
}

}  // namespace
}  // namespace lpvid
