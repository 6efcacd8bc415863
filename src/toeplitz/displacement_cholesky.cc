#include "toeplitz/displacement_cholesky.h"

#include <cmath>
#include <stdexcept>

namespace lpvid {

namespace {

/// The generalised Schur sweep; `store(k, column, count)` receives column k of
/// the factor (rows k … L−1). False at the first rotation that does not exist.
template <typename Store>
bool schur_sweep(const Eigen::VectorXd& h, double t, double* log_det, Store&& store) {
  const Eigen::Index L = h.size();
  if (!(t > 0)) return false;
  // Both generator columns in coordinates relative to the current row k:
  // g₁ keeps its place (S shifts it down as k advances), g₂ moves up by one.
  std::vector<double> a(static_cast<std::size_t>(L), 0.0), b(h.data(), h.data() + L);
  a[0] = std::sqrt(t);
  double sum = 0;
  for (Eigen::Index k = 0; k < L; ++k) {
    const Eigen::Index n = L - k;
    double* A = a.data();
    double* B = b.data() + k;
    const double gamma = B[0] / A[0];
    if (!(std::fabs(gamma) < 1) || !(A[0] > 0)) return false;
    const double c = std::sqrt((1 - gamma) * (1 + gamma));
    if (!(c > 0)) return false;
    const double inv_c = 1 / c;
    for (Eigen::Index j = 0; j < n; ++j) {
      const double an = (A[j] - gamma * B[j]) * inv_c;  // mixed form: the new g₁ first,
      B[j] = c * B[j] - gamma * an;                      // then g₂ from it
      A[j] = an;
    }
    B[0] = 0;
    if (!(A[0] > 0) || !std::isfinite(A[0])) return false;
    sum += std::log(A[0]);
    store(k, A, n);
  }
  *log_det = 2 * sum;
  return std::isfinite(*log_det);
}

}  // namespace

bool DisplacementCholesky::factor(const Eigen::VectorXd& h, double t, bool keep_factor) {
  L_ = h.size();
  kept_ = false;
  if (keep_factor) packed_.resize(static_cast<std::size_t>(L_ * (L_ + 1) / 2));
  const bool ok = schur_sweep(h, t, &log_det_, [&](Eigen::Index k, const double* col, Eigen::Index n) {
    if (keep_factor) std::copy(col, col + n, packed_.data() + k * L_ - k * (k - 1) / 2);
  });
  kept_ = ok && keep_factor;
  return ok;
}

Eigen::VectorXd DisplacementCholesky::solve(const Eigen::VectorXd& b) const {
  if (!kept_ || b.size() != L_) throw std::logic_error("DisplacementCholesky::solve without a kept factor of this size");
  Eigen::VectorXd x = b;
  for (Eigen::Index k = 0; k < L_; ++k) {  // L y = b, by columns
    const double* c = column(k);
    const double yk = x(k) / c[0];
    x(k) = yk;
    for (Eigen::Index i = 1; i < L_ - k; ++i) x(k + i) -= yk * c[i];
  }
  for (Eigen::Index k = L_ - 1; k >= 0; --k) {  // Lᵀ x = y, by dots with the columns
    const double* c = column(k);
    double s = x(k);
    for (Eigen::Index i = 1; i < L_ - k; ++i) s -= c[i] * x(k + i);
    x(k) = s / c[0];
  }
  return x;
}

Eigen::MatrixXd DisplacementCholesky::dense_factor() const {
  if (!kept_) throw std::logic_error("DisplacementCholesky::dense_factor without a kept factor");
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(L_, L_);
  for (Eigen::Index k = 0; k < L_; ++k)
    for (Eigen::Index i = 0; i < L_ - k; ++i) F(k + i, k) = column(k)[i];
  return F;
}

bool displacement_log_det(const Eigen::VectorXd& h, double t, double* log_det) {
  return schur_sweep(h, t, log_det, [](Eigen::Index, const double*, Eigen::Index) {});
}

double lower_toeplitz_norm2(const Eigen::VectorXd& h) {
  const double l1 = h.cwiseAbs().sum();
  double lo = 0, hi = l1 * l1 * (1 + 1e-12), log_det = 0;
  if (!(hi > 0)) return 0;
  for (int k = 0; k < 64; ++k) {
    const double mid = 0.5 * (lo + hi);
    (displacement_log_det(h, mid, &log_det) ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace lpvid
