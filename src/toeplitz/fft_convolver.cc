#include "toeplitz/fft_convolver.h"

#include <fftw3.h>

#include <algorithm>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>

#include "toeplitz/fftw_support.h"

namespace lpvid {

using fftw::array;
using fftw::as_fftw;

FftConvolver::FftConvolver(Eigen::Index L)
    : L_(L), M_(fftw::smooth_size(std::max<Eigen::Index>(2 * L, 2))), H_(M_ / 2 + 1) {
  real_ = array<double>(static_cast<std::size_t>(M_));
  half_ = array<std::complex<double>>(static_cast<std::size_t>(H_));
  {
    std::lock_guard<std::mutex> lock(fftw::planner_mutex());
    forward_ = fftw_plan_dft_r2c_1d(static_cast<int>(M_), real_.get(), as_fftw(half_.get()), FFTW_ESTIMATE);
    backward_ = fftw_plan_dft_c2r_1d(static_cast<int>(M_), as_fftw(half_.get()), real_.get(), FFTW_ESTIMATE);
  }
  if (!forward_ || !backward_) throw std::runtime_error("FFTW could not plan a length-" + std::to_string(M_) + " transform");
}

FftConvolver::~FftConvolver() {
  std::lock_guard<std::mutex> lock(fftw::planner_mutex());
  if (forward_) fftw_destroy_plan(static_cast<fftw_plan>(forward_));
  if (backward_) fftw_destroy_plan(static_cast<fftw_plan>(backward_));
}

FftConvolver::Spectrum FftConvolver::spectrum(const Eigen::VectorXd& v) const {
  if (v.size() > L_) throw std::invalid_argument("FftConvolver: a vector longer than the convolver's length");
  double* x = real_.get();
  std::memset(x, 0, sizeof(double) * static_cast<std::size_t>(M_));
  std::copy(v.data(), v.data() + v.size(), x);
  fftw_execute(static_cast<fftw_plan>(forward_));
  ++transforms_;
  return Spectrum(half_.get(), half_.get() + H_);
}

Eigen::VectorXd FftConvolver::samples(const Spectrum& s) const {
  if (static_cast<Eigen::Index>(s.size()) != H_) throw std::invalid_argument("FftConvolver: a spectrum of another size");
  std::copy(s.begin(), s.end(), half_.get());
  fftw_execute(static_cast<fftw_plan>(backward_));
  ++transforms_;
  Eigen::VectorXd out(L_);
  const double scale = 1.0 / static_cast<double>(M_);
  for (Eigen::Index i = 0; i < L_; ++i) out(i) = real_.get()[i] * scale;
  return out;
}

FftConvolver::Spectrum spectrum_product(const FftConvolver::Spectrum& a, const FftConvolver::Spectrum& b) {
  FftConvolver::Spectrum out(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) out[i] = a[i] * b[i];
  return out;
}

FftConvolver::Spectrum spectrum_conj_product(const FftConvolver::Spectrum& a, const FftConvolver::Spectrum& b) {
  FftConvolver::Spectrum out(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) out[i] = std::conj(a[i]) * b[i];
  return out;
}

void spectrum_add(FftConvolver::Spectrum& acc, double c, const FftConvolver::Spectrum& x) {
  for (std::size_t i = 0; i < acc.size(); ++i) acc[i] += c * x[i];
}

}  // namespace lpvid
