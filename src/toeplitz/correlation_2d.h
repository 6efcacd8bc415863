#pragma once
/// Two-dimensional cross-correlations of square matrices by FFT, the kernel
/// of the structured (Toeplitz) Hessian in lmi/delta_form_barrier.h.
///
///   corr(X, Y)(p, q) = Σ_{i,j} X(i + p, j + q) · Y(i, j)
///
/// (entries outside X are zero). For L × L inputs and shifts p ∈ [0, L),
/// q ∈ (−L, L) this costs O(L² log L) instead of the O(L⁴) of the sum.
///
/// The inputs are real, so their spectra are kept as real-to-complex half
/// spectra (FFTW, M × (M/2 + 1) of the zero-padded M × M grid, M ≥ 2L):
/// corr(X, Y) = IDFT(X̂ · conj(Ŷ)) without wrap-around. A sum of two
/// correlations is formed in the frequency domain and inverted once; the
/// shift q → −q of one of them is, for a real signal a with a'(p, q) =
/// a(p, −q), â'(u, v) = â(u, −v) = conj(â(−u, v)) (Hermitian symmetry), which
/// the half spectrum holds.

#include <algorithm>
#include <complex>
#include <memory>

#include "core/scalar.h"

namespace lpvid {

/// The half spectrum of an L × L real matrix on a CorrelationGrid.
struct Spectrum {
  std::shared_ptr<std::complex<double>> data;  ///< M × (M/2 + 1), row-major; FFTW-aligned
};

/// The spectra of L × L real matrices zero-padded to an M × M grid
/// (M ≥ 2L), reused across several correlations. Its methods may be called
/// from several threads at once (FFTW's new-array execute functions).
class CorrelationGrid {
 public:
  explicit CorrelationGrid(Eigen::Index L);
  ~CorrelationGrid();
  CorrelationGrid(const CorrelationGrid&) = delete;
  CorrelationGrid& operator=(const CorrelationGrid&) = delete;
  Eigen::Index size() const { return M_; }
  /// The 2-D DFT of X (L × L), zero-padded to M × M (half spectrum).
  Spectrum spectrum(const Mat<double>& X) const;
  /// corr(X, Y)(p, sign·q) for p, q ∈ [0, L) from the spectra of X and Y:
  /// sign = +1 gives shifts q ≥ 0, sign = −1 gives q ≤ 0.
  Mat<double> correlate(const Spectrum& X_hat, const Spectrum& Y_hat, int sign) const;
  /// corr(A, B)(p, −q) + corr(C, D)(p, q) for p, q ∈ [0, L), with one
  /// inverse transform.
  Mat<double> correlate_sum(const Spectrum& A_hat, const Spectrum& B_hat, const Spectrum& C_hat,
                            const Spectrum& D_hat) const;

