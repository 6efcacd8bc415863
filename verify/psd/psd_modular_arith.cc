/// Word arithmetic modulo 31-bit primes and the Chinese remainder lift
/// (verify/psd/psd_modular_arith.h).

#include "verify/psd/psd_modular_arith.h"

#include <algorithm>
#include <mutex>

namespace lpvid::psd_detail {

// Compiled for AVX-512, AVX2 and baseline x86-64 and chosen at load time
// (target_clones); all are the same exact integer code (only the vector width
// differs).
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
void subtract_multiple(Word* __restrict row_i, const Word* __restrict row_k, std::size_t len, Word l, Word lp,
                       Word p) {
  for (std::size_t j = 0; j < len; ++j) {
    const Word x = row_k[j];
    const Word q = static_cast<Word>((static_cast<std::uint64_t>(lp) * x) >> 32);
    Word t = l * x - q * p;  // in [0, 2p)
    t = t >= p ? t - p : t;
    const Word a = row_i[j];
    row_i[j] = a >= t ? a - t : a + (p - t);
  }
}

bool inv_mod(Word a, Word p, Word* out) {
  std::int64_t t = 0, new_t = 1;
  std::int64_t r = p, new_r = a;
  while (new_r != 0) {
    const std::int64_t q = r / new_r;
    const std::int64_t tt = t - q * new_t;
    t = new_t;
    new_t = tt;
    const std::int64_t rr = r - q * new_r;
    r = new_r;
    new_r = rr;
  }
  if (r != 1) return false;
  *out = static_cast<Word>(t < 0 ? t + p : t);
  return true;
}

std::vector<Word> modular_primes(std::size_t count) {
  static std::mutex mutex;
  static std::vector<Word> cache;
  static bool exhausted = false;  // the cache holds every prime in the range
  std::lock_guard<std::mutex> lock(mutex);
  if (cache.size() < count && !exhausted) {
    Mpz z;
    mpz_set_ui(z.z, (1ul << 31) - (1ul << 24));
    if (!cache.empty()) mpz_set_ui(z.z, cache.back());
    while (cache.size() < count) {
      mpz_nextprime(z.z, z.z);
      if (mpz_cmp_ui(z.z, 1ul << 31) >= 0) {
        exhausted = true;
        break;
      }
      cache.push_back(static_cast<Word>(mpz_get_ui(z.z)));
    }
  }
  const std::size_t have = std::min(count, cache.size());
  return std::vector<Word>(cache.begin(), cache.begin() + static_cast<std::ptrdiff_t>(have));
}

Crt::Crt(const std::vector<Word>& primes) : primes_(primes), basis_(primes.size()) {
  mpz_set_ui(P_.z, 1);
  for (Word p : primes_) mpz_mul_ui(P_.z, P_.z, p);
  Mpz q, inv, pz;
  for (std::size_t i = 0; i < primes_.size(); ++i) {
    mpz_divexact_ui(q.z, P_.z, primes_[i]);
    mpz_set_ui(pz.z, primes_[i]);
    if (!mpz_invert(inv.z, q.z, pz.z)) ok_ = false;  // moduli not coprime: never for distinct primes
    mpz_mul(basis_[i].z, q.z, inv.z);
  }
  mpz_fdiv_q_2exp(half_.z, P_.z, 1);
}

}  // namespace lpvid::psd_detail
