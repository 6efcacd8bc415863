// Exact sums over one common denominator (core/integer_form.h) against the
// same sums formed rational by rational: equal as rational numbers, on
// matrices whose denominators share a base (powers of 10: the integer form is
// taken) and on matrices of unrelated prime denominators (the integer form is
// refused and the functions fall back).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/integer_form.h"

namespace lpvid {
namespace {

const long kPrimes[] = {3, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83, 89, 97, 101};

/// A random rational: numerator up to 10⁹ in size over 10^k (decimal) or a product of primes.
Rational random_rational(bool decimal) {
  Rational num(*rc::gen::inRange<long>(-1000000000L, 1000000000L));
  Rational den(1);
  if (decimal) {
    for (int k = *rc::gen::inRange(0, 30); k > 0; --k) den *= 10;
  } else {
    for (int k = *rc::gen::inRange(1, 4); k > 0; --k) den *= kPrimes[*rc::gen::inRange(0, 24)];
  }
  return num / den;
}

Mat<Rational> random_matrix(Eigen::Index rows, Eigen::Index cols, bool decimal) {
  Mat<Rational> m(rows, cols);
  for (Eigen::Index i = 0; i < m.size(); ++i) m(i) = random_rational(decimal);
  return m;
}

TEST(IntegerForm, DecimalMatricesHaveOneOverTheirLargestDenominator) {
  Mat<Rational> m(2, 2);
  m << Rational(1, 10), Rational(3, 1000), Rational(-7), Rational(9, 100);
  const auto f = integer_form(m);
  ASSERT_TRUE(f);
  EXPECT_EQ(Rational(f->den.z), Rational(1000));
  EXPECT_EQ(Rational(f->at(0, 0)) / Rational(f->den.z), m(0, 0));
  EXPECT_EQ(Rational(f->at(1, 0)) / Rational(f->den.z), m(1, 0));
}

TEST(IntegerForm, ManyUnrelatedDenominatorsAreRefused) {
  // 24 distinct primes above 2^61: their lcm has about 24·62 bits, far above 4·62 + 256
  Mat<Rational> m(1, 24);
  Mpz prime;
  mpz_set_ui(prime.z, 1);
  mpz_mul_2exp(prime.z, prime.z, 61);
  for (int i = 0; i < 24; ++i) {
    mpz_nextprime(prime.z, prime.z);
    m(0, i) = Rational(i + 1) / Rational(prime.z);
  }
  EXPECT_FALSE(integer_form(m));
  // and the sums still come out exact
  Rational naive(0);
  for (int i = 0; i < 24; ++i) naive += m(0, i) * m(0, i);
  EXPECT_EQ(exact_dot(m, m), naive);
  EXPECT_EQ(exact_transpose_product(m.transpose(), m.transpose())(0, 0), naive);
}

RC_GTEST_PROP(IntegerForm, SumsEqualTheRationalSums, ()) {
  const bool decimal = *rc::gen::arbitrary<bool>();
  const Eigen::Index m = *rc::gen::inRange(1, 12), p = *rc::gen::inRange(1, 5);
  const Mat<Rational> a = random_matrix(m, p, decimal), b = random_matrix(m, p, decimal);
  Rational dot(0);
  for (Eigen::Index i = 0; i < a.size(); ++i) dot += a(i) * b(i);
  RC_ASSERT(exact_dot(a, b) == dot);
  const Mat<Rational> atb = exact_transpose_product(a, b);
  for (Eigen::Index i = 0; i < p; ++i)
    for (Eigen::Index j = 0; j < p; ++j) {
      Rational s(0);
      for (Eigen::Index k = 0; k < m; ++k) s += a(k, i) * b(k, j);
      RC_ASSERT(atb(i, j) == s);
    }
  const Vec<Rational> g = random_matrix(m, 1, decimal).col(0), x = random_matrix(p, 1, !decimal).col(0);
  const Vec<Rational> got = exact_minus_product(g, a, x);
  for (Eigen::Index k = 0; k < m; ++k) {
    Rational s = g(k);
    for (Eigen::Index j = 0; j < p; ++j) s -= a(k, j) * x(j);
    RC_ASSERT(got(k) == s);
  }
}

}  // namespace
}  // namespace lpvid
