#pragma once
/// Powers with an integer exponent by repeated multiplication: the same bits
/// on every machine. std::pow goes through libm, whose x86-64 builds pick a
/// variant by the CPU at run time (with and without FMA), and those may
/// differ in the last bit; a power that feeds a fit or a printed figure must
/// not (docs/determinism.md).

namespace lpvid {

/// x^e for e >= 0 (x^0 = 1), by binary exponentiation.
inline double integer_power(double x, int e) {
  double result = 1.0, base = x;
  for (unsigned k = static_cast<unsigned>(e < 0 ? 0 : e); k > 0; k >>= 1) {
    if (k & 1u) result *= base;
    base *= base;
  }
  return result;
}

/// 10^e, for e in [-22, 22] correctly rounded (10^|e| is exact there, one
/// division rounds it), beyond that by repeated multiplication.
inline double double_power_of_ten(int e) {
  const double p = integer_power(10.0, e < 0 ? -e : e);
  return e < 0 ? 1.0 / p : p;
}

}  // namespace lpvid
