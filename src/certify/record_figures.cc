#include "certify/record_figures.h"

#include <cmath>

#include "model/simulate.h"
#include "toeplitz/record_segments.h"

namespace lpvid {
namespace {

/// The figures of rows [first, first + n) (d: the noise, or none).
RecordFigures figures_of_rows(const Mat<double>& y, const Mat<double>& r, const Mat<double>* d, Eigen::Index first,
                              Eigen::Index n) {
  RecordFigures f;
  f.samples = static_cast<long>(n);
  const double count = static_cast<double>(n * y.cols());
  const Mat<double> yk = y.middleRows(first, n);
  const Mat<double> centred = yk.rowwise() - yk.colwise().mean();
  const double r2 = r.middleRows(first, n).squaredNorm();
  f.rms_residual = std::sqrt(r2 / count);
  f.fit_percent = 100.0 * (1.0 - std::sqrt(r2) / centred.norm());
  if (d) f.rms_noise = std::sqrt(d->middleRows(first, n).squaredNorm() / count);
  return f;
}

}  // namespace

RecordTable record_figures(const Mat<double>& y, const Mat<double>& r, const std::vector<Eigen::Index>& lengths_in,
                           const std::optional<Mat<double>>& w) {
  const RecordLengths lengths = record_lengths_of(lengths_in, y.rows());
  const std::vector<Eigen::Index> start = record_starts(lengths);
  const std::optional<Mat<double>> d = w ? std::optional<Mat<double>>(r - *w) : std::nullopt;
  const double d2 = d ? d->squaredNorm() : 0.0;
  RecordTable t;
  for (size_t k = 0; k < lengths.size(); ++k) {
    t.records.push_back(figures_of_rows(y, r, d ? &*d : nullptr, start[k], lengths[k]));
    if (d) t.records.back().dmax_share = d2 > 0 ? d->middleRows(start[k], lengths[k]).squaredNorm() / d2 : 0.0;
  }
  t.pooled = figures_of_rows(y, r, d ? &*d : nullptr, 0, y.rows());
  if (d) t.pooled.dmax_share = 1.0;
  return t;
}

RecordTable record_figures(const LpvModel<double>& model, const Experiment<double>& exp, const CertifiedBounds& b) {
  const Simulation<double> sim = simulate(model, exp);
  const Mat<double> r = exp.y - sim.output;
  std::optional<Mat<double>> w;
  const bool delta_form = b.verified() && b.certificate && b.certificate->form == CertificateForm::kDelta &&
                          b.certificate->claim == CertificateClaim::kConsistent;
  if (delta_form)
    w = apply_fir_records(nearest_double(b.certificate->taps), sim.z, exp.ny(), b.certificate->horizon, exp.records);
  return record_figures(exp.y, r, exp.records, w);
}

}  // namespace lpvid
