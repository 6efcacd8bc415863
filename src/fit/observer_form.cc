// GCC 12 reports a false -Wmaybe-uninitialized inside Eigen's triangular
// matrix-vector product when EigenSolver is instantiated at -O2/-O3; the
// diagnostic points into Eigen's headers, so it is silenced for them only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include "fit/observer_form.h"

#include <complex>

#include <Eigen/Eigenvalues>

#include "model/monomial.h"
#pragma GCC diagnostic pop

namespace lpvid {

Mat<double> ObserverForm::A() const {
  const int n = order();
  Mat<double> A = Mat<double>::Zero(n, n);
  A.col(0) = -a;
  for (int i = 0; i + 1 < n; ++i) A(i, i + 1) = 1.0;
  return A;
}

int ObserverForm::parameter_count() const {
  const int n = order(), m = inputs();
  return n + n * m + m + n + (has_offset ? 1 : 0);
}

Vec<double> ObserverForm::parameters() const {
  Vec<double> p(parameter_count());
  const int n = order(), m = inputs();
  p << a, B.reshaped(), D.reshaped(), x0, Vec<double>::Constant(has_offset ? 1 : 0, offset);
  (void)n;
  (void)m;
  return p;
}

void ObserverForm::set_parameters(const Vec<double>& p) {
  const int n = order(), m = inputs();
  Eigen::Index i = 0;
  a = p.segment(i, n), i += n;
  B = p.segment(i, n * m).reshaped(n, m), i += n * m;
  D = p.segment(i, m).reshaped(1, m), i += m;
  x0 = p.segment(i, n), i += n;
  if (has_offset) offset = p(i);
}

ObserverForm zero_observer_form(int n, int nu, bool has_offset) {
  ObserverForm f;
  f.a = Vec<double>::Zero(n);
  f.B = Mat<double>::Zero(n, nu);
  f.D = Mat<double>::Zero(1, nu);
  f.x0 = Vec<double>::Zero(n);
  f.has_offset = has_offset;
  return f;
}

Vec<double> simulate_observer(const ObserverForm& f, const Mat<double>& u) {
  const int n = f.order();
  const Eigen::Index N = u.rows();
  Vec<double> y(N);
  Vec<double> x = f.x0, next(n);
  const double c = f.has_offset ? f.offset : 0.0;
  for (Eigen::Index k = 0; k < N; ++k) {
    const double uk_d = (f.D * u.row(k).transpose())(0);
    y(k) = (n > 0 ? x(0) : 0.0) + uk_d + c;
    // x_{k+1} = A x_k + B u_k with A the companion matrix: shift up, feed x_1 back through −a.
    for (int i = 0; i < n; ++i) next(i) = (i + 1 < n ? x(i + 1) : 0.0) - f.a(i) * x(0);
    next.noalias() += f.B * u.row(k).transpose();
    x.swap(next);
  }
  return y;
}

namespace {

Eigen::VectorXcd denominator_roots(const Vec<double>& a) {
  ObserverForm f;
  f.a = a;
  return Eigen::EigenSolver<Mat<double>>(f.A(), false).eigenvalues();
}

}  // namespace

double spectral_radius(const Vec<double>& a) {
  if (a.size() == 0) return 0.0;
  return denominator_roots(a).cwiseAbs().maxCoeff();
}

Vec<double> stabilise_denominator(const Vec<double>& a, double max_radius) {
  if (spectral_radius(a) <= max_radius) return a;
  Eigen::VectorXcd roots = denominator_roots(a);
  // Π (z − λ_i), coefficients highest power first; complex roots come in
  // conjugate pairs (reflection keeps that), so the imaginary parts cancel.
  std::vector<std::complex<double>> poly{1.0};
  for (Eigen::Index i = 0; i < roots.size(); ++i) {
    std::complex<double> l = roots(i);
    if (std::abs(l) >= 1.0) l = 1.0 / std::conj(l);
    if (std::abs(l) > max_radius) l *= max_radius / std::abs(l);
    std::vector<std::complex<double>> next(poly.size() + 1, 0.0);
    for (size_t j = 0; j < poly.size(); ++j) {
      next[j] += poly[j];
      next[j + 1] -= l * poly[j];
    }
    poly.swap(next);
  }
  Vec<double> out(a.size());
  for (Eigen::Index i = 0; i < a.size(); ++i) out(i) = poly[static_cast<size_t>(i) + 1].real();
  return out;
}

LpvModel<double> to_lpv_model(const ObserverForm& f, const ColumnMap& columns) {
  LpvModel<double> m;
  m.nx = f.order();
  m.nu = f.inputs();
  m.ny = 1;
  m.columns = columns;
  const Monomial one = parse_monomial("1", {});
  m.A = ParamMatrix<double>(m.nx, m.nx);
  m.B = ParamMatrix<double>(m.nx, m.nu);
  m.C = ParamMatrix<double>(1, m.nx);
  m.D = ParamMatrix<double>(1, m.nu);
  m.A.add(one, f.A());
  m.B.add(one, f.B);
  Mat<double> C = Mat<double>::Zero(1, m.nx);
  if (m.nx > 0) C(0, 0) = 1.0;
  m.C.add(one, C);
  m.D.add(one, f.D);
  if (f.has_offset) {
    m.offset.basis = {one};
    m.offset.values = {Vec<double>::Constant(1, f.offset)};
  }
  m.x0 = f.x0;
  return m;
}

}  // namespace lpvid
