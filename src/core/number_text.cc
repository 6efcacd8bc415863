#include "core/number_text.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include <gmp.h>
#include <mpfr.h>

#include "core/gmp_raii.h"
#include "core/input_error.h"
#include "core/limits.h"

namespace lpvid {
namespace {

/// Largest |decimal exponent| accepted: keeps 10^e representable without
/// letting a hostile file allocate gigabytes.
constexpr long kMaxExponent = 4000;

bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// The message for a number longer than InputLimits::max_number_digits.
std::string too_many_digits(long size) {
  return "a number of " + std::to_string(size) + " digits" +
         limit_hint(static_cast<long double>(input_limits().max_number_digits), "--max-digits");
}

/// Parsed pieces of "[+-]digits[.digits][(e|E)[+-]digits]".
struct Decimal {
  bool negative = false;
  std::string digits;  // integer and fraction digits concatenated
  long scale = 0;      // value = digits * 10^(exponent - fraction_digits)
};

std::optional<std::string> parse_decimal(std::string_view s, Decimal* out) {
  size_t i = 0;
  Decimal d;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) {
    d.negative = s[i] == '-';
    ++i;
  }
  size_t int_digits = 0, frac_digits = 0;
  while (i < s.size() && is_digit(s[i])) {
    d.digits += s[i++];
    ++int_digits;
  }
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && is_digit(s[i])) {
      d.digits += s[i++];
      ++frac_digits;
    }
  }
  if (int_digits + frac_digits == 0) return "'" + std::string(s) + "' is not a number";
  long exponent = 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    bool eneg = false;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) {
      eneg = s[i] == '-';
      ++i;
    }
    size_t start = i;
    while (i < s.size() && is_digit(s[i])) {
      if (exponent > kMaxExponent) return "exponent out of range in '" + std::string(s) + "'";
      exponent = exponent * 10 + (s[i] - '0');
      ++i;
    }
    if (i == start) return "missing exponent digits in '" + std::string(s) + "'";
    if (exponent > kMaxExponent) return "exponent out of range in '" + std::string(s) + "'";
    if (eneg) exponent = -exponent;
  }
  if (i != s.size()) return "unexpected character '" + std::string(1, s[i]) + "' in '" + std::string(s) + "'";
  d.scale = exponent - static_cast<long>(frac_digits);
  // The exact value has about digits + |scale| decimal digits (1e4000: 4001).
  const long size = static_cast<long>(int_digits + frac_digits) + std::labs(d.scale);
  if (size > input_limits().max_number_digits) return too_many_digits(size);
  if (out) *out = std::move(d);
  return std::nullopt;
}

std::optional<std::string> parse_integer(std::string_view s) {
  size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  if (i == s.size()) return "'" + std::string(s) + "' is not an integer";
  for (; i < s.size(); ++i)
    if (!is_digit(s[i])) return "'" + std::string(s) + "' is not an integer";
  return std::nullopt;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

Rational decimal_to_rational(const Decimal& d) {
  Mpz num, pow10;
  mpz_set_str(num.z, d.digits.c_str(), 10);
  mpz_ui_pow_ui(pow10.z, 10, static_cast<unsigned long>(d.scale < 0 ? -d.scale : d.scale));
  Mpq q;
  if (d.scale >= 0) {
    mpz_mul(num.z, num.z, pow10.z);
    mpq_set_z(q.q, num.z);
  } else {
    mpq_set_num(q.q, num.z);
    mpq_set_den(q.q, pow10.z);
    mpq_canonicalize(q.q);
  }
  if (d.negative) mpq_neg(q.q, q.q);
  return Rational(q.q);
}

Rational integer_to_rational(std::string_view s) {
  std::string t(s);
  if (!t.empty() && t[0] == '+') t.erase(0, 1);
  Mpz z;
  mpz_set_str(z.z, t.c_str(), 10);
  return mpz_to_rational(z.z);
}

}  // namespace

std::optional<std::string> number_text_problem(std::string_view text) {
  std::string_view s = trim(text);
  if (s.empty()) return std::string("empty number");
  size_t slash = s.find('/');
  if (slash == std::string_view::npos) return parse_decimal(s, nullptr);
  std::string_view p = trim(s.substr(0, slash)), q = trim(s.substr(slash + 1));
  if (auto e = parse_integer(p)) return "numerator: " + *e;
  if (auto e = parse_integer(q)) return "denominator: " + *e;
  if (const long size = static_cast<long>(p.size() + q.size()); size > input_limits().max_number_digits)
    return too_many_digits(size);
  if (q.find_first_not_of("+-0") == std::string_view::npos) return "zero denominator in '" + std::string(s) + "'";
  return std::nullopt;
}

