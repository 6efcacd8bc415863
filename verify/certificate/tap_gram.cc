#include "verify/certificate/tap_gram.h"

#include <algorithm>

#include "core/gmp_raii.h"
#include "core/stop_request.h"

namespace lpvid {
namespace {

/// The taps as integer numerators (into `num`, K·width of them) over their
/// common denominator D; D² in `D2`.
void tap_numerators(const Mat<Rational>& taps, MpzArray& num, Mpz& D2) {
  const Eigen::Index K = taps.rows(), width = taps.cols();
  Mpz D, f;
  mpz_set_ui(D.z, 1);
  for (Eigen::Index t = 0; t < K; ++t)
    for (Eigen::Index c = 0; c < width; ++c)
      if (mpq_srcptr q = taps(t, c).mpq(); !mpz_divisible_p(D.z, mpq_denref(q))) mpz_lcm(D.z, D.z, mpq_denref(q));
  for (Eigen::Index t = 0; t < K; ++t)
    for (Eigen::Index c = 0; c < width; ++c) {
      mpq_srcptr q = taps(t, c).mpq();
      mpz_divexact(f.z, D.z, mpq_denref(q));
      mpz_mul(num[static_cast<std::size_t>(t * width + c)], f.z, mpq_numref(q));
    }
  mpz_mul(D2.z, D.z, D.z);
}

}  // namespace

Mat<Rational> tap_gram_complement(const Mat<Rational>& taps, Eigen::Index L, Eigen::Index ny, Eigen::Index nz,
                                  const Rational& d2) {
  const Eigen::Index K = taps.rows(), width = ny * nz;
  Mpz D2;
  MpzArray num(static_cast<std::size_t>(K * width));
  tap_numerators(taps, num, D2);
  const auto at = [&num, width](Eigen::Index t, Eigen::Index c) { return num[static_cast<std::size_t>(t * width + c)]; };
  const bool rows = ny <= nz;  // T Tᵀ (blocks ny × ny) or TᵀT (blocks nz × nz)
  const Eigen::Index m = rows ? ny : nz;
  Mat<Rational> S = Mat<Rational>::Zero(L * m, L * m);
  MpzArray sum(static_cast<std::size_t>(m * m));
  Mat<Rational> block(m, m);  // −G(a, c), the running block of this diagonal
  Mpq g;
  for (Eigen::Index o = 0; o < std::min(K, L); ++o) {  // the block diagonal c − a = o
    for (std::size_t e = 0; e < sum.size(); ++e) mpz_set_ui(sum[e], 0);
    block.setZero();
    for (Eigen::Index s = 0; s + o < L; ++s) {
      if (s % 256 == 0) check_stop();  // a requested stop
      if (s + o < K) {  // the recurrence's new term (tap_gram.h), then −sum/D² once
        for (Eigen::Index p = 0; p < m; ++p)
          for (Eigen::Index q = 0; q < m; ++q) {
            mpz_ptr acc = sum[static_cast<std::size_t>(p * m + q)];
            if (rows)
              for (Eigen::Index j = 0; j < nz; ++j) mpz_addmul(acc, at(s, p * nz + j), at(s + o, q * nz + j));
            else
              for (Eigen::Index i = 0; i < ny; ++i) mpz_addmul(acc, at(s + o, i * nz + p), at(s, i * nz + q));
            mpz_neg(mpq_numref(g.q), acc);
            mpz_set(mpq_denref(g.q), D2.z);
            mpq_canonicalize(g.q);
            block(p, q) = Rational(g.q);
          }
      }
      const Eigen::Index a = rows ? s : L - 1 - o - s, c = a + o;
      for (Eigen::Index p = 0; p < m; ++p)
        for (Eigen::Index q = 0; q < m; ++q) {
          S(a * m + p, c * m + q) = block(p, q);
          if (o != 0) S(c * m + q, a * m + p) = block(p, q);
        }
    }
  }
  for (Eigen::Index k = 0; k < L * m; ++k) S(k, k) += d2;
  return S;
}

}  // namespace lpvid
