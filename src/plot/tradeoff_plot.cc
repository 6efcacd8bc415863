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

/// Tick positions inside [lo, hi]: the multiples of the smallest 1-2-5 step
/// giving at most seven ticks, or (log) the powers of ten.
std::vector<double> round_positions(double lo, double hi, bool log) {
  std::vector<double> at;
  if (log && lo > 0) {
    for (double k = std::ceil(std::log10(lo) - 1e-9); k <= std::floor(std::log10(hi) + 1e-9); ++k) at.push_back(std::pow(10.0, k));
    if (at.size() >= 2) return at;
    at.clear();
  }
  const auto first = [&](double step) { return std::ceil(lo / step - 1e-9); };
  const auto last = [&](double step) { return std::floor(hi / step + 1e-9); };
  double step = std::pow(10.0, std::floor(std::log10(hi - lo)) - 1);  // at least 10 ticks: widen 1, 2, 5, 10, …
  for (int k = 0; last(step) - first(step) + 1 > 7; ++k) step *= k % 3 == 1 ? 2.5 : 2.0;
  for (double k = first(step); k <= last(step); ++k) at.push_back(k * step);
  return at;
}

}  // namespace

std::vector<PlotTick> distinct_ticks(const std::vector<double>& values, bool log) {
  if (values.empty()) return {};
  const auto [lo_it, hi_it] = std::minmax_element(values.begin(), values.end());
  const std::vector<double> at = *hi_it > *lo_it ? round_positions(*lo_it, *hi_it, log) : std::vector<double>{*lo_it};
  for (int digits = 3;; ++digits) {  // the fewest significant digits that tell every tick apart
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
    if (!p.bounds.verified()) continue;
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
