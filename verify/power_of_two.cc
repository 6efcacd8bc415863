#include "verify/power_of_two.h"

#include <gmp.h>

#include "verify/gmp_raii.h"

namespace lpvid {

Rational power_of_two(long e) {
  psd_detail::Mpq p;
  mpq_set_ui(p.q, 1, 1);
  if (e >= 0)
    mpq_mul_2exp(p.q, p.q, static_cast<mp_bitcnt_t>(e));
  else
    mpq_div_2exp(p.q, p.q, static_cast<mp_bitcnt_t>(-e));
  return Rational(p.q);
}

std::optional<long> binary_magnitude(const Rational& q) {
  if (mpq_sgn(q.mpq()) == 0) return std::nullopt;
  return static_cast<long>(mpz_sizeinbase(mpq_numref(q.mpq()), 2)) -
         static_cast<long>(mpz_sizeinbase(mpq_denref(q.mpq()), 2));
}

Rational sqrt_scale(const Rational& q) {
  if (!(q > 0)) return Rational(1);
  const long bits = *binary_magnitude(q);
  return power_of_two(bits >= 0 ? bits / 2 : -((-bits + 1) / 2));
}

}  // namespace lpvid
