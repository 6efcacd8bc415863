#include "toeplitz/exact_convolution.h"

#include <algorithm>
#include <memory>

#include "core/gmp_raii.h"
#include "core/integer_form.h"
#include "core/stop_request.h"
#include "toeplitz/record_lengths.h"

namespace lpvid {

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
