#pragma once
/// Products of length-L vectors by lower-triangular Toeplitz, upper-triangular
/// Toeplitz and Hankel matrices through real FFTs of one size M ≥ 2L − 1, so
/// that no product wraps around for the lags 0 … L−1 it returns:
///   conv(a, b)_i = Σ_{j ≤ i} a_j b_{i−j}   = (T_a b)_i      spectra A·B
///   corr(a, b)_i = Σ_j a_j b_{i+j}         = (T_aᵀ b)_i     spectra conj(A)·B
///   (H(u) w)_i   = Σ_k u_{i+k} w_k         = corr(w, u)_i   (H(u)(i, k) = u_{i+k}, zero past L−1)
/// Used by the long-horizon solver (lmi/long_horizon_barrier.h), where every
/// L × L operator is one of these or a sum of their products. A convolver owns
/// work arrays: one object per thread.

#include <complex>
#include <memory>
#include <vector>

#include "core/scalar.h"

namespace lpvid {

class FftConvolver {
 public:
  using Spectrum = std::vector<std::complex<double>>;

  explicit FftConvolver(Eigen::Index L);
  ~FftConvolver();
  FftConvolver(const FftConvolver&) = delete;
  FftConvolver& operator=(const FftConvolver&) = delete;

  Eigen::Index length() const { return L_; }
  Eigen::Index transform_size() const { return M_; }

  /// The half spectrum of v (length ≤ L), zero-padded to M.
  Spectrum spectrum(const Eigen::VectorXd& v) const;
  /// The samples 0 … L−1 of the inverse transform of s (divided by M).
  Eigen::VectorXd samples(const Spectrum& s) const;
  /// How many transforms this object has run (the work count benches print).
  long transforms() const { return transforms_; }

 private:
  Eigen::Index L_, M_, H_;
  void* forward_ = nullptr;
  void* backward_ = nullptr;
  std::shared_ptr<double> real_;
  std::shared_ptr<std::complex<double>> half_;
  mutable long transforms_ = 0;
};

/// a·b, entry by entry.
FftConvolver::Spectrum spectrum_product(const FftConvolver::Spectrum& a, const FftConvolver::Spectrum& b);
/// conj(a)·b, entry by entry (a correlation's spectrum).
FftConvolver::Spectrum spectrum_conj_product(const FftConvolver::Spectrum& a, const FftConvolver::Spectrum& b);
/// acc += c·x.
void spectrum_add(FftConvolver::Spectrum& acc, double c, const FftConvolver::Spectrum& x);

}  // namespace lpvid
