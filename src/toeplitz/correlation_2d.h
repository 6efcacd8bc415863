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
#include <functional>
#include <memory>

#include "core/scalar.h"

namespace lpvid {

class HelperThread;

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
  /// The transforms of a Newton step, as FFTW's 2-D plans compute them
  /// (a 2-D r2c is 1-D r2c's along the rows, then 1-D c2c's down the
  /// columns; c2r the reverse), written out so that (a) a helper thread
  /// takes half of the rows and half of the columns, (b) the forward skips
  /// the M − L rows that are zero (their transforms are zero) and (c) the
  /// inverse transforms only the L rows that are kept, in place. Each 1-D
  /// transform is the one the 2-D plan runs: the same bits
  /// (tests/toeplitz/correlation_2d_test.cc, WorkspaceIsBitIdentical…), in
  /// about a third of the time on two threads.
  ///
  /// out ← the spectrum of the grid whose first L rows (of M reals each,
  /// zero from column L on) are `rows`; the rest of the grid is zero.
  void forward_rows(const double* rows, std::complex<double>* out, HelperThread* helper,
                    const std::function<void(Eigen::Index, Eigen::Index)>& fill_rows) const;
  /// out (L × L) ← the normalised inverse of `product`, in place (product is destroyed).
  void inverse_in_place(std::complex<double>* product, Mat<double>& out, HelperThread* helper) const;
  /// o ← conj(Â(−u, v)·conj(B̂(−u, v))) + Ĉ·conj(D̂), the spectrum of correlate_sum.
  void product_sum(const Spectrum& A_hat, const Spectrum& B_hat, const Spectrum& C_hat, const Spectrum& D_hat,
                   std::complex<double>* o, Eigen::Index u0, Eigen::Index u1) const;  ///< rows u ∈ [u0, u1) of o
  Mat<double> inverse(std::complex<double>* product) const;
  Eigen::Index L_, M_, H_;  ///< H = M/2 + 1
  void* forward_ = nullptr;  ///< fftw_plan (r2c)
  void* backward_ = nullptr;  ///< fftw_plan (c2r)
  /// The split plans (index 0: the caller's part, 1: the helper's): row r2c's
  /// of rows [0, r) and [r, L), column c2c's (forward, backward, in place) of
  /// columns [0, c) and [c, H), row c2r's (in place) of rows [0, r) and [r, L).
  void* rows_forward_[2] = {nullptr, nullptr};
  void* columns_forward_[2] = {nullptr, nullptr};
  void* columns_backward_[2] = {nullptr, nullptr};
  void* rows_backward_[2] = {nullptr, nullptr};
  Eigen::Index row_split_ = 0, column_split_ = 0;
  void make_split_plans();
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
    const Eigen::Index M = grid_.M_;
    double* real = this->real();  // L rows of M: FFTW's r2c keeps its input, so columns ≥ L stay zero
    if (!out.data) out.data = fftw_array(static_cast<std::size_t>(grid_.M_ * grid_.H_));
    grid_.forward_rows(real, out.data.get(), helper_, [&](Eigen::Index r0, Eigen::Index r1) {
      for (Eigen::Index i = r0; i < r1; ++i)
        for (Eigen::Index j = 0; j < x.cols(); ++j) real[i * M + j] = x(i, j);
    });
  }
  /// A helper thread for the transforms (null: the caller alone; the same numbers).
  void set_helper(HelperThread* helper) { helper_ = helper; }
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
  /// The first L rows of the M × M real grid (zero from column L on).
  double* real();
  /// reflect_product for the row pairs (u, −u) with u ∈ [u0, u1).
  void reflect_rows(Spectrum& A_hat, const Spectrum& B_hat, Eigen::Index u0, Eigen::Index u1) const;
  static std::shared_ptr<std::complex<double>> fftw_array(std::size_t count);
  const CorrelationGrid& grid_;
  HelperThread* helper_ = nullptr;
  std::shared_ptr<double> real_;
  std::shared_ptr<std::complex<double>> product_;  ///< empty until a correlation needs it
};

/// The same sum evaluated directly, O(L⁴): the reference for tests.
Mat<double> correlate_direct(const Mat<double>& X, const Mat<double>& Y, int sign);

}  // namespace lpvid
