#include "core/integer_form.h"

#include <algorithm>

namespace lpvid {

std::unique_ptr<IntegerForm> integer_form(const Mat<Rational>& m) {
  auto f = std::make_unique<IntegerForm>(m);
  mpz_set_ui(f->den.z, 1);
  std::size_t largest_bits = 1;
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      mpz_srcptr d = mpq_denref(m(i, j).mpq());
      largest_bits = std::max(largest_bits, mpz_sizeinbase(d, 2));
      if (!mpz_divisible_p(f->den.z, d)) mpz_lcm(f->den.z, f->den.z, d);
    }
  if (mpz_sizeinbase(f->den.z, 2) > 4 * largest_bits + 256) return nullptr;
  Mpz scale;
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      mpq_srcptr q = m(i, j).mpq();
      mpz_divexact(scale.z, f->den.z, mpq_denref(q));
      mpz_mul(f->num[static_cast<std::size_t>(i * m.cols() + j)], scale.z, mpq_numref(q));
    }
  return f;
}

Rational over_product(mpz_srcptr sum, const IntegerForm& a, const IntegerForm& b, Mpq& q) {
  mpz_set(mpq_numref(q.q), sum);
  mpz_mul(mpq_denref(q.q), a.den.z, b.den.z);
  mpq_canonicalize(q.q);
  return Rational(q.q);
}

Rational exact_dot(const Mat<Rational>& a, const Mat<Rational>& b) {
  const std::unique_ptr<IntegerForm> ai = integer_form(a), bi = integer_form(b);
  if (!ai || !bi) {
    Rational s(0);
    for (Eigen::Index i = 0; i < a.rows(); ++i)
      for (Eigen::Index j = 0; j < a.cols(); ++j) s += a(i, j) * b(i, j);
    return s;
  }
  Mpz sum;
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < a.cols(); ++j) mpz_addmul(sum.z, ai->at(i, j), bi->at(i, j));
  Mpq q;
  return over_product(sum.z, *ai, *bi, q);
}

Mat<Rational> exact_transpose_product(const Mat<Rational>& a, const Mat<Rational>& b) {
  const std::unique_ptr<IntegerForm> ai = integer_form(a), bi = integer_form(b);
  if (!ai || !bi) return Mat<Rational>(a.transpose() * b);
  Mat<Rational> out(a.cols(), b.cols());
  Mpz sum;
  Mpq q;
  for (Eigen::Index i = 0; i < a.cols(); ++i)
    for (Eigen::Index j = 0; j < b.cols(); ++j) {
      mpz_set_ui(sum.z, 0);
      for (Eigen::Index k = 0; k < a.rows(); ++k) mpz_addmul(sum.z, ai->at(k, i), bi->at(k, j));
      out(i, j) = over_product(sum.z, *ai, *bi, q);
    }
  return out;
}

Vec<Rational> exact_minus_product(const Vec<Rational>& g, const Mat<Rational>& F, const Vec<Rational>& x) {
  const Mat<Rational> gm = g, xm = x;
  const std::unique_ptr<IntegerForm> gi = integer_form(gm), fi = integer_form(F), xi = integer_form(xm);
  if (!gi || !fi || !xi) return Vec<Rational>(g - F * x);
  // g_k − (F x)_k = (g̃_k·F.den·x.den − g.den·Σ_j F̃_kj x̃_j) / (g.den·F.den·x.den)
  Mpz fx_den, sum, term;
  mpz_mul(fx_den.z, fi->den.z, xi->den.z);
  Mpq q;
  Vec<Rational> out(g.size());
  for (Eigen::Index k = 0; k < g.size(); ++k) {
    mpz_set_ui(sum.z, 0);
    for (Eigen::Index j = 0; j < F.cols(); ++j) mpz_addmul(sum.z, fi->at(k, j), xi->at(j, 0));
    mpz_mul(term.z, gi->at(k, 0), fx_den.z);
    mpz_mul(sum.z, sum.z, gi->den.z);
    mpz_sub(mpq_numref(q.q), term.z, sum.z);
    mpz_mul(mpq_denref(q.q), gi->den.z, fx_den.z);
    mpq_canonicalize(q.q);
    out(k) = Rational(q.q);
  }
  return out;
}

}  // namespace lpvid
