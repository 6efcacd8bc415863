#pragma once
/// A fixed bound (δ or d_max of Theorem 2.1) in one value with two views,
/// made once where the number enters the program: `exact` is the rational
/// the certificates carry, `approx` the double the solvers use. From text
/// (what the user typed), exact is that decimal read exactly and approx its
/// correctly rounded double; from a double, exact is the double's shortest
/// decimal text read exactly (the number the user sees printed).

#include <cmath>
#include <string_view>

#include "core/number_text.h"
#include "core/scalar.h"

namespace lpvid {

struct ExactBound {
  Rational exact{0};
  double approx = 0.0;

  ExactBound() = default;
  /// From a double: exact is its shortest decimal text (implicit, so that a
  /// computed bound can be assigned where a fixed one is expected). A
  /// non-finite double keeps exact = 0; BoundObjective::validate refuses it.
  ExactBound(double value)  // NOLINT(google-explicit-constructor)
      : exact(std::isfinite(value) ? rational_from_text(double_to_text(value)) : Rational(0)), approx(value) {}
  /// From the decimal text a user or a file gave (checked by the caller).
  static ExactBound from_text(std::string_view text) {
    ExactBound b;
    b.exact = rational_from_text(text);
    b.approx = double_from_text(text);
    return b;
  }
};

}  // namespace lpvid
