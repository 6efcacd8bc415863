#include "verify/psd/power_of_two.h"

#include <gmp.h>

#include "core/gmp_raii.h"

namespace lpvid {

Rational power_of_two(long e) {
  Mpq p;
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

std::vector<long> diagonal_balance_exponents(const Mat<Rational>& M, long min_range_bits) {
  std::vector<long> k(static_cast<std::size_t>(M.rows()), 0);
  long lo = 0, hi = 0;
  bool any = false;
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    if (!(M(i, i) > 0)) continue;
    const long e = *binary_magnitude(M(i, i));  // 2^(e−1) < M_ii < 2^(e+1)
    k[static_cast<std::size_t>(i)] = e >= 0 ? -(e / 2) : (-e) / 2;  // 2^(2k)·M_ii within [1/4, 4]
    lo = any ? std::min(lo, e) : e;
    hi = any ? std::max(hi, e) : e;
    any = true;
  }
  if (!any || hi - lo < min_range_bits) return {};
  return k;
}

Mat<Rational> diagonal_congruence(const Mat<Rational>& M, const std::vector<long>& k) {
  Mat<Rational> out(M.rows(), M.cols());
  Mpq x;
  for (Eigen::Index i = 0; i < M.rows(); ++i)
    for (Eigen::Index j = 0; j < M.cols(); ++j) {
      const long e = k[static_cast<std::size_t>(i)] + k[static_cast<std::size_t>(j)];
      if (e >= 0)
        mpq_mul_2exp(x.q, M(i, j).mpq(), static_cast<mp_bitcnt_t>(e));
      else
        mpq_div_2exp(x.q, M(i, j).mpq(), static_cast<mp_bitcnt_t>(-e));
      out(i, j) = Rational(x.q);
    }
  return out;
}

}  // namespace lpvid