Rational rational_from_text(std::string_view text) {
  if (auto e = number_text_problem(text)) throw InputError(*e);
  std::string_view s = trim(text);
  size_t slash = s.find('/');
  if (slash == std::string_view::npos) {
    Decimal d;
    parse_decimal(s, &d);
    return decimal_to_rational(d);
  }
  return integer_to_rational(trim(s.substr(0, slash))) / integer_to_rational(trim(s.substr(slash + 1)));
}

double double_from_text(std::string_view text) {
  if (auto e = number_text_problem(text)) throw InputError(*e);
  std::string s(trim(text));
  if (s.find('/') != std::string::npos) return nearest_double(rational_from_text(s));
  double x = std::strtod(s.c_str(), nullptr);
  if (!std::isfinite(x)) throw InputError("'" + s + "' overflows a double");
  return x;
}

double nearest_double(const Rational& q) {
  Mpfr f(53);
  mpfr_set_q(f.f, q.mpq(), MPFR_RNDN);
  return mpfr_get_d(f.f, MPFR_RNDN);
}

Mat<double> nearest_double(const Mat<Rational>& m) {
  Mat<double> d(m.rows(), m.cols());
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) d(i, j) = nearest_double(m(i, j));
  return d;
}

std::string rational_to_text(const Rational& q) {
  char* str = mpq_get_str(nullptr, 10, q.mpq());
  std::string out(str);
  void (*freefunc)(void*, size_t);
  mp_get_memory_functions(nullptr, nullptr, &freefunc);
  freefunc(str, out.size() + 1);
  return out;
}

std::string double_to_text(double x) {
  char buf[64];
  for (int prec = 1; prec <= 17; ++prec) {
    std::snprintf(buf, sizeof buf, "%.*g", prec, x);
    if (std::strtod(buf, nullptr) == x) return buf;
  }
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

Rational exact_rational_of_double(double x) {
  if (!std::isfinite(x)) throw InputError("not a finite number");
  return Rational(x);  // mpq_set_d is exact
}

std::string exact_decimal_or_fraction(const Rational& q) {
  constexpr unsigned long kMaxDecimals = 40;
  mpz_srcptr num = mpq_numref(q.mpq());
  mpz_srcptr den = mpq_denref(q.mpq());
  if (mpz_cmp_ui(den, 1) == 0) return rational_to_text(q);
  Mpz rest_owner(den);
  mpz_ptr rest = rest_owner.z;
  const unsigned long twos = mpz_scan1(rest, 0);
  mpz_tdiv_q_2exp(rest, rest, twos);
  unsigned long fives = 0;
  while (fives <= kMaxDecimals && mpz_divisible_ui_p(rest, 5)) {
    mpz_divexact_ui(rest, rest, 5);
    ++fives;
  }
  const unsigned long k = std::max(twos, fives);
  std::string out;
  if (mpz_cmp_ui(rest, 1) != 0 || k > kMaxDecimals) {
    out = rational_to_text(q);
  } else {
    // value = num / den = (num · 10^k / den) / 10^k, and 10^k / den = 2^(k-twos)·5^(k-fives).
    Mpz scaled_owner, factor_owner;
    mpz_ptr scaled = scaled_owner.z, factor = factor_owner.z;
    mpz_ui_pow_ui(factor, 5, k - fives);
    mpz_mul_2exp(factor, factor, k - twos);
    mpz_mul(scaled, num, factor);
    const bool negative = mpz_sgn(scaled) < 0;
    mpz_abs(scaled, scaled);
    std::vector<char> buf(mpz_sizeinbase(scaled, 10) + 2);
    mpz_get_str(buf.data(), 10, scaled);
    std::string digits(buf.data());
    if (digits.size() <= k) digits = std::string(k + 1 - digits.size(), '0') + digits;
    out = (negative ? "-" : "") + digits.substr(0, digits.size() - k) + "." + digits.substr(digits.size() - k);
  }
  return out;
}

}  // namespace lpvid
