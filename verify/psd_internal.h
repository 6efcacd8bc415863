#pragma once
/// Internals shared by the exact PSD decision's files (verify/exact_psd.h is
/// the contract; nothing outside verify/psd_*.cc and the tests includes this).

#include <algorithm>
#include <cstddef>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "verify/exact_psd.h"
#include "verify/gmp_raii.h"

namespace lpvid::psd_detail {

/// The integer matrix L·M (L = lcm of all denominators > 0): same verdict as M
/// and vᵀ(L·M)v = L·vᵀMv, so witnesses carry over unchanged.
struct IntegerMatrix {
  std::size_t n;
  MpzArray a;  // n×n row-major; only the upper triangle (i ≤ j) is used
  explicit IntegerMatrix(std::size_t size) : n(size), a(size * size) {}
  mpz_ptr at(std::size_t i, std::size_t j) { return a[i * n + j]; }
  mpz_srcptr at(std::size_t i, std::size_t j) const { return a[i * n + j]; }
};

/// L·M for the symmetric rational M (upper triangle only).
std::unique_ptr<IntegerMatrix> integer_matrix(const Mat<Rational>& M);

/// Sign of wᵀAw for the symmetric integer A (upper triangle) and integer w.
int quadratic_form_sign(const IntegerMatrix& A, const std::vector<Mpz>& w);

/// Divides w by the gcd of its entries (w ≠ 0) and returns it as rationals.
Vec<Rational> reduced_witness(std::vector<Mpz>& w);

/// Re-checks a witness exactly (wᵀMw < 0); a failure is a bug, never an answer.
void check_witness(const Mat<Rational>& M, const std::vector<Mpz>& w);

/// `threads` ≤ 0: the hardware concurrency (at most 8); else at most 64.
inline int resolve_threads(int threads) {
  if (threads > 0) return std::min(threads, 64);
  const unsigned hw = std::thread::hardware_concurrency();
  return static_cast<int>(std::clamp(hw, 1u, 8u));
}

/// Outcome of the multi-modular path: a result, or "undecided" (the caller
/// then decides with Bareiss).
struct ModularOutcome {
  bool decided = false;
  PsdResult result;
};

/// The multi-modular decision (verify/psd_modular.cc).
ModularOutcome decide_psd_modular(const Mat<Rational>& M, int threads);

}  // namespace lpvid::psd_detail
