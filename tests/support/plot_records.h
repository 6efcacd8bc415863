#pragma once
// A test record figure's inputs from random signals (tests/plot): 60 samples at
// 4 s, columns uEst, yEst, d_max 0.25, a warm-up of 10 samples.
#include <string>

#include "plot/diagnose_plots.h"
#include "support/test_signals.h"

namespace lpvid {

inline TestRecordPlot random_test_record(const std::string& source) {
  TestRecordPlot t;
  t.u = gaussian(60, 1, 11, 1.0);
  t.y = gaussian(60, 1, 12, 1.0);
  t.yhat_before = gaussian(60, 1, 13, 1.0);
  t.yhat_after = t.y + gaussian(60, 1, 14, 0.1);
  t.dmax_after = 0.25;
  t.warmup = 10;
  t.input_columns = {"uEst"};
  t.output_columns = {"yEst"};
  t.info.sample_time = 4.0;
  t.source = source;
  return t;
}

}  // namespace lpvid
