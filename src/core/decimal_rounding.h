#pragma once
/// Decimal rounding to exact rationals: how solver doubles become the short
/// rational numbers a certificate states (SPEC §7) and how exact bounds are
/// rounded outwards (δ², d_max² up; a lower end down), all in one place.

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
/// √q rounded up to a double (for display only).
double sqrt_up(const Rational& q);

}  // namespace lpvid
