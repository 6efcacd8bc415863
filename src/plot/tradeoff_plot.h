#pragma once
/// The plot of `lpvid tradeoff`: certified δ against certified d_max, points
/// labelled by λ; an axis is logarithmic when its values span more than two
/// decades.

#include <string>
#include <vector>

#include "identify/tradeoff.h"
#include "plot/gnuplot.h"

namespace lpvid {

PlotSpec tradeoff_plot(const std::vector<TradeoffPoint>& points, const std::string& title);

}  // namespace lpvid
