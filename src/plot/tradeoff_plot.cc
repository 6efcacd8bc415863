#include "plot/tradeoff_plot.h"

#include <algorithm>

namespace lpvid {

PlotSpec tradeoff_plot(const std::vector<TradeoffPoint>& points, const std::string& title) {
  PlotSpec spec;
  spec.title = title;
  spec.xlabel = "d_max (certified, RMS noise bound)";
  spec.ylabel = "delta (certified uncertainty bound)";
  spec.key = "bottom left";  // a Pareto curve falls from top left to bottom right
  PlotSeries ser;
  ser.title = "certified (delta, d_max), labelled by lambda";
  for (const TradeoffPoint& p : points) {
    if (!p.bounds.verified()) continue;
    ser.x.push_back(p.bounds.dmax);
    ser.y.push_back(p.bounds.delta);
    ser.labels.push_back("λ=" + lambda_text(p.lambda));
  }
  // A logarithmic axis when the values span more than two decades (small λ
  // buys a small d_max with a large δ; the default grid can crowd δ near 0).
  auto spans = [](const std::vector<double>& v) {
    if (v.size() < 2) return false;
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    return *lo > 0 && *hi / *lo > 100.0;
  };
  spec.logx = spans(ser.x);
  spec.logy = spans(ser.y);
  spec.series.push_back(ser);
  return spec;
}

}  // namespace lpvid
