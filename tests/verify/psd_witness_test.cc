// The exact witness check (verify/psd/psd_witness.cc) reads M row by row with
// one denominator per row instead of forming L·M: its sign of wᵀMw must be
// that of the plain rational sum, also with denominators of 10^500.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <vector>

#include "support/gen_numbers.h"
#include "verify/psd/exact_psd.h"
#include "verify/psd/psd_internal.h"

namespace lpvid {
namespace {


RC_GTEST_PROP(VerifyWitnessSign, RowwiseSignEqualsTheRationalQuadraticForm, ()) {
  const int n = *rc::gen::inRange(1, 7);
  Mat<Rational> B = *gen::rational_matrix(n, n, gen::small_rational());
  Rational tiny(1);
  for (int i = 0; i < 500; ++i) tiny /= Rational(10);
  const int r = *rc::gen::inRange(0, n);
  B(r, r) = B(r, r) * tiny;  // one row with a 500-digit denominator
  const Mat<Rational> M = B + B.transpose();
  const std::vector<int> ints = *rc::gen::container<std::vector<int>>(static_cast<size_t>(n), rc::gen::inRange(-3, 4));
  std::vector<Mpz> w(static_cast<size_t>(n));
  Vec<Rational> v(n);
  for (int i = 0; i < n; ++i) {
    mpz_set_si(w[static_cast<size_t>(i)].z, ints[static_cast<size_t>(i)]);
    v(i) = Rational(ints[static_cast<size_t>(i)]);
  }
  const Rational q = quadratic_form(M, v);
  const int expected = q > 0 ? 1 : (q < 0 ? -1 : 0);
  RC_CLASSIFY(expected < 0, "negative");
  RC_ASSERT(psd_detail::quadratic_form_sign(M, w) == expected);
}

}  // namespace
}  // namespace lpvid
