#pragma once
/// Small helpers shared by the certificate checkers (certificate_check.cc,
/// dual_check.cc): a rejected verdict and a short decimal for messages.

#include <sstream>
#include <string>

#include "core/scalar.h"
#include "verify/certificate_check.h"

namespace lpvid {

/// A rational shown as a decimal with `precision` significant digits (messages only).
inline std::string approx_text(const Rational& q, int precision = 6) {
  std::ostringstream o;
  o.precision(precision);
  o << nearest_double(q);
  return o.str();
}

/// The verdict "the claim does not hold", with the reason and what was checked.
inline CertificateVerdict invalid_verdict(std::string reason, std::string details = "") {
  return {false, std::move(reason), std::move(details), ""};
}

}  // namespace lpvid
