#include "toeplitz/exact_convolution.h"

#include <algorithm>
#include <memory>

#include "core/gmp_raii.h"
#include "core/stop_request.h"
#include "toeplitz/record_lengths.h"

namespace lpvid {
namespace {

/// A rational matrix as integer numerators over one common denominator.
struct IntegerForm {
  Eigen::Index rows = 0, cols = 0;
  MpzArray num;
  Mpz den;
  explicit IntegerForm(const Mat<Rational>& m) : rows(m.rows()), cols(m.cols()), num(static_cast<std::size_t>(m.size())) {}
  mpz_srcptr at(Eigen::Index i, Eigen::Index j) const { return num[static_cast<std::size_t>(i * cols + j)]; }
};

/// The integer form of `m`, or null when the common denominator has more
/// than 4× the bits of the largest single denominator (+ 256 bits).
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

/// sum / (a.den · b.den) as a reduced Rational.
Rational over_product(mpz_srcptr sum, const IntegerForm& a, const IntegerForm& b, Mpq& q) {
  mpz_set(mpq_numref(q.q), sum);
  mpz_mul(mpq_denref(q.q), a.den.z, b.den.z);
  mpq_canonicalize(q.q);
  return Rational(q.q);
}

}  // namespace

bool apply_fir_records_exact(const Mat<Rational>& taps, const Mat<Rational>& z, Eigen::Index ny, Eigen::Index horizon,
                             const std::vector<Eigen::Index>& lengths_in, Mat<Rational>& w) {
  const std::unique_ptr<IntegerForm> h = integer_form(taps), zi = integer_form(z);
  if (!h || !zi) return false;
  const RecordLengths lengths = record_lengths_of(lengths_in, z.rows());
  const std::vector<Eigen::Index> start = record_starts(lengths);
  const Eigen::Index nz = z.cols(), K = taps.rows();
  w = Mat<Rational>::Zero(z.rows(), ny);
  Mpz sum;
  Mpq q;
  for (size_t r = 0; r < lengths.size(); ++r) {
    const Eigen::Index s = start[r], m = std::max<Eigen::Index>(0, lengths[r] - horizon);
    for (Eigen::Index k = m; k < lengths[r]; ++k) {
      if (k % 256 == 0) check_stop();
      for (Eigen::Index i = 0; i < ny; ++i) {
        mpz_set_ui(sum.z, 0);
        for (Eigen::Index l = 0; l <= k - m && l < K; ++l)
          for (Eigen::Index j = 0; j < nz; ++j) mpz_addmul(sum.z, h->at(l, i * nz + j), zi->at(s + k - l, j));
        if (mpz_sgn(sum.z) != 0) w(s + k, i) = over_product(sum.z, *h, *zi, q);
      }
    }
  }
  return true;
}

bool fir_adjoint_records_exact(const Mat<Rational>& g, const Mat<Rational>& z, Eigen::Index horizon,
                               const std::vector<Eigen::Index>& lengths_in, Mat<Rational>& c) {
  const std::unique_ptr<IntegerForm> gi = integer_form(g), zi = integer_form(z);
  if (!gi || !zi) return false;
  const RecordLengths lengths = record_lengths_of(lengths_in, z.rows());
  const std::vector<Eigen::Index> start = record_starts(lengths);
  const Eigen::Index nz = z.cols(), ny = g.cols();
  c = Mat<Rational>::Zero(horizon, ny * nz);
  Mpz sum;
  Mpq q;
  for (Eigen::Index l = 0; l < horizon; ++l) {
    if (l % 64 == 0) check_stop();
    for (Eigen::Index i = 0; i < ny; ++i)
      for (Eigen::Index j = 0; j < nz; ++j) {
        mpz_set_ui(sum.z, 0);
        for (size_t r = 0; r < lengths.size(); ++r) {
          const Eigen::Index s = start[r], n = lengths[r], m = std::max<Eigen::Index>(0, n - horizon);
          for (Eigen::Index k = m + l; k < n; ++k) mpz_addmul(sum.z, gi->at(s + k, i), zi->at(s + k - l, j));
        }
        if (mpz_sgn(sum.z) != 0) c(l, i * nz + j) = over_product(sum.z, *gi, *zi, q);
      }
  }
  return true;
}

}  // namespace lpvid
