#include "verify/certificate/column_gram.h"

#include <gmp.h>

#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/gmp_raii.h"
#include "core/stop_request.h"

namespace lpvid {

Mat<Rational> column_gram(const Mat<Rational>& T) {
  const Eigen::Index rows = T.rows(), n = T.cols();
  const std::size_t r = static_cast<std::size_t>(rows);
  MpzArray num(r * static_cast<std::size_t>(n)), den(static_cast<std::size_t>(n));
  std::vector<Eigen::Index> first(static_cast<std::size_t>(n), rows);  // first non-zero row of each column
  Mpz f;
  for (Eigen::Index j = 0; j < n; ++j) {
    const std::size_t jj = static_cast<std::size_t>(j);
    mpz_set_ui(den[jj], 1);
    for (Eigen::Index k = 0; k < rows; ++k) {
      mpq_srcptr q = T(k, j).mpq();
      if (mpq_sgn(q) == 0) continue;
      first[jj] = std::min(first[jj], k);
      if (!mpz_divisible_p(den[jj], mpq_denref(q))) mpz_lcm(den[jj], den[jj], mpq_denref(q));
    }
    for (Eigen::Index k = first[jj]; k < rows; ++k) {  // N_kj = D_j·T_kj
      mpq_srcptr q = T(k, j).mpq();
      mpz_divexact(f.z, den[jj], mpq_denref(q));
      mpz_mul(num[jj * r + static_cast<std::size_t>(k)], f.z, mpq_numref(q));
    }
  }
  Mat<Rational> G(n, n);
  Mpz dot;
  Mpq g;
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = i; j < n; ++j) {
      if (j == i) check_stop();  // a requested stop, once a row
      const std::size_t ii = static_cast<std::size_t>(i), jj = static_cast<std::size_t>(j);
      mpz_set_ui(dot.z, 0);
      for (Eigen::Index k = std::max(first[ii], first[jj]); k < rows; ++k)
        mpz_addmul(dot.z, num[ii * r + static_cast<std::size_t>(k)], num[jj * r + static_cast<std::size_t>(k)]);
      mpz_set(mpq_numref(g.q), dot.z);
      mpz_mul(mpq_denref(g.q), den[ii], den[jj]);
      mpq_canonicalize(g.q);
      G(i, j) = Rational(g.q);
      if (j != i) G(j, i) = G(i, j);
    }
  return G;
}

}  // namespace lpvid
