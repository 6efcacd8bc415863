#pragma once
/// Numbers as text (docs/design.md §4, §10, §11).
///
/// Data and model files hold numbers as decimal text ("0.1", "-2.5e-3") or as
/// exact fractions ("1/3"). The exact path reads them as exact rationals
/// (0.1 is 1/10, not the nearest double); the floating path reads the same
/// text as the nearest double. Anything else (empty, NaN, inf, hex, trailing
/// junk, zero denominator, absurd exponent) is rejected.

#include <optional>
#include <string>
#include <string_view>

#include "core/scalar.h"

namespace lpvid {

/// Why a text is not a number, or std::nullopt when it is one.
std::optional<std::string> number_text_problem(std::string_view text);

/// Exact value of a decimal or p/q text. Throws InputError (no location) if
/// the text is not a number; callers add file/line/field.
Rational rational_from_text(std::string_view text);

/// Nearest double of the same text (decimal: correctly rounded by strtod;
/// p/q: the exact rational rounded once).
double double_from_text(std::string_view text);

/// Reads `text` as the scalar T (double or Rational).
template <typename T>
T number_from_text(std::string_view text);

template <>
inline double number_from_text<double>(std::string_view text) { return double_from_text(text); }
template <>
inline Rational number_from_text<Rational>(std::string_view text) { return rational_from_text(text); }

/// The double nearest to q (round-to-nearest-even, via MPFR). Unlike
/// CGAL::to_double (which truncates), this is correctly rounded.
double nearest_double(const Rational& q);

/// Entrywise nearest_double of a rational matrix.
Mat<double> nearest_double(const Mat<Rational>& m);

/// Exact text of a rational: "p/q", or "p" when q = 1. Round-trips exactly.
std::string rational_to_text(const Rational& q);

/// Shortest exact text of a rational: "p" for an integer, a terminating
/// decimal when the denominator is 2^a·5^b (at most 40 decimals), else "p/q".
std::string exact_decimal_or_fraction(const Rational& q);

/// Shortest decimal text that reads back as the same double ("%.17g" style,
/// but shortest). Its exact rational is the double's exact binary value only
/// if you print enough digits; use exact_rational_of_double for that.
std::string double_to_text(double x);

/// The exact rational value of a finite double (every double is a dyadic
/// rational). Throws InputError for NaN/inf.
Rational exact_rational_of_double(double x);

}  // namespace lpvid
