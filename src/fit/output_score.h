#pragma once
/// How well a model's output ŷ matches the measured y on the same rows:
/// the RMS of y − ŷ and the fit index of the identification literature
/// (MATLAB's compare, the nonlinear_benchmarks loaders):
///   fit % = 100 · (1 − ‖y − ŷ‖ / ‖y − ȳ‖),  ȳ the mean of y on these rows,
/// 100 for a perfect match, 0 for a model no better than the mean, negative
/// when it is worse. Per output column and over all of them (the norms then
/// run over every entry, each column centred on its own mean).

#include <vector>

#include "core/scalar.h"

namespace lpvid {

struct OutputScores {
  std::vector<double> rms, fit_percent;  ///< per output column
  double rms_all = 0, fit_percent_all = 0;
  /// false when ŷ is not finite: then every RMS is +inf and every fit −inf
  bool finite = true;
};

/// y, yhat: n × ny on the same rows. A column of y without spread (all
/// equal) has fit −inf unless ŷ matches it exactly (then 100).
OutputScores score_outputs(const Mat<double>& y, const Mat<double>& yhat);

}  // namespace lpvid
