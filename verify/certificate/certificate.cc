#include "verify/certificate/certificate.h"

namespace lpvid {

const char* to_string(CertificateClaim c) {
  switch (c) {
    case CertificateClaim::kConsistent:
      return "consistent";
    case CertificateClaim::kInvalidated:
      return "invalidated";
    case CertificateClaim::kLowerBound:
      return "lower_bound";
    case CertificateClaim::kNotAWitness:
      return "not_a_witness";
    case CertificateClaim::kClassLowerBound:
      return "class_lower_bound";
    case CertificateClaim::kClassInvalidated:
      return "class_invalidated";
  }
  return "?";
}

const char* to_string(CertificateForm f) {
  switch (f) {
    case CertificateForm::kDelta:
      return "delta";
    case CertificateForm::kW:
      return "w";
    case CertificateForm::kDualDelta:
      return "dual_delta";
    case CertificateForm::kDualDeltaPath:
      return "dual_delta_path";
    case CertificateForm::kZeroDelta:
      return "zero_delta";
    case CertificateForm::kNonnegative:
      return "nonnegative";
  }
  return "?";
}

}  // namespace lpvid
