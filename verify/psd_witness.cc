/// The integer matrix L·M and exact witness checks (verify/psd_internal.h).

#include <gmp.h>

#include <stdexcept>

#include "verify/psd_internal.h"

namespace lpvid::psd_detail {

std::unique_ptr<IntegerMatrix> integer_matrix(const Mat<Rational>& M) {
  const std::size_t n = static_cast<std::size_t>(M.rows());
  auto out = std::make_unique<IntegerMatrix>(n);
  Mpz L, f;
  mpz_set_ui(L.z, 1);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j) {
      mpz_srcptr d = mpq_denref(M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)).mpq());
      if (!mpz_divisible_p(L.z, d)) mpz_lcm(L.z, L.z, d);
    }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j) {
      mpq_srcptr q = M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)).mpq();
      mpz_divexact(f.z, L.z, mpq_denref(q));
      mpz_mul(out->at(i, j), mpq_numref(q), f.z);
    }
  return out;
}

int quadratic_form_sign(const IntegerMatrix& A, const std::vector<Mpz>& w) {
  const std::size_t n = A.n;
  Mpz q, row, t;
  for (std::size_t i = 0; i < n; ++i) {
    if (mpz_sgn(w[i].z) == 0) continue;
    mpz_set_ui(row.z, 0);  // Σ_{j>i} A_ij w_j
    for (std::size_t j = i + 1; j < n; ++j)
      if (mpz_sgn(w[j].z) != 0) mpz_addmul(row.z, A.at(i, j), w[j].z);
    mpz_mul_2exp(row.z, row.z, 1);
    mpz_addmul(row.z, A.at(i, i), w[i].z);  // A_ii w_i + 2 Σ_{j>i} A_ij w_j
    mpz_addmul(q.z, row.z, w[i].z);
  }
  return mpz_sgn(q.z);
}

Vec<Rational> reduced_witness(std::vector<Mpz>& w) {
  Mpz g;
  for (auto& x : w) mpz_gcd(g.z, g.z, x.z);
  Vec<Rational> v(static_cast<Eigen::Index>(w.size()));
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (mpz_sgn(g.z) != 0) mpz_divexact(w[i].z, w[i].z, g.z);
    v(static_cast<Eigen::Index>(i)) = mpz_to_rational(w[i].z);
  }
  return v;
}

void check_witness(const Mat<Rational>& M, const std::vector<Mpz>& w) {
  auto A = integer_matrix(M);
  if (quadratic_form_sign(*A, w) >= 0)
    throw std::logic_error("exact_psd: internal error: witness does not satisfy v'Mv < 0");
}

}  // namespace lpvid::psd_detail