 private:
  friend class CorrelationWorkspace;
  /// out ← the transform of the M × M grid `real` (out's array allocated when empty).
  void forward(double* real, Spectrum& out) const;
  /// out (L × L) ← the normalised inverse of `product` through the M × M grid `real` (product is destroyed).
  void inverse_into(std::complex<double>* product, double* real, Mat<double>& out) const;
  /// The same in place: the grid overwrites `product` (rows of 2·(M/2 + 1)
  /// reals). FFTW's in-place and out-of-place c2r give the same bits here
  /// (correlation_2d_test.cc checks it), in ~2/3 of the time and without
  /// writing the M × M real grid.
  void inverse_in_place(std::complex<double>* product, Mat<double>& out) const;
  /// o ← conj(Â(−u, v)·conj(B̂(−u, v))) + Ĉ·conj(D̂), the spectrum of correlate_sum.
  void product_sum(const Spectrum& A_hat, const Spectrum& B_hat, const Spectrum& C_hat, const Spectrum& D_hat,
                   std::complex<double>* o) const;
  Mat<double> inverse(std::complex<double>* product) const;
  Eigen::Index L_, M_, H_;  ///< H = M/2 + 1
  void* forward_ = nullptr;  ///< fftw_plan (r2c)
  void* backward_ = nullptr;  ///< fftw_plan (c2r)
  void* backward_in_place_ = nullptr;  ///< fftw_plan (c2r, in place)
};

/// One caller's buffers on a CorrelationGrid (the zero-padded M × M real
/// grid and a product spectrum), allocated once: the spectra and correlation
/// sums of a Newton step without an allocation (nor the page faults of fresh
/// memory) per call, bit for bit CorrelationGrid::spectrum and correlate_sum.
/// Not for several threads at once.
class CorrelationWorkspace {
 public:
  explicit CorrelationWorkspace(const CorrelationGrid& grid);
  /// out ← the spectrum of x (any L × L expression: a strided sub-block, a
  /// transpose), reusing out's array.
  template <typename X>
  void spectrum(const Eigen::MatrixBase<X>& x, Spectrum& out) {
    double* real = this->real();
    // FFTW's out-of-place r2c keeps its input and the inverses run in place:
    // outside the L × L corner the grid stays zero once it is
    fill_grid(x, real, !real_zero_padded_);
    real_zero_padded_ = true;
    grid_.forward(real, out);
  }
  /// The same with `scratch`'s array (an M × (M/2 + 1) spectrum not needed
  /// now) as the real grid, for a second thread: the same input, the same bits.
  template <typename X>
  void spectrum_via(const Eigen::MatrixBase<X>& x, Spectrum& out, Spectrum& scratch) const {
    if (!scratch.data) scratch.data = fftw_array(static_cast<std::size_t>(grid_.M_ * grid_.H_));
    double* real = reinterpret_cast<double*>(scratch.data.get());
    fill_grid(x, real, true);
    grid_.forward(real, out);
  }
  /// out ← grid.correlate_sum(A, B, C, D) (L × L). consume_C: C's last use,
  /// its array holds the product (and is overwritten; one M × (M/2 + 1)
  /// buffer less, the product buffer is allocated at its first use only).
  void correlate_sum(const Spectrum& A_hat, const Spectrum& B_hat, Spectrum& C_hat, const Spectrum& D_hat,
                     Mat<double>& out, bool consume_C = false);
  /// A ← the first term of correlate_sum, conj(Â(−u, v)·conj(B̂(−u, v))), in
  /// A's own array (rows u and −u together), so that B's array is free for
  /// the next spectrum: one spectrum less at a time for a single pair.
  void reflect_product(Spectrum& A_hat, const Spectrum& B_hat) const;
  /// out ← the inverse of S + Ĉ·conj(D̂), S from reflect_product: bit for bit
  /// correlate_sum(A, B, C, D, out, true) (C's array takes the sum).
  void correlate_reflected(const Spectrum& S, Spectrum& C_hat, const Spectrum& D_hat, Mat<double>& out);
  /// Frees the grid and the product buffer (allocated again at their next use).
  void release();

 private:
  double* real();
  /// The M × M grid ← x in its L × L corner, zeros elsewhere (only the corner when `padding` is false).
  template <typename X>
  void fill_grid(const Eigen::MatrixBase<X>& x, double* real, bool padding) const {
    const Eigen::Index M = grid_.size();
    if (padding) std::fill(real, real + M * M, 0.0);
    for (Eigen::Index i = 0; i < x.rows(); ++i)
      for (Eigen::Index j = 0; j < x.cols(); ++j) real[i * M + j] = x(i, j);
  }
  static std::shared_ptr<std::complex<double>> fftw_array(std::size_t count);
  const CorrelationGrid& grid_;
  std::shared_ptr<double> real_;
  bool real_zero_padded_ = false;  ///< real_ is zero outside the L × L corner
  std::shared_ptr<std::complex<double>> product_;  ///< empty until a correlation needs it
};

/// The same sum evaluated directly, O(L⁴): the reference for tests.
Mat<double> correlate_direct(const Mat<double>& X, const Mat<double>& Y, int sign);

}  // namespace lpvid
