/// The integer matrix L·M and exact witness checks (verify/psd/psd_internal.h).
/// The witness checks read M itself, row by row: a δ² = 1e−5000 on the
/// diagonal makes L·M a matrix of 5000-digit integers (and a second copy).

#include <gmp.h>

#include <stdexcept>

#include "verify/psd/psd_internal.h"

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

int quadratic_form_sign(const Mat<Rational>& M, const std::vector<Mpz>& w) {
  // Only the rows and columns where w ≠ 0 matter. Row i of the sum,
  //   r_i = w_i·(M_ii w_i + 2 Σ_{j>i} M_ij w_j),
  // is an integer over the lcm D_i of that row's denominators (upper
  // triangle, support of w only), so the integers stay as large as one row
  // needs, never as large as the lcm over all of M; then wᵀMw = Σ_i r_i
  // in rationals (one canonical sum per row).
  std::vector<Eigen::Index> support;
  for (std::size_t i = 0; i < w.size(); ++i)
    if (mpz_sgn(w[i].z) != 0) support.push_back(static_cast<Eigen::Index>(i));
  Mpz den, row, whole, t;
  Mpq term, q;
  for (std::size_t a = 0; a < support.size(); ++a) {
    const Eigen::Index i = support[a];
    mpz_set_ui(den.z, 1);
    for (std::size_t b = a; b < support.size(); ++b) {
      mpz_srcptr d = mpq_denref(M(i, support[b]).mpq());
      if (!mpz_divisible_p(den.z, d)) mpz_lcm(den.z, den.z, d);
    }
    // D_i·Σ_{j>i} M_ij w_j; the integer entries (the common case) are summed
    // apart and multiplied by D_i once.
    mpz_set_ui(row.z, 0);
    mpz_set_ui(whole.z, 0);
    for (std::size_t b = a + 1; b < support.size(); ++b) {
      mpq_srcptr m = M(i, support[b]).mpq();
      mpz_srcptr wj = w[static_cast<std::size_t>(support[b])].z;
      if (mpz_cmp_ui(mpq_denref(m), 1) == 0) {
        mpz_addmul(whole.z, mpq_numref(m), wj);
        continue;
      }
      mpz_divexact(t.z, den.z, mpq_denref(m));
      mpz_mul(t.z, t.z, mpq_numref(m));
      mpz_addmul(row.z, t.z, wj);
    }
    mpz_addmul(row.z, den.z, whole.z);
    mpz_mul_2exp(row.z, row.z, 1);
    mpq_srcptr m = M(i, i).mpq();
    mpz_divexact(t.z, den.z, mpq_denref(m));
    mpz_mul(t.z, t.z, mpq_numref(m));
    mpz_addmul(row.z, t.z, w[static_cast<std::size_t>(i)].z);  // D_i·(M_ii w_i + 2 Σ_{j>i} M_ij w_j)
    mpz_mul(mpq_numref(term.q), row.z, w[static_cast<std::size_t>(i)].z);
    mpz_set(mpq_denref(term.q), den.z);
    mpq_canonicalize(term.q);
    mpq_add(q.q, q.q, term.q);
  }
  return mpq_sgn(q.q);
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
  if (quadratic_form_sign(M, w) >= 0)
    throw std::logic_error("exact_psd: internal error: witness does not satisfy v'Mv < 0");
}

}  // namespace lpvid::psd_detail
