#include "toeplitz/correlation_2d.h"

#include <unsupported/Eigen/FFT>

namespace lpvid {

namespace {

/// The smallest M ≥ n whose prime factors are 2, 3 and 5 (fast radices).
Eigen::Index smooth_size(Eigen::Index n) {
  for (Eigen::Index m = std::max<Eigen::Index>(n, 1);; ++m) {
    Eigen::Index k = m;
    for (const Eigen::Index f : {2, 3, 5})
      while (k % f == 0) k /= f;
    if (k == 1) return m;
  }
}

/// In-place 2-D DFT (forward or inverse, unnormalised) of an M × M array.
void fft_2d(Eigen::MatrixXcd& a, bool inverse) {
  Eigen::FFT<double> fft;
  const Eigen::Index M = a.rows();
  Eigen::VectorXcd in(M), out(M);
  for (int pass = 0; pass < 2; ++pass) {
    for (Eigen::Index c = 0; c < M; ++c) {
      in = a.col(c);
      if (inverse)
        fft.inv(out, in);
      else
        fft.fwd(out, in);
      a.col(c) = out;
    }
    a.transposeInPlace();
  }
}

}  // namespace

CorrelationGrid::CorrelationGrid(Eigen::Index L) : L_(L), M_(smooth_size(2 * L)) {}

Eigen::MatrixXcd CorrelationGrid::spectrum(const Mat<double>& X) const {
  Eigen::MatrixXcd a = Eigen::MatrixXcd::Zero(M_, M_);
  a.topLeftCorner(X.rows(), X.cols()) = X.cast<std::complex<double>>();
  fft_2d(a, false);
  return a;
}

Mat<double> CorrelationGrid::correlate(const Eigen::MatrixXcd& X_hat, const Eigen::MatrixXcd& Y_hat, int sign) const {
  // Σ X(i+p, j+q) Y(i, j) = IDFT(X̂ · conj(Ŷ))(p, q) on the padded grid
  // (no wrap-around: M ≥ 2L). Eigen's inverse FFT is normalised per pass.
  Eigen::MatrixXcd a = X_hat.cwiseProduct(Y_hat.conjugate());
  fft_2d(a, true);
  Mat<double> out(L_, L_);
  for (Eigen::Index p = 0; p < L_; ++p)
    for (Eigen::Index q = 0; q < L_; ++q) out(p, q) = a(p, sign > 0 ? q : (M_ - q) % M_).real();
  return out;
}

Mat<double> correlate_direct(const Mat<double>& X, const Mat<double>& Y, int sign) {
  const Eigen::Index L = X.rows();
  Mat<double> out = Mat<double>::Zero(L, L);
  for (Eigen::Index p = 0; p < L; ++p)
    for (Eigen::Index q = 0; q < L; ++q)
      for (Eigen::Index i = 0; i + p < L; ++i)
        for (Eigen::Index j = 0; j < L; ++j) {
          const Eigen::Index jj = j + sign * q;
          if (jj >= 0 && jj < L) out(p, q) += X(i + p, jj) * Y(i, j);
        }
  return out;
}

}  // namespace lpvid
