#include "fit/mimo_arx.h"

#include <string>

#include "core/input_error.h"

namespace lpvid {

MimoArx fit_mimo_arx(const Mat<double>& u, const Mat<double>& y, int order) {
  const Eigen::Index n_rows = y.rows() - order, ny = y.cols(), nu = u.cols();
  const Eigen::Index n_reg = order * (ny + nu) + 1;
  if (order < 1 || n_rows < n_reg)
    throw InputError("fit_mimo_arx: " + std::to_string(y.rows()) + " samples are too few for order " +
                     std::to_string(order) + " (need " + std::to_string(n_reg + order) + ")");
  Mat<double> phi(n_rows, n_reg);
  for (Eigen::Index r = 0; r < n_rows; ++r) {
    const Eigen::Index k = r + order;
    for (int i = 1; i <= order; ++i) {
      phi.block(r, (i - 1) * ny, 1, ny) = y.row(k - i);
      phi.block(r, order * ny + (i - 1) * nu, 1, nu) = u.row(k - i);
    }
    phi(r, n_reg - 1) = 1.0;
  }
  const Mat<double> theta = phi.colPivHouseholderQr().solve(y.bottomRows(n_rows));  // n_reg × ny
  MimoArx m;
  for (int i = 0; i < order; ++i) {
    m.P.push_back(theta.middleRows(i * ny, ny).transpose());
    m.Q.push_back(theta.middleRows(order * ny + i * nu, nu).transpose());
  }
  m.c = theta.row(n_reg - 1).transpose();
  return m;
}

void arx_realisation(const MimoArx& m, bool identity, Mat<double>& A, Mat<double>& B) {
  const int n = m.order();
  const Eigen::Index ny = m.P[0].rows(), nu = m.Q[0].cols();
  A = Mat<double>::Zero(n * ny, n * ny);
  B = Mat<double>::Zero(n * ny, nu);
  for (int i = 0; i < n; ++i) {
    A.block(i * ny, 0, ny, ny) = m.P[i];
    if (identity && i + 1 < n) A.block(i * ny, (i + 1) * ny, ny, ny) = Mat<double>::Identity(ny, ny);
    B.middleRows(i * ny, ny) = m.Q[i];
  }
}

}  // namespace lpvid
