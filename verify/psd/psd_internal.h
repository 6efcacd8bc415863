#pragma once
/// Internals shared by the exact PSD decision's files (verify/psd/exact_psd.h is
/// the contract; nothing outside verify/psd_*.cc and the tests includes this).

#include <algorithm>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "verify/psd/exact_psd.h"
#include "core/gmp_raii.h"
#include "core/parallel_for.h"

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

/// log₂ of Hadamard's bound, rounded up: Σ_i ⌈log₂ max(1, ‖A_i‖₂)⌉
/// (verify/psd/psd_modular.cc).
std::size_t hadamard_bits(const IntegerMatrix& A);

/// Sign of wᵀMw, exactly, for the symmetric rational M (upper triangle) and
/// integer w: over the support of w and with one common denominator per row
/// (verify/psd/psd_witness.cc), without forming L·M.
int quadratic_form_sign(const Mat<Rational>& M, const std::vector<Mpz>& w);

/// Divides w by the gcd of its entries (w ≠ 0) and returns it as rationals.
Vec<Rational> reduced_witness(std::vector<Mpz>& w);

/// Re-checks a witness exactly (wᵀMw < 0); a failure is a bug, never an answer.
void check_witness(const Mat<Rational>& M, const std::vector<Mpz>& w);

/// `threads` ≤ 0: the hardware concurrency (core/parallel_for.h, at most 8);
/// else at most 64.
inline int resolve_threads(int threads) {
  if (threads > 0) return std::min(threads, 64);
  return static_cast<int>(std::min(default_thread_count(), 8u));
}

/// Outcome of the multi-modular path: a result, or "undecided" with the
/// reason in `why` (the caller then decides with Bareiss).
struct ModularOutcome {
  bool decided = false;
  PsdResult result;
  std::string why;
};

/// No limit on the number of primes below the supply: the primes in
/// (2^31 − 2^24, 2^31), about 7.8·10⁵ (2^24 / ln 2^31, prime number theorem),
/// i.e. Hadamard bounds up to about 2·10⁷ bits.
inline constexpr std::size_t kAllPrimes = static_cast<std::size_t>(-1);

/// The multi-modular decision (verify/psd/psd_modular.cc) with at most
/// `max_primes` primes.
ModularOutcome decide_psd_modular(const Mat<Rational>& M, int threads, std::size_t max_primes = kAllPrimes);

/// Resource limits of decide_psd_exact. The defaults are the real ones; the
/// tests lower them to reach the fallbacks on small matrices.
struct ExactPsdLimits {
  /// Most primes the multi-modular path may use (beyond: Bareiss decides).
  std::size_t max_primes = kAllPrimes;
  /// The leading-block screen decides the leading principal submatrices of
  /// sizes 2, 4, 8, … ≤ n / screen_divisor first (verify/psd/psd_screen.cc);
  /// 0 turns the screen off.
  std::size_t screen_divisor = 4;
};

/// decide_psd_exact with explicit limits (same `threads` as decide_psd_exact).
PsdResult decide_psd_exact_limited(const Mat<Rational>& M, int threads, const ExactPsdLimits& limits);

/// The leading-block screen: true with *out = NOT_PSD (witness padded by zeros
/// and checked exactly on M) when a leading principal submatrix of M within
/// the limits is not PSD; false when none is (which proves nothing about M).
bool screen_leading_blocks(const Mat<Rational>& M, int threads, const ExactPsdLimits& limits, PsdResult* out);

}  // namespace lpvid::psd_detail
