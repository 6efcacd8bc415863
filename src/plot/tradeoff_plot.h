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

/// Ticks inside the values' range at round numbers: multiples of the smallest
/// 1, 2 or 5 times 10^k step giving at most seven, or the powers of ten on a logarithmic axis
/// spanning two of them; labelled with the fewest significant digits (at least
/// 3) that keep every label distinct. One tick when all values are equal;
/// none for no values.
std::vector<PlotTick> distinct_ticks(const std::vector<double>& values, bool log);

PlotSpec tradeoff_plot(const std::vector<TradeoffPoint>& points, const std::string& title);

}  // namespace lpvid
