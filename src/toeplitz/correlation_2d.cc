#include "toeplitz/correlation_2d.h"

#include "toeplitz/fftw_support.h"

#include <cstring>
#include <mutex>
#include <new>

namespace lpvid {

using fftw::array;
using fftw::as_fftw;
using fftw::planner_mutex;
using fftw::smooth_size;

CorrelationGrid::CorrelationGrid(Eigen::Index L) : L_(L), M_(smooth_size(2 * L)), H_(M_ / 2 + 1) {
  const int m = static_cast<int>(M_);
  const std::size_t real_size = static_cast<std::size_t>(M_ * M_), half_size = static_cast<std::size_t>(M_ * H_);
  auto real = array<double>(real_size);
  auto half = array<std::complex<double>>(half_size);
  std::lock_guard<std::mutex> lock(planner_mutex());
  // FFTW_ESTIMATE does not touch the arrays while planning.
  forward_ = fftw_plan_dft_r2c_2d(m, m, real.get(), as_fftw(half.get()), FFTW_ESTIMATE);
  backward_ = fftw_plan_dft_c2r_2d(m, m, as_fftw(half.get()), real.get(), FFTW_ESTIMATE);
  backward_in_place_ = fftw_plan_dft_c2r_2d(m, m, as_fftw(half.get()), reinterpret_cast<double*>(half.get()), FFTW_ESTIMATE);
  if (!forward_ || !backward_ || !backward_in_place_) throw std::runtime_error("FFTW could not plan a " + std::to_string(m) + "^2 transform");
}

CorrelationGrid::~CorrelationGrid() {
  std::lock_guard<std::mutex> lock(planner_mutex());
  if (forward_) fftw_destroy_plan(static_cast<fftw_plan>(forward_));
  if (backward_) fftw_destroy_plan(static_cast<fftw_plan>(backward_));
  if (backward_in_place_) fftw_destroy_plan(static_cast<fftw_plan>(backward_in_place_));
}

void CorrelationGrid::forward(double* real, Spectrum& out) const {
  if (!out.data) out.data = array<std::complex<double>>(static_cast<std::size_t>(M_ * H_));
  fftw_execute_dft_r2c(static_cast<fftw_plan>(forward_), real, as_fftw(out.data.get()));
}

Spectrum CorrelationGrid::spectrum(const Mat<double>& X) const {
  auto real = array<double>(static_cast<std::size_t>(M_ * M_));
  std::memset(real.get(), 0, sizeof(double) * static_cast<std::size_t>(M_ * M_));
  for (Eigen::Index i = 0; i < X.rows(); ++i)
    for (Eigen::Index j = 0; j < X.cols(); ++j) real.get()[i * M_ + j] = X(i, j);
  Spectrum s;
  forward(real.get(), s);
  return s;
}

void CorrelationGrid::inverse_into(std::complex<double>* product, double* real, Mat<double>& out) const {
  fftw_execute_dft_c2r(static_cast<fftw_plan>(backward_), as_fftw(product), real);  // unnormalised
  const double scale = 1.0 / (static_cast<double>(M_) * static_cast<double>(M_));
  out.resize(L_, L_);
  for (Eigen::Index p = 0; p < L_; ++p)
    for (Eigen::Index q = 0; q < L_; ++q) out(p, q) = real[p * M_ + q] * scale;
}

void CorrelationGrid::inverse_in_place(std::complex<double>* product, Mat<double>& out) const {
  double* real = reinterpret_cast<double*>(product);
  fftw_execute_dft_c2r(static_cast<fftw_plan>(backward_in_place_), as_fftw(product), real);  // unnormalised
  const double scale = 1.0 / (static_cast<double>(M_) * static_cast<double>(M_));
  const Eigen::Index stride = 2 * H_;
  out.resize(L_, L_);
  for (Eigen::Index p = 0; p < L_; ++p)
    for (Eigen::Index q = 0; q < L_; ++q) out(p, q) = real[p * stride + q] * scale;
}

Mat<double> CorrelationGrid::inverse(std::complex<double>* product) const {
  auto real = array<double>(static_cast<std::size_t>(M_ * M_));
  Mat<double> out;
  inverse_into(product, real.get(), out);
  return out;
}

Mat<double> CorrelationGrid::correlate(const Spectrum& X_hat, const Spectrum& Y_hat, int sign) const {
  auto product = array<std::complex<double>>(static_cast<std::size_t>(M_ * H_));
  const std::complex<double>*x = X_hat.data.get(), *y = Y_hat.data.get();
  std::complex<double>* o = product.get();
  for (Eigen::Index u = 0; u < M_; ++u) {
    // sign −1: the spectrum of a(p, −q) is conj(â(−u, v)).
    const Eigen::Index uu = sign > 0 ? u : (M_ - u) % M_;
    for (Eigen::Index v = 0; v < H_; ++v) {
      const std::complex<double> c = x[uu * H_ + v] * std::conj(y[uu * H_ + v]);
      o[u * H_ + v] = sign > 0 ? c : std::conj(c);
    }
  }
  return inverse(o);
}

void CorrelationGrid::product_sum(const Spectrum& A_hat, const Spectrum& B_hat, const Spectrum& C_hat,
                                  const Spectrum& D_hat, std::complex<double>* o) const {
  const std::complex<double>*a = A_hat.data.get(), *b = B_hat.data.get(), *c = C_hat.data.get(), *d = D_hat.data.get();
  for (Eigen::Index u = 0; u < M_; ++u) {
    const Eigen::Index uu = (M_ - u) % M_;
    for (Eigen::Index v = 0; v < H_; ++v)
      o[u * H_ + v] = std::conj(a[uu * H_ + v] * std::conj(b[uu * H_ + v])) + c[u * H_ + v] * std::conj(d[u * H_ + v]);
  }
}

Mat<double> CorrelationGrid::correlate_sum(const Spectrum& A_hat, const Spectrum& B_hat, const Spectrum& C_hat,
                                           const Spectrum& D_hat) const {
  auto product = array<std::complex<double>>(static_cast<std::size_t>(M_ * H_));
  product_sum(A_hat, B_hat, C_hat, D_hat, product.get());
  return inverse(product.get());
}

CorrelationWorkspace::CorrelationWorkspace(const CorrelationGrid& grid) : grid_(grid) {}

double* CorrelationWorkspace::real() {
  if (!real_) real_ = array<double>(static_cast<std::size_t>(grid_.M_ * grid_.M_));
  return real_.get();
}

std::shared_ptr<std::complex<double>> CorrelationWorkspace::fftw_array(std::size_t count) {
  return array<std::complex<double>>(count);
}

void CorrelationWorkspace::release() {
  real_.reset();
  real_zero_padded_ = false;
  product_.reset();
}

void CorrelationWorkspace::reflect_product(Spectrum& A_hat, const Spectrum& B_hat) const {
  const Eigen::Index M = grid_.M_, H = grid_.H_;
  std::complex<double>* a = A_hat.data.get();
  const std::complex<double>* b = B_hat.data.get();
  for (Eigen::Index u = 0; 2 * u <= M; ++u) {
    const Eigen::Index uu = (M - u) % M;
    for (Eigen::Index v = 0; v < H; ++v) {
      const std::complex<double> at_u = std::conj(a[uu * H + v] * std::conj(b[uu * H + v]));
      a[uu * H + v] = std::conj(a[u * H + v] * std::conj(b[u * H + v]));
      a[u * H + v] = at_u;
    }
  }
}

void CorrelationWorkspace::correlate_reflected(const Spectrum& S, Spectrum& C_hat, const Spectrum& D_hat,
                                               Mat<double>& out) {
  const Eigen::Index n = grid_.M_ * grid_.H_;
  const std::complex<double>*s = S.data.get(), *d = D_hat.data.get();
  std::complex<double>* c = C_hat.data.get();
  for (Eigen::Index k = 0; k < n; ++k) c[k] = s[k] + c[k] * std::conj(d[k]);
  grid_.inverse_in_place(c, out);
}

void CorrelationWorkspace::correlate_sum(const Spectrum& A_hat, const Spectrum& B_hat, Spectrum& C_hat,
                                         const Spectrum& D_hat, Mat<double>& out, bool consume_C) {
  if (!consume_C && !product_) product_ = array<std::complex<double>>(static_cast<std::size_t>(grid_.M_ * grid_.H_));
  // in place into C: entry (u, v) of the product reads C at (u, v) only
  std::complex<double>* product = consume_C ? C_hat.data.get() : product_.get();
  grid_.product_sum(A_hat, B_hat, C_hat, D_hat, product);
  grid_.inverse_in_place(product, out);
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
