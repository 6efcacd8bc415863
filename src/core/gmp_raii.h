#pragma once
/// RAII owners of GMP integers and rationals and of MPFR floats: in-place
/// GMP arithmetic without temporaries (the exact PSD decision,
/// verify/psd/exact_psd.h; number text and decimal rounding), and no leak when
/// an exception unwinds. Every GMP/MPFR value of the project lives in one.

#include <gmp.h>
#include <mpfr.h>

#include <cstddef>
#include <memory>

#include "core/scalar.h"

namespace lpvid {

/// A fixed-size array of initialised GMP values (S = __mpz_struct or
/// __mpq_struct, with its init and clear functions).
template <typename S, void (*Init)(S*), void (*Clear)(S*)>
class GmpArray {
 public:
  explicit GmpArray(std::size_t count) : count_(count), x_(new S[count]) {
    for (std::size_t i = 0; i < count_; ++i) Init(&x_[i]);
  }
  ~GmpArray() {
    for (std::size_t i = 0; i < count_; ++i) Clear(&x_[i]);
  }
  GmpArray(const GmpArray&) = delete;
  GmpArray& operator=(const GmpArray&) = delete;
  S* operator[](std::size_t i) { return &x_[i]; }
  const S* operator[](std::size_t i) const { return &x_[i]; }
  std::size_t size() const { return count_; }

 private:
  std::size_t count_;
  std::unique_ptr<S[]> x_;
};

using MpzArray = GmpArray<__mpz_struct, &mpz_init, &mpz_clear>;
using MpqArray = GmpArray<__mpq_struct, &mpq_init, &mpq_clear>;

/// One mpz_t (initialised to 0, or to a copy of another integer).
struct Mpz {
  mpz_t z;
  Mpz() { mpz_init(z); }
  explicit Mpz(mpz_srcptr from) { mpz_init_set(z, from); }
  ~Mpz() { mpz_clear(z); }
  Mpz(const Mpz&) = delete;
  Mpz& operator=(const Mpz&) = delete;
};

/// One mpq_t (initialised to 0).
struct Mpq {
  mpq_t q;
  Mpq() { mpq_init(q); }
  ~Mpq() { mpq_clear(q); }
  Mpq(const Mpq&) = delete;
  Mpq& operator=(const Mpq&) = delete;
};

/// One mpfr_t of `precision` bits (NaN until set).
struct Mpfr {
  mpfr_t f;
  explicit Mpfr(mpfr_prec_t precision) { mpfr_init2(f, precision); }
  ~Mpfr() { mpfr_clear(f); }
  Mpfr(const Mpfr&) = delete;
  Mpfr& operator=(const Mpfr&) = delete;
};

inline Rational mpz_to_rational(mpz_srcptr z) {
  Mpq t;
  mpq_set_z(t.q, z);
  return Rational(t.q);
}

}  // namespace lpvid
