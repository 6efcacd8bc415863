#pragma once
/// The plot of `lpvid tradeoff`: certified δ against certified d_max, points
/// labelled by λ; an axis is logarithmic when its values span more than two
/// decades. Its ticks are placed here, each label distinct (tick marks a
/// decade apart on a narrow logarithmic range would repeat "0.1"); the
/// title names no folders.

#include <string>
#include <vector>

#include "identify/tradeoff.h"
#include "plot/gnuplot.h"

namespace lpvid {

/// Five ticks spread evenly (logarithmically when log) over the values'
/// range, labelled with the fewest significant digits that keep every label
/// distinct; one tick when all values are equal; none for no values.
std::vector<PlotTick> distinct_ticks(const std::vector<double>& values, bool log);

PlotSpec tradeoff_plot(const std::vector<TradeoffPoint>& points, const std::string& title);

}  // namespace lpvid
