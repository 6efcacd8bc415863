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

}  // namespace lpvid
