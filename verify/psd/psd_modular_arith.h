#pragma once
/// Word arithmetic modulo 31-bit primes and the Chinese remainder lift, for
/// the multi-modular PSD decision (verify/psd/psd_modular.cc).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/gmp_raii.h"

namespace lpvid::psd_detail {

__extension__ typedef unsigned __int128 u128;

/// Residues live in 32-bit words: p < 2^31, so l·x < 2^62 and the Shoup
/// remainder l·x − q·p lies in [0, 2p) ⊂ [0, 2^32): exact in uint32.
using Word = std::uint32_t;

inline Word mul_mod(Word a, Word b, Word p) {
  return static_cast<Word>(static_cast<std::uint64_t>(a) * b % p);
}
/// Shoup's precomputation ⌊w·2^32/p⌋ for multiplying by the fixed w < p.
inline Word shoup(Word w, Word p) { return static_cast<Word>((static_cast<std::uint64_t>(w) << 32) / p); }

/// x·w mod p with wp = shoup(w, p) (no division).
inline Word mul_shoup(Word x, Word w, Word wp, Word p) {
  const Word q = static_cast<Word>((static_cast<std::uint64_t>(wp) * x) >> 32);
  const Word t = w * x - q * p;  // in [0, 2p)
  return t >= p ? t - p : t;
}

/// row_i[j] ← row_i[j] − l·row_k[j] mod p, j < len (Shoup multiplication by
/// l with lp = shoup(l, p)).
void subtract_multiple(Word* __restrict row_i, const Word* __restrict row_k, std::size_t len, Word l, Word lp,
                       Word p);

/// a⁻¹ mod p, or false if gcd(a, p) ≠ 1 (extended Euclid).
bool inv_mod(Word a, Word p, Word* out);

/// Bits credited to each prime (all primes lie in (2^31 − 2^24, 2^31)).
constexpr unsigned kPrimeBits = 30;

/// The first `count` primes above 2^31 − 2^24 (cached; thread-safe); fewer
/// when the range below 2^31 holds fewer (the caller must check the size).
std::vector<Word> modular_primes(std::size_t count);

/// Lifts residues (one per prime) to the integer in (−P/2, P/2], P = Π primes.
class Crt {
 public:
  explicit Crt(const std::vector<Word>& primes);
  bool ok() const { return ok_; }
  std::size_t bits() const { return mpz_sizeinbase(P_.z, 2); }
  /// residue(i) for prime i.
  template <typename R>
  void lift(R&& residue, mpz_ptr out) const {
    mpz_set_ui(out, 0);
    for (std::size_t i = 0; i < primes_.size(); ++i) {
      const Word r = residue(i);
      if (r) mpz_addmul_ui(out, basis_[i].z, r);
    }
    mpz_mod(out, out, P_.z);
    if (mpz_cmp(out, half_.z) > 0) mpz_sub(out, out, P_.z);
  }

 private:
  std::vector<Word> primes_;
  std::vector<Mpz> basis_;  // (P/p_i)·((P/p_i)⁻¹ mod p_i)
  Mpz P_, half_;
  bool ok_ = true;
};

}  // namespace lpvid::psd_detail
