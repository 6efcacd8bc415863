#include "fit/local_lpv.h"

#include <stdexcept>
#include <string>

#include "core/decimal_rounding.h"

namespace lpvid {
namespace {

/// Rows h_j(ρ_k) of the basis at the given ρ rows.
Mat<double> basis_matrix(const Mat<double>& rho, const std::vector<Monomial>& basis) {
  Mat<double> f(rho.rows(), static_cast<Eigen::Index>(basis.size()));
  for (Eigen::Index k = 0; k < rho.rows(); ++k)
    for (size_t j = 0; j < basis.size(); ++j)
      f(k, static_cast<Eigen::Index>(j)) = basis[j].eval<double>(rho.row(k).transpose());
  return f;
}

Mat<Rational> rounded(const Mat<double>& m, int digits) {
  return m.unaryExpr([digits](double x) { return round_to_digits(x, digits); });
}

std::vector<std::string> numbered(const char* stem, Eigen::Index count) {
  std::vector<std::string> names;
  for (Eigen::Index i = 1; i <= count; ++i) names.push_back(stem + std::to_string(i));
  return names;
}

}  // namespace

std::vector<OperatingPointFit> fit_operating_points(const Experiment<double>& e, int order, long skip) {
  std::vector<OperatingPointFit> out;
  Eigen::Index begin = 0;
  while (begin < e.n()) {
    Eigen::Index end = begin + 1;
    while (end < e.n() && e.rho.row(end) == e.rho.row(begin)) ++end;
    const Eigen::Index first = begin + skip, rows = end - first;
    if (rows > order * (e.ny() + e.nu() + 1) + 1)
      out.push_back({e.rho.row(begin).transpose(),
                     fit_mimo_arx(e.u.middleRows(first, rows), e.y.middleRows(first, rows), order)});
    begin = end;
  }
  return out;
}

std::vector<MimoArx> interpolate_arx(const std::vector<OperatingPointFit>& points,
                                     const std::vector<Monomial>& basis) {
  if (points.empty()) throw std::invalid_argument("interpolate_arx: no operating points");
  const Eigen::Index n_pts = static_cast<Eigen::Index>(points.size());
  Mat<double> rho(n_pts, points[0].rho.size());
  for (Eigen::Index p = 0; p < n_pts; ++p) rho.row(p) = points[p].rho.transpose();
  const auto qr = basis_matrix(rho, basis).colPivHouseholderQr();
  // One least-squares problem per entry; the right-hand sides are stacked as columns.
  auto fit = [&](auto entry_of, Eigen::Index rows, Eigen::Index cols) {
    Mat<double> rhs(n_pts, rows * cols);
    for (Eigen::Index p = 0; p < n_pts; ++p) rhs.row(p) = entry_of(points[p].arx).reshaped().transpose();
    const Mat<double> coef = qr.solve(rhs);
    std::vector<Mat<double>> terms;
    for (Eigen::Index j = 0; j < coef.rows(); ++j) terms.push_back(coef.row(j).transpose().reshaped(rows, cols));
    return terms;
  };
  const MimoArx& m0 = points[0].arx;
  const Eigen::Index ny = m0.P[0].rows(), nu = m0.Q[0].cols();
  std::vector<MimoArx> out(basis.size());
  for (int i = 0; i < m0.order(); ++i) {
    const auto p = fit([i](const MimoArx& m) { return m.P[i]; }, ny, ny);
    const auto q = fit([i](const MimoArx& m) { return m.Q[i]; }, ny, nu);
    for (size_t j = 0; j < basis.size(); ++j) {
      out[j].P.push_back(p[j]);
      out[j].Q.push_back(q[j]);
    }
  }
  const auto c = fit([](const MimoArx& m) { return Mat<double>(m.c); }, ny, 1);
  for (size_t j = 0; j < basis.size(); ++j) out[j].c = c[j];
  return out;
}

LpvModel<Rational> lpv_from_arx_terms(const std::vector<MimoArx>& terms, const std::vector<Monomial>& basis,
                                      const Rational& weight, int digits) {
  const int ny = static_cast<int>(terms.at(0).P.at(0).rows()), nu = static_cast<int>(terms[0].Q[0].cols());
  const int nx = terms[0].order() * ny, n_rho = static_cast<int>(basis.at(0).powers.size());
  LpvModel<Rational> m;
  m.nx = nx;
  m.nu = nu;
  m.ny = ny;
  m.scheduling = numbered("rho", n_rho);
  m.columns = {numbered("u", nu), numbered("y", ny), m.scheduling};
  m.A = ParamMatrix<Rational>(nx, nx);
  m.B = ParamMatrix<Rational>(nx, nu);
  m.C = ParamMatrix<Rational>(ny, nx);
  m.D = ParamMatrix<Rational>(ny, nu);
  bool has_one = false;
  for (size_t j = 0; j < basis.size(); ++j) {
    Mat<double> a, b;
    arx_realisation(terms[j], basis[j].is_constant(), a, b);
    has_one = has_one || basis[j].is_constant();
    m.A.add(basis[j], rounded(a, digits));
    m.B.add(basis[j], rounded(b, digits));
  }
  if (!has_one) throw std::invalid_argument("lpv_from_arx_terms: the basis must contain 1");
  Mat<Rational> c = Mat<Rational>::Zero(ny, nx);
  for (int i = 0; i < ny; ++i) c(i, i) = 1;
  m.C.add(constant_monomial(static_cast<size_t>(n_rho)), c);
  m.uncertainty.structure = UncertaintyStructure::kMultiplicative;
  m.uncertainty.weight = weight;
  m.x0 = Vec<Rational>::Zero(nx);
  return m;
}

Mat<double> fit_static_gain(const Experiment<double>& e, const std::vector<Monomial>& basis) {
  return basis_matrix(e.rho, basis).colPivHouseholderQr().solve(e.y);
}

}  // namespace lpvid
