#include "verify/psd/work_limits.h"

#include <atomic>
#include <cstdio>

#include "verify/psd/check_progress.h"

namespace lpvid {

VerifyWorkLimits& verify_work_limits() {
  static VerifyWorkLimits limits;
  return limits;
}

void require_exact_work(long n, double hadamard_bits) {
  const double limit = verify_work_limits().max_exact_work;
  const double primes = hadamard_bits / 31 + 1;
  const double work = primes * static_cast<double>(n) * static_cast<double>(n) * static_cast<double>(n) / 3;
  if (limit > 0 && work > limit) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "the exact elimination of a %ld x %ld matrix needs about %.3g modular operations (%.0f primes), "
                  "above the limit %.3g; raise it with --max-exact-work",
                  n, n, work, primes, limit);
    throw WorkLimitError(text);
  }
  charge_total_work(work, "the exact elimination of a " + std::to_string(n) + " x " + std::to_string(n) + " matrix");
}

void require_dual_order(long order) {
  const long limit = verify_work_limits().max_dual_order;
  if (limit <= 0 || order <= limit) return;
  throw WorkLimitError("the compact dual point has order L*ny = " + std::to_string(order) +
                       " (a floating inversion of that order and exact sums over its entries), above the limit " +
                       std::to_string(limit) + "; raise it with --max-dual-order");
}

namespace {
/// The total of the check under way (atomic: the library's callers may check
/// in several threads, unlimited; then nothing is counted anyway).
std::atomic<double>& total_work() {
  static std::atomic<double> total{0};
  return total;
}

std::atomic<double>& floating_work() {
  static std::atomic<double> total{0};
  return total;
}

/// Adds `work` to `total` unless that passes `limit` (then WorkLimitError
/// naming the part, the sum, the limit and its option).
void charge(std::atomic<double>& total, double limit, double work, const std::string& what, const char* kind,
            const char* option) {
  if (limit <= 0) return;
  const double sum = total + work;
  if (sum > limit) {
    char text[200];
    std::snprintf(text, sizeof text, "needs about %.3g %s, which brings the check's estimated total to %.3g, above the limit %.3g",
                  work, kind, sum, limit);
    throw WorkLimitError(what + " " + text + "; raise it with " + option);
  }
  total = sum;
}
}  // namespace

void start_total_work() {
  total_work() = 0;
  floating_work() = 0;
  start_check_progress(verify_work_limits().max_total_work > 0);
}

double total_work_charged() { return total_work(); }
double floating_work_charged() { return floating_work(); }

void charge_total_work(double work, const std::string& what) {
  charge(total_work(), verify_work_limits().max_total_work, work, what, "operations", "--max-total-work");
}

void charge_floating_work(double work, const std::string& what) {
  charge(floating_work(), verify_work_limits().max_floating_work, work, what, "floating multiply-adds",
         "--max-floating-work");
}

}  // namespace lpvid
