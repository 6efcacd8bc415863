#include "fit/output_score.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/rms.h"

namespace lpvid {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double fit_of(double error_norm, double spread) {
  if (spread > 0) return 100.0 * (1.0 - error_norm / spread);
  return error_norm == 0 ? 100.0 : -kInf;
}

}  // namespace

OutputScores score_outputs(const Mat<double>& y, const Mat<double>& yhat) {
  if (y.rows() != yhat.rows() || y.cols() != yhat.cols())
    throw std::invalid_argument("score_outputs: y and yhat differ in shape");
  OutputScores s;
  const auto ny = static_cast<size_t>(y.cols());
  const Mat<double> e = y - yhat;
  if (!e.allFinite()) {
    s.finite = false;
    s.rms.assign(ny, kInf);
    s.fit_percent.assign(ny, -kInf);
    s.rms_all = kInf;
    s.fit_percent_all = -kInf;
    return s;
  }
  const Mat<double> centred = y.rowwise() - y.colwise().mean();
  for (Eigen::Index i = 0; i < y.cols(); ++i) {
    s.rms.push_back(rms(e.col(i)));
    s.fit_percent.push_back(fit_of(e.col(i).norm(), centred.col(i).norm()));
  }
  s.rms_all = rms(e);
  s.fit_percent_all = fit_of(e.norm(), centred.norm());
  return s;
}

}  // namespace lpvid
