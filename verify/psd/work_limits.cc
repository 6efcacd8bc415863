#include "verify/psd/work_limits.h"

#include <cstdio>

namespace lpvid {

VerifyWorkLimits& verify_work_limits() {
  static VerifyWorkLimits limits;
  return limits;
}

void require_exact_work(long n, double hadamard_bits) {
  const double limit = verify_work_limits().max_exact_work;
  const double primes = hadamard_bits / 31 + 1;
  const double work = primes * static_cast<double>(n) * static_cast<double>(n) * static_cast<double>(n) / 3;
  if (limit <= 0 || work <= limit) return;
  char text[200];
  std::snprintf(text, sizeof text,
                "the exact elimination of a %ld x %ld matrix needs about %.3g modular operations (%.0f primes), "
                "above the limit %.3g; raise it with --max-exact-work",
                n, n, work, primes, limit);
  throw WorkLimitError(text);
}

void require_dual_order(long order) {
  const long limit = verify_work_limits().max_dual_order;
  if (limit <= 0 || order <= limit) return;
  throw WorkLimitError("the compact dual point has order L*ny = " + std::to_string(order) +
                       " (a floating inversion of that order and exact sums over its entries), above the limit " +
                       std::to_string(limit) + "; raise it with --max-dual-order");
}

}  // namespace lpvid
