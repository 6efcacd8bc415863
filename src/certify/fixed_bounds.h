#pragma once
/// A fixed δ or d_max (Theorem 2.1 at given bounds) exactly: the decimal
/// text the user gave, read as a rational, else the double's shortest
/// decimal text (the number the user sees printed). The one place where a
/// fixed bound's text and double become the certificate's rational.

#include <string>

#include "certify/certify.h"
#include "core/number_text.h"

namespace lpvid {

/// `text` exactly when given, else `value`'s shortest decimal text.
inline Rational exact_fixed_bound(const std::string& text, double value) {
  return rational_from_text(text.empty() ? double_to_text(value) : text);
}

/// The fixed δ of `o` (o.objective.delta_fixed()) exactly.
inline Rational fixed_delta(const CertifyOptions& o) { return exact_fixed_bound(o.fixed_delta_text, o.objective.delta); }

/// The fixed d_max of `o` (o.objective.dmax_fixed()) exactly.
inline Rational fixed_dmax(const CertifyOptions& o) { return exact_fixed_bound(o.fixed_dmax_text, o.objective.dmax); }

}  // namespace lpvid
