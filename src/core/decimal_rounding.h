#pragma once
/// Decimal rounding to exact rationals: how solver doubles become the short
/// rational numbers a certificate states (docs/design.md §10.3) and how exact bounds are
/// rounded outwards (δ², d_max² up; a lower end down), all in one place.

#include <string>

#include "core/scalar.h"

namespace lpvid {

/// 10^e as an exact rational (e may be negative).
Rational power_of_ten(int e);
/// x rounded to `digits` significant decimal digits, as an exact rational.
Rational round_to_digits(double x, int digits);
/// The smallest decimal with `digits` significant digits that is ≥ q (q ≥ 0).
Rational round_up_to_digits(const Rational& q, int digits);
/// The largest decimal with `digits` significant digits that is ≤ q.
Rational round_down_to_digits(const Rational& q, int digits);
/// The smallest double ≥ q and the largest double ≤ q (the ends of a certified
/// interval in a JSON report: printed = certified, as for the text below).
/// ±∞ only when no finite double lies on that side of q.
double double_up(const Rational& q);
double double_down(const Rational& q);
/// √q rounded up to a double (for display only).
double sqrt_up(const Rational& q);
/// √q rounded down to a double (q ≥ 0; for display only).
double sqrt_down(const Rational& q);

/// Printed = certified: the text of an UPPER end q (q ≥ 0) with `digits`
/// significant digits, never below q (the smallest such decimal ≥ q), and of
/// a LOWER end, never above it. A bound printed to the nearest could fall on
/// the wrong side of what was proved (0.00954801 for a certified
/// 0.0095480146).
std::string upper_text(const Rational& q, int digits = 6);
std::string lower_text(const Rational& q, int digits = 6);
/// The same for a displayed square root of a certified square (δ from δ²,
/// d_max from d_max²): upper_text of a double ≥ √q, lower_text of one ≤ √q.
std::string upper_sqrt_text(const Rational& q2, int digits = 6);
std::string lower_sqrt_text(const Rational& q2, int digits = 6);

}  // namespace lpvid
