#include "toeplitz/tap_toeplitz.h"

#include "toeplitz/fftw_support.h"

#include <algorithm>
#include <complex>
#include <cstring>
#include <mutex>
#include <new>
#include <vector>

namespace lpvid {

using fftw::array;
using fftw::as_fftw;
using fftw::planner_mutex;
using fftw::smooth_size;

Mat<double> tap_gram(const Mat<double>& taps, Eigen::Index ny, Eigen::Index nz) {
  Mat<double> G;
  tap_gram_into(taps, ny, nz, G);
  return G;
}

void tap_gram_into(const Mat<double>& taps, Eigen::Index ny, Eigen::Index nz, Mat<double>& G) {
  const Eigen::Index L = taps.rows(), P = L * ny;
  G.resize(P, P);
  for (Eigen::Index a = 0; a < L; ++a)
    for (Eigen::Index a2 = 0; a2 < L; ++a2)
      for (Eigen::Index i = 0; i < ny; ++i)
        for (Eigen::Index i2 = 0; i2 < ny; ++i2) {
          double v = a > 0 && a2 > 0 ? G((a - 1) * ny + i, (a2 - 1) * ny + i2) : 0.0;
          for (Eigen::Index j = 0; j < nz; ++j) v += taps(a, i * nz + j) * taps(a2, i2 * nz + j);
          G(a * ny + i, a2 * ny + i2) = v;
        }
}

ToeplitzProduct::ToeplitzProduct(const Mat<double>& taps, Eigen::Index ny, Eigen::Index nz)
    : L_(taps.rows()), ny_(ny), nz_(nz), M_(smooth_size(2 * taps.rows())), H_(M_ / 2 + 1) {
  auto real = array<double>(static_cast<std::size_t>(M_));
  auto half = array<std::complex<double>>(static_cast<std::size_t>(H_));
  {
    std::lock_guard<std::mutex> lock(planner_mutex());
    forward_ = fftw_plan_dft_r2c_1d(static_cast<int>(M_), real.get(), as_fftw(half.get()), FFTW_ESTIMATE);
    backward_ = fftw_plan_dft_c2r_1d(static_cast<int>(M_), as_fftw(half.get()), real.get(), FFTW_ESTIMATE);
  }
  if (!forward_ || !backward_) throw std::runtime_error("FFTW could not plan a length-" + std::to_string(M_) + " transform");
  h_hat_ = array<std::complex<double>>(static_cast<std::size_t>(ny * nz * H_));
  set_taps(taps);
}

void ToeplitzProduct::set_taps(const Mat<double>& taps) {
  if (taps.rows() != L_ || taps.cols() != ny_ * nz_) throw std::invalid_argument("ToeplitzProduct: taps of another size");
  auto real = array<double>(static_cast<std::size_t>(M_));
  for (Eigen::Index c = 0; c < ny_ * nz_; ++c) {
    std::memset(real.get(), 0, sizeof(double) * static_cast<std::size_t>(M_));
    for (Eigen::Index l = 0; l < L_; ++l) real.get()[l] = taps(l, c);
    fftw_execute_dft_r2c(static_cast<fftw_plan>(forward_), real.get(), as_fftw(h_hat_.get() + c * H_));
  }
}

ToeplitzProduct::~ToeplitzProduct() {
  std::lock_guard<std::mutex> lock(planner_mutex());
  if (forward_) fftw_destroy_plan(static_cast<fftw_plan>(forward_));
  if (backward_) fftw_destroy_plan(static_cast<fftw_plan>(backward_));
}

namespace {
/// Rows transformed together: right_into gathers them from X's columns a
/// cache line at a time (X is column-major; one row alone is strided).
constexpr Eigen::Index kRowBlock = 8;
/// n rounded up to a multiple of k (each row's buffers keep the planned arrays' alignment).
Eigen::Index round_up(Eigen::Index n, Eigen::Index k) { return (n + k - 1) / k * k; }
}  // namespace

template <typename Gather, typename Scatter>
void ToeplitzProduct::apply(Eigen::Index rows, Gather gather, Scatter scatter) const {
  const Eigen::Index Ms = round_up(M_, 8), Hs = round_up(H_, 4);  // per-row strides: 64-byte steps
  auto real = array<double>(static_cast<std::size_t>(kRowBlock * Ms));
  auto x_hat = array<std::complex<double>>(static_cast<std::size_t>(kRowBlock * ny_ * Hs));
  auto acc = array<std::complex<double>>(static_cast<std::size_t>(H_));
  const double scale = 1.0 / static_cast<double>(M_);
  const std::complex<double>* h = h_hat_.get();
  for (Eigen::Index row0 = 0; row0 < rows; row0 += kRowBlock) {
    const Eigen::Index n = std::min(kRowBlock, rows - row0);
    for (Eigen::Index i = 0; i < ny_; ++i) {
      std::memset(real.get(), 0, sizeof(double) * static_cast<std::size_t>(kRowBlock * Ms));
      gather(row0, n, i, real.get(), Ms);  // real[k·Ms + c] ← sample c of input i in row row0 + k
      for (Eigen::Index k = 0; k < n; ++k)
        fftw_execute_dft_r2c(static_cast<fftw_plan>(forward_), real.get() + k * Ms, as_fftw(x_hat.get() + (k * ny_ + i) * Hs));
    }
    for (Eigen::Index j = 0; j < nz_; ++j) {
      for (Eigen::Index k = 0; k < n; ++k) {
        // Σ_{i'} corr(x_{i'}, h_{i'j}) = IDFT(Σ_{i'} x̂_{i'}·conj(ĥ_{i'j})); no wrap-around (M ≥ 2L).
        std::complex<double>* a = acc.get();
        for (Eigen::Index v = 0; v < H_; ++v) a[v] = 0.0;
        for (Eigen::Index i = 0; i < ny_; ++i) {
          const std::complex<double>* xs = x_hat.get() + (k * ny_ + i) * Hs;
          const std::complex<double>* hs = h + (i * nz_ + j) * H_;
          for (Eigen::Index v = 0; v < H_; ++v) a[v] += xs[v] * std::conj(hs[v]);
        }
        fftw_execute_dft_c2r(static_cast<fftw_plan>(backward_), as_fftw(a), real.get() + k * Ms);
      }
      scatter(row0, n, j, real.get(), Ms, scale);  // (X·T)(row0 + k, b·nz + j) ← real[k·Ms + b]·scale
    }
  }
}

void ToeplitzProduct::right_into(const Mat<double>& X, Mat<double>& out) const {
  if (X.cols() != L_ * ny_) throw std::invalid_argument("ToeplitzProduct: X has " + std::to_string(X.cols()) + " columns");
  out.resize(X.rows(), L_ * nz_);
  apply(
      X.rows(),
      [&](Eigen::Index row0, Eigen::Index n, Eigen::Index i, double* real, Eigen::Index Ms) {
        for (Eigen::Index c = 0; c < L_; ++c)
          for (Eigen::Index k = 0; k < n; ++k) real[k * Ms + c] = X(row0 + k, c * ny_ + i);
      },
      [&](Eigen::Index row0, Eigen::Index n, Eigen::Index j, const double* real, Eigen::Index Ms, double scale) {
        for (Eigen::Index b = 0; b < L_; ++b)
          for (Eigen::Index k = 0; k < n; ++k) out(row0 + k, b * nz_ + j) = real[k * Ms + b] * scale;
      });
}

void ToeplitzProduct::left_into(const Mat<double>& Y, Mat<double>& out) const {
  if (Y.rows() != L_ * ny_) throw std::invalid_argument("ToeplitzProduct: Y has " + std::to_string(Y.rows()) + " rows");
  out.resize(L_ * nz_, Y.cols());
  apply(
      Y.cols(),
      [&](Eigen::Index col0, Eigen::Index n, Eigen::Index i, double* real, Eigen::Index Ms) {
        for (Eigen::Index k = 0; k < n; ++k)
          for (Eigen::Index c = 0; c < L_; ++c) real[k * Ms + c] = Y(c * ny_ + i, col0 + k);
      },
      [&](Eigen::Index col0, Eigen::Index n, Eigen::Index j, const double* real, Eigen::Index Ms, double scale) {
        for (Eigen::Index k = 0; k < n; ++k)
          for (Eigen::Index b = 0; b < L_; ++b) out(b * nz_ + j, col0 + k) = real[k * Ms + b] * scale;
      });
}

Mat<double> ToeplitzProduct::right(const Mat<double>& X) const {
  Mat<double> out;
  right_into(X, out);
  return out;
}

}  // namespace lpvid
