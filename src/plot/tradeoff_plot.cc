#include "plot/tradeoff_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "plot/palette.h"
#include "plot/plot_labels.h"

namespace lpvid {
namespace {

/// A logarithmic axis when the values span more than two decades (small λ
/// buys a small d_max with a large δ; the default grid can crowd δ near 0).
bool spans_decades(const std::vector<double>& v) {
  if (v.size() < 2) return false;
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *lo > 0 && *hi / *lo > 100.0;
}

}  // namespace

std::vector<PlotTick> distinct_ticks(const std::vector<double>& values, bool log) {
  if (values.empty()) return {};
  const auto [lo_it, hi_it] = std::minmax_element(values.begin(), values.end());
  const double lo = *lo_it, hi = *hi_it;
  std::vector<double> at;
  constexpr int kTicks = 5;
  if (!(hi > lo)) at.push_back(lo);
  for (int k = 0; hi > lo && k < kTicks; ++k)
    at.push_back(log && lo > 0 ? lo * std::pow(hi / lo, k / double(kTicks - 1)) : lo + (hi - lo) * k / (kTicks - 1));
  for (int digits = 2;; ++digits) {  // the fewest significant digits that tell every tick apart
    std::vector<PlotTick> ticks;
    std::set<std::string> seen;
    for (double a : at) {
      char buf[48];
      std::snprintf(buf, sizeof buf, "%.*g", digits, a);
      ticks.push_back({a, buf});
      seen.insert(buf);
    }
    if (seen.size() == ticks.size() || digits >= 17) return ticks;
  }
}

PlotSpec tradeoff_plot(const std::vector<TradeoffPoint>& points, const std::string& title) {
  PlotSpec spec;
  spec.title = title_without_folders(title);
  spec.xlabel = "d_max (certified RMS noise bound) [output units]";
  spec.ylabel = "delta (certified bound on ||Delta||, no unit)";
  spec.key = "bottom left";  // a Pareto curve falls from top left to bottom right
  PlotSeries ser;
  ser.title = "certified (delta, d_max), labelled by lambda";
  ser.color = palette::kBound;
  for (const TradeoffPoint& p : points) {
    if (!p.bounds.verified) continue;
    ser.x.push_back(p.bounds.dmax);
    ser.y.push_back(p.bounds.delta);
    ser.labels.push_back("λ=" + lambda_text(p.lambda));
  }
  spec.logx = spans_decades(ser.x);
  spec.logy = spans_decades(ser.y);
  spec.xtics = distinct_ticks(ser.x, spec.logx);
  spec.ytics = distinct_ticks(ser.y, spec.logy);
  spec.series.push_back(ser);
  return spec;
}

}  // namespace lpvid
