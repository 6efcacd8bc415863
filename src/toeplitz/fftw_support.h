#pragma once
/// What the FFTW users (toeplitz/correlation_2d.h, toeplitz/tap_toeplitz.h)
/// share: one planner lock (FFTW's planner is not thread-safe; execution on
/// new arrays is), FFTW-aligned arrays, fast transform sizes.

#include <fftw3.h>

#include <complex>
#include <memory>
#include <mutex>

#include "core/scalar.h"

namespace lpvid::fftw {

/// Held while making or destroying any plan, process-wide.
std::mutex& planner_mutex();

/// The smallest M ≥ n whose prime factors are 2, 3 and 5 (fast radices).
Eigen::Index smooth_size(Eigen::Index n);

/// `count` elements from fftw_malloc (the alignment FFTW's plans assume).
template <typename T>
std::shared_ptr<T> array(std::size_t count) {
  void* p = fftw_malloc(sizeof(T) * (count > 0 ? count : 1));
  if (!p) throw std::bad_alloc();
  return std::shared_ptr<T>(static_cast<T*>(p), [](T* q) { fftw_free(q); });
}

inline fftw_complex* as_fftw(std::complex<double>* p) { return reinterpret_cast<fftw_complex*>(p); }

}  // namespace lpvid::fftw
