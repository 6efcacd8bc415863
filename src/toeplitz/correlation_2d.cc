#include "toeplitz/correlation_2d.h"

#include "toeplitz/fftw_support.h"

#include "core/helper_thread.h"

#include <cstring>
#include <mutex>
#include <new>

namespace lpvid {

using fftw::array;
using fftw::as_fftw;
using fftw::planner_mutex;
using fftw::smooth_size;

namespace {

/// body(i0, i1) for [0, n) in two halves, the second on the helper.
void split_range(HelperThread* helper, Eigen::Index n, const std::function<void(Eigen::Index, Eigen::Index)>& body) {
  fork_join(helper, [&] { body(n / 2, n); }, [&] { body(0, n / 2); });
}

/// The helper, for grids large enough that half a transform outweighs a
/// hand-over (measured: 3×3 n = 200, M = 400, was slower split; a MIMO
/// step spreads whole transforms instead, lmi/delta_form_barrier.cc).
HelperThread* helper_for_grid(HelperThread* helper, Eigen::Index M) { return M >= 1024 ? helper : nullptr; }

}  // namespace

CorrelationGrid::CorrelationGrid(Eigen::Index L) : L_(L), M_(smooth_size(2 * L)), H_(M_ / 2 + 1) {
  const int m = static_cast<int>(M_);
  const std::size_t real_size = static_cast<std::size_t>(M_ * M_), half_size = static_cast<std::size_t>(M_ * H_);
  auto real = array<double>(real_size);
  auto half = array<std::complex<double>>(half_size);
  std::lock_guard<std::mutex> lock(planner_mutex());
  // FFTW_ESTIMATE does not touch the arrays while planning.
  forward_ = fftw_plan_dft_r2c_2d(m, m, real.get(), as_fftw(half.get()), FFTW_ESTIMATE);
  backward_ = fftw_plan_dft_c2r_2d(m, m, as_fftw(half.get()), real.get(), FFTW_ESTIMATE);
  if (!forward_ || !backward_) throw std::runtime_error("FFTW could not plan a " + std::to_string(m) + "^2 transform");
  make_split_plans();
}

void CorrelationGrid::make_split_plans() {
  // FFTW_ESTIMATE does not touch the arrays; the new-array execute calls use
  // arrays at the same offsets from an fftw_malloc'd start (the same alignment)
  auto real = array<double>(static_cast<std::size_t>(L_ * M_));
  auto half = array<std::complex<double>>(static_cast<std::size_t>(M_ * H_));
  double* r = real.get();
  fftw_complex* h = as_fftw(half.get());
  const int m = static_cast<int>(M_), H = static_cast<int>(H_);
  int n[1] = {m};
  row_split_ = L_ / 2;
  column_split_ = H_ / 2;
  const int rows[2] = {static_cast<int>(row_split_), static_cast<int>(L_ - row_split_)};
  const int columns[2] = {static_cast<int>(column_split_), static_cast<int>(H_ - column_split_)};
  for (int k = 0; k < 2; ++k) {
    const Eigen::Index row0 = k == 0 ? 0 : row_split_, column0 = k == 0 ? 0 : column_split_;
    fftw_complex* spectrum_rows = h + row0 * H_;
    rows_forward_[k] = rows[k] == 0 ? nullptr
                                    : fftw_plan_many_dft_r2c(1, n, rows[k], r + row0 * M_, nullptr, 1, m, spectrum_rows,
                                                             nullptr, 1, H, FFTW_ESTIMATE);
    columns_forward_[k] = columns[k] == 0 ? nullptr
                                          : fftw_plan_many_dft(1, n, columns[k], h + column0, nullptr, H, 1, h + column0,
                                                               nullptr, H, 1, FFTW_FORWARD, FFTW_ESTIMATE);
    columns_backward_[k] = columns[k] == 0 ? nullptr
                                           : fftw_plan_many_dft(1, n, columns[k], h + column0, nullptr, H, 1, h + column0,
                                                                nullptr, H, 1, FFTW_BACKWARD, FFTW_ESTIMATE);
    rows_backward_[k] = rows[k] == 0 ? nullptr
                                     : fftw_plan_many_dft_c2r(1, n, rows[k], spectrum_rows, nullptr, 1, H,
                                                              reinterpret_cast<double*>(spectrum_rows), nullptr, 1, 2 * H,
                                                              FFTW_ESTIMATE);
    const bool missing = (rows[k] > 0 && (!rows_forward_[k] || !rows_backward_[k])) ||
                         (columns[k] > 0 && (!columns_forward_[k] || !columns_backward_[k]));
    if (missing) throw std::runtime_error("FFTW could not plan the row and column transforms of a " + std::to_string(m) + "^2 grid");
  }
}

CorrelationGrid::~CorrelationGrid() {
  std::lock_guard<std::mutex> lock(planner_mutex());
  if (forward_) fftw_destroy_plan(static_cast<fftw_plan>(forward_));
  if (backward_) fftw_destroy_plan(static_cast<fftw_plan>(backward_));
  for (void** plans : {rows_forward_, columns_forward_, columns_backward_, rows_backward_})
    for (int k = 0; k < 2; ++k)
      if (plans[k]) fftw_destroy_plan(static_cast<fftw_plan>(plans[k]));
}

void CorrelationGrid::forward_rows(const double* rows, std::complex<double>* out, HelperThread* helper,
                                   const std::function<void(Eigen::Index, Eigen::Index)>& fill_rows) const {
  const auto row_part = [&](int k) {
    const Eigen::Index row0 = k == 0 ? 0 : row_split_, row1 = k == 0 ? row_split_ : L_;
    fill_rows(row0, row1);
    if (rows_forward_[k])
      fftw_execute_dft_r2c(static_cast<fftw_plan>(rows_forward_[k]), const_cast<double*>(rows) + row0 * M_,
                           as_fftw(out + row0 * H_));
    // the zero rows' transforms are zero: rows L … M − 1, half each
    const Eigen::Index zero0 = L_ + (k == 0 ? 0 : (M_ - L_) / 2), zero1 = k == 0 ? L_ + (M_ - L_) / 2 : M_;
    std::fill(out + zero0 * H_, out + zero1 * H_, std::complex<double>(0.0, 0.0));
  };
  helper = helper_for_grid(helper, M_);
  fork_join(helper, [&] { row_part(1); }, [&] { row_part(0); });
  const auto column_part = [&](int k) {
    std::complex<double>* columns = out + (k == 0 ? 0 : column_split_);
    if (columns_forward_[k]) fftw_execute_dft(static_cast<fftw_plan>(columns_forward_[k]), as_fftw(columns), as_fftw(columns));
  };
  fork_join(helper, [&] { column_part(1); }, [&] { column_part(0); });
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

void CorrelationGrid::inverse_in_place(std::complex<double>* product, Mat<double>& out, HelperThread* helper) const {
  helper = helper_for_grid(helper, M_);
  const auto column_part = [&](int k) {
    std::complex<double>* columns = product + (k == 0 ? 0 : column_split_);
    if (columns_backward_[k]) fftw_execute_dft(static_cast<fftw_plan>(columns_backward_[k]), as_fftw(columns), as_fftw(columns));
  };
  fork_join(helper, [&] { column_part(1); }, [&] { column_part(0); });
  const double scale = 1.0 / (static_cast<double>(M_) * static_cast<double>(M_));
  const Eigen::Index stride = 2 * H_;
  out.resize(L_, L_);
  const auto row_part = [&](int k) {  // only the L rows kept, each in its own place (unnormalised, then scaled)
    const Eigen::Index row0 = k == 0 ? 0 : row_split_, row1 = k == 0 ? row_split_ : L_;
    std::complex<double>* rows = product + row0 * H_;
    if (rows_backward_[k])
      fftw_execute_dft_c2r(static_cast<fftw_plan>(rows_backward_[k]), as_fftw(rows), reinterpret_cast<double*>(rows));
    const double* real = reinterpret_cast<const double*>(product);
    for (Eigen::Index p = row0; p < row1; ++p)
      for (Eigen::Index q = 0; q < L_; ++q) out(p, q) = real[p * stride + q] * scale;
  };
  fork_join(helper, [&] { row_part(1); }, [&] { row_part(0); });
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
                                  const Spectrum& D_hat, std::complex<double>* o, Eigen::Index u0, Eigen::Index u1) const {
  const std::complex<double>*a = A_hat.data.get(), *b = B_hat.data.get(), *c = C_hat.data.get(), *d = D_hat.data.get();
  for (Eigen::Index u = u0; u < u1; ++u) {
    const Eigen::Index uu = (M_ - u) % M_;
    for (Eigen::Index v = 0; v < H_; ++v)
      o[u * H_ + v] = std::conj(a[uu * H_ + v] * std::conj(b[uu * H_ + v])) + c[u * H_ + v] * std::conj(d[u * H_ + v]);
  }
}

Mat<double> CorrelationGrid::correlate_sum(const Spectrum& A_hat, const Spectrum& B_hat, const Spectrum& C_hat,
                                           const Spectrum& D_hat) const {
  auto product = array<std::complex<double>>(static_cast<std::size_t>(M_ * H_));
  product_sum(A_hat, B_hat, C_hat, D_hat, product.get(), 0, M_);
  return inverse(product.get());
}

CorrelationWorkspace::CorrelationWorkspace(const CorrelationGrid& grid) : grid_(grid) {}

double* CorrelationWorkspace::real() {
  if (!real_) {
    const std::size_t size = static_cast<std::size_t>(grid_.L_ * grid_.M_);
    real_ = array<double>(size);
    std::fill(real_.get(), real_.get() + size, 0.0);
  }
  return real_.get();
}

std::shared_ptr<std::complex<double>> CorrelationWorkspace::fftw_array(std::size_t count) {
  return array<std::complex<double>>(count);
}

void CorrelationWorkspace::release() {
  real_.reset();
  product_.reset();
}


void CorrelationWorkspace::reflect_product(Spectrum& A_hat, const Spectrum& B_hat) const {
  split_range(helper_for_grid(helper_, grid_.M_), grid_.M_ / 2 + 1, [&](Eigen::Index u0, Eigen::Index u1) { reflect_rows(A_hat, B_hat, u0, u1); });
}

void CorrelationWorkspace::reflect_rows(Spectrum& A_hat, const Spectrum& B_hat, Eigen::Index u0, Eigen::Index u1) const {
  const Eigen::Index M = grid_.M_, H = grid_.H_;
  std::complex<double>* a = A_hat.data.get();
  const std::complex<double>* b = B_hat.data.get();
  for (Eigen::Index u = u0; u < u1 && 2 * u <= M; ++u) {
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
  split_range(helper_for_grid(helper_, grid_.M_), n, [&](Eigen::Index k0, Eigen::Index k1) {
    for (Eigen::Index k = k0; k < k1; ++k) c[k] = s[k] + c[k] * std::conj(d[k]);
  });
  grid_.inverse_in_place(c, out, helper_);
}

void CorrelationWorkspace::correlate_sum(const Spectrum& A_hat, const Spectrum& B_hat, Spectrum& C_hat,
                                         const Spectrum& D_hat, Mat<double>& out, bool consume_C) {
  if (!consume_C && !product_) product_ = array<std::complex<double>>(static_cast<std::size_t>(grid_.M_ * grid_.H_));
  // in place into C: entry (u, v) of the product reads C at (u, v) only
  std::complex<double>* product = consume_C ? C_hat.data.get() : product_.get();
  split_range(helper_for_grid(helper_, grid_.M_), grid_.M_, [&](Eigen::Index u0, Eigen::Index u1) { grid_.product_sum(A_hat, B_hat, C_hat, D_hat, product, u0, u1); });
  grid_.inverse_in_place(product, out, helper_);
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
