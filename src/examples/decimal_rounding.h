#pragma once
/// Rounding to a fixed number of decimals, exactly, for generated data sets:
/// the written CSV text then IS the data (no hidden binary digits).

#include <cmath>
#include <gmp.h>

#include "core/gmp_raii.h"
#include "core/scalar.h"

namespace lpvid {

/// x rounded to `digits` decimals, as an exact rational.
inline Rational round_decimal(double x, int digits) {
  const double scale = std::pow(10.0, digits);
  const long long k = std::llround(x * scale);
  return Rational(static_cast<long>(k)) / Rational(static_cast<long>(std::llround(scale)));
}

/// floor(q·10^digits + 1/2) / 10^digits, exactly (ties towards +∞).
inline Rational round_decimal(const Rational& q, int digits) {
  Rational scale(1);
  for (int i = 0; i < digits; ++i) scale *= 10;
  const Rational s = q * scale;
  Mpz num(mpq_numref(s.mpq())), den(mpq_denref(s.mpq())), quo;
  mpz_mul_ui(num.z, num.z, 2);
  mpz_add(num.z, num.z, den.z);  // floor((2·num + den) / (2·den)) = floor(s + 1/2)
  mpz_mul_ui(den.z, den.z, 2);
  mpz_fdiv_q(quo.z, num.z, den.z);
  return mpz_to_rational(quo.z) / scale;
}

}  // namespace lpvid
