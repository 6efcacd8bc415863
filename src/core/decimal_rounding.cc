#include "core/decimal_rounding.h"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "core/gmp_raii.h"
#include "core/number_text.h"

namespace lpvid {

Rational power_of_ten(int e) {
  Mpz p;
  mpz_ui_pow_ui(p.z, 10, static_cast<unsigned long>(std::abs(e)));
  Mpq q;
  if (e >= 0) {
    mpq_set_z(q.q, p.z);
  } else {
    mpq_set_den(q.q, p.z);  // 1/10^|e|: the numerator of a fresh mpq is 0, set it to 1
    mpz_set_ui(mpq_numref(q.q), 1);
  }
  return Rational(q.q);
}

Rational round_to_digits(double x, int digits) {
  if (!std::isfinite(x)) throw std::invalid_argument("round_to_digits: not finite");
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*e", digits - 1, x);
  return rational_from_text(buf);
}

namespace {

/// q > 0 rounded to `digits` significant decimal digits, towards +∞ (up) or 0.
Rational round_directed(const Rational& q, int digits, bool up) {
  // e = floor(log10 q) estimated from the double (from the bit lengths when
  // q is outside the double range), then corrected exactly.
  const double d = nearest_double(q);
  const double log10_q =
      d > 0 && std::isfinite(d)
          ? std::log10(d)
          : (static_cast<double>(mpz_sizeinbase(mpq_numref(q.mpq()), 2)) -
             static_cast<double>(mpz_sizeinbase(mpq_denref(q.mpq()), 2))) * 0.30102999566398120;
  int e = static_cast<int>(std::floor(log10_q));
  while (power_of_ten(e) > q) --e;
  while (power_of_ten(e + 1) <= q) ++e;
  const Rational unit = power_of_ten(e - digits + 1);
  const Rational s = q / unit;  // in [10^(digits−1), 10^digits)
  Mpz c;
  if (up)
    mpz_cdiv_q(c.z, mpq_numref(s.mpq()), mpq_denref(s.mpq()));
  else
    mpz_fdiv_q(c.z, mpq_numref(s.mpq()), mpq_denref(s.mpq()));
  return mpz_to_rational(c.z) * unit;
}

}  // namespace

Rational round_up_to_digits(const Rational& q, int digits) {
  if (q == 0) return Rational(0);
  if (q < 0) throw std::invalid_argument("round_up_to_digits: negative value");
  return round_directed(q, digits, true);
}

Rational round_down_to_digits(const Rational& q, int digits) {
  if (q == 0) return Rational(0);
  return q > 0 ? round_directed(q, digits, false) : -round_directed(-q, digits, true);
}

double double_up(const Rational& q) {
  double d = nearest_double(q);
  if (d == -INFINITY) return -DBL_MAX;
  if (std::isfinite(d) && Rational(d) < q) d = std::nextafter(d, INFINITY);
  return d;
}

double double_down(const Rational& q) { return -double_up(-q); }

double sqrt_up(const Rational& q) {
  double s = std::sqrt(nearest_double(q));
  while (Rational(s) * Rational(s) < q) s = std::nextafter(s, INFINITY);
  return s;
}

double sqrt_down(const Rational& q) {
  if (q <= 0) return 0.0;
  double s = std::sqrt(nearest_double(q));
  while (s > 0 && Rational(s) * Rational(s) > q) s = std::nextafter(s, 0.0);
  return s;
}

std::string upper_text(const Rational& q, int digits) {
  // a negative q: −(|q| rounded down) is the smallest such decimal ≥ q
  return exact_decimal_or_fraction(q < 0 ? Rational(-round_down_to_digits(-q, digits)) : round_up_to_digits(q, digits));
}

std::string lower_text(const Rational& q, int digits) { return exact_decimal_or_fraction(round_down_to_digits(q, digits)); }

std::string upper_sqrt_text(const Rational& q2, int digits) { return upper_text(Rational(sqrt_up(q2)), digits); }

std::string lower_sqrt_text(const Rational& q2, int digits) { return lower_text(Rational(sqrt_down(q2)), digits); }

}  // namespace lpvid
