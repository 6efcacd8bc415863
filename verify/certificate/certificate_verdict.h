#pragma once
/// The verdict of an exact certificate check (certificate_check.h): the claim
/// holds, or it does not with the reason. Made only by the two named
/// constructors, so that no caller spells the fields positionally.

#include <string>
#include <utility>

namespace lpvid {

struct CertificateVerdict {
  /// The certificate's claim (Certificate::claim: consistent, invalidated or
  /// a lower bound) was checked exactly and holds.
  bool holds = false;
  std::string reason;   ///< why not (empty when it holds)
  std::string details;  ///< what was checked, sizes, which PSD path decided
  /// The first line lpvid-verify prints when the claim holds: "consistent",
  /// "invalidated" or "lower_bound <value>" (the claimed value, ≈).
  std::string claim_text;
  /// What exactly was claimed, echoed by lpvid-verify under the first line:
  /// the Toeplitz mode, δ² and d_max² as exact numbers (the fixed ones for a
  /// dual claim) and, for a lower bound, the objective and its value rounded
  /// down (never above what was proved).
  std::string claim_echo;

  /// The claim holds; `details` says what was checked (the claim's text and
  /// echo are set by the check that knows the claim).
  static CertificateVerdict holding(std::string details = "") {
    CertificateVerdict v;
    v.holds = true;
    v.details = std::move(details);
    return v;
  }
  /// The claim does not hold, with the reason and what was checked.
  static CertificateVerdict invalid(std::string reason, std::string details = "") {
    CertificateVerdict v;
    v.reason = std::move(reason);
    v.details = std::move(details);
    return v;
  }
};

}  // namespace lpvid
