#pragma once
/// Small helpers shared by the certificate checkers (certificate_check.cc,
/// dual_check.cc, c1_*.cc): a rejected verdict, a short decimal and the
/// PSD path for messages.

#include <sstream>
#include <string>

#include "core/scalar.h"
#include "verify/certificate/certificate_verdict.h"
#include "verify/psd/exact_psd.h"

namespace lpvid {

/// A rational shown as a decimal with `precision` significant digits (messages only).
inline std::string approx_text(const Rational& q, int precision = 6) {
  std::ostringstream o;
  o.precision(precision);
  o << nearest_double(q);
  return o.str();
}

/// "PSD (exact elimination)" etc.: the verdict word and the path that decided.
inline std::string psd_note(const PsdResult& r) {
  return std::string(verdict_word(r.verdict)) + " (" +
         (r.decided_by_filter ? "floating filter with rigorous bound" : "exact elimination") + ")";
}

/// The verdict "the claim does not hold", with the reason and what was checked.
inline CertificateVerdict invalid_verdict(std::string reason, std::string details = "") {
  return CertificateVerdict::invalid(std::move(reason), std::move(details));
}

}  // namespace lpvid
