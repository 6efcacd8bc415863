#include "lmi/free_regressors.h"

#include <stdexcept>

namespace lpvid {

FreeRegressors::FreeRegressors(const Mat<double>& G, Eigen::Index n, Eigen::Index ny, const std::string& what) {
  if (G.cols() == 0) return;
  if (G.rows() != n * ny)
    throw std::invalid_argument(what + ": the free regressors have " + std::to_string(G.rows()) +
                                " rows, expected n*ny = " + std::to_string(n * ny) + " (stacked like the residual)");
  if (!G.allFinite()) throw std::invalid_argument(what + ": a free regressor has a non-finite entry");
  G_ = G;
  const Eigen::Index P = G.cols();
  Vec<double> scale = G.colwise().norm().transpose();
  for (Eigen::Index c = 0; c < P; ++c)
    if (!(scale(c) > 0)) scale(c) = 1.0;  // a zero column stays zero
  const Mat<double> unit = G * scale.cwiseInverse().asDiagonal();
  const Eigen::JacobiSVD<Mat<double>> svd(unit, Eigen::ComputeThinU | Eigen::ComputeFullV);
  const Vec<double> sv = svd.singularValues();
  Eigen::Index k = 0;
  while (k < sv.size() && sv(k) > kFreeRegressorRankTolerance * sv(0)) ++k;
  Q_ = svd.matrixU().leftCols(k);
  // unit = U Σ Vᵀ and G = unit·D: q = D⁻¹ V_k Σ_k⁻¹ U_kᵀ e solves G q = Q Qᵀ e;
  // G's null space (numerically) is D⁻¹ V_⊥, orthonormalised for the least-norm step
  pinv_ = scale.cwiseInverse().asDiagonal() * svd.matrixV().leftCols(k) * sv.head(k).cwiseInverse().asDiagonal() *
          Q_.transpose();
  const Mat<double> null_dir = scale.cwiseInverse().asDiagonal() * svd.matrixV().rightCols(P - k);
  const Eigen::HouseholderQR<Mat<double>> qr(null_dir);
  null_ = qr.householderQ() * Mat<double>::Identity(P, P - k);
}

// Twice (classical Gram–Schmidt's "twice is enough"): after one pass the
// rounding left in range(G) is ε·‖v‖ of the input, which dominates a result
// much shorter than v (r nearly in range(G)); after the second it is ε·‖P⊥v‖,
// so Gᵀ(P⊥v) is at rounding relative to the result.
void FreeRegressors::project(Vec<double>& v) const {
  if (Q_.cols() == 0) return;
  for (int pass = 0; pass < 2; ++pass) v -= Q_ * (Q_.transpose() * v);
}

Vec<double> FreeRegressors::coefficients(const Vec<double>& e) const {
  if (G_.cols() == 0) return Vec<double>(0);
  Vec<double> q = pinv_ * e;
  if (null_.cols() > 0) q -= null_ * (null_.transpose() * q);
  return q;
}

}  // namespace lpvid
