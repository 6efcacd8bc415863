#include "diagnose/bound_windows.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace lpvid {

std::vector<RowWindow> tile_windows(Eigen::Index n, Eigen::Index length, Eigen::Index min_last) {
  if (length < 1) throw std::invalid_argument("tile_windows: length must be >= 1");
  std::vector<RowWindow> out;
  for (Eigen::Index b = 0; b < n; b += length) out.emplace_back(b, std::min(n, b + length));
  if (out.size() > 1 && out.back().second - out.back().first < min_last) {
    const Eigen::Index end = out.back().second;
    out.pop_back();
    out.back().second = end;
  }
  return out;
}

std::vector<RowWindow> default_bound_windows(Eigen::Index n) {
  return tile_windows(n, kDefaultWindowLength, kDefaultMinLastWindow);
}

std::vector<RowWindow> spread_windows(const std::vector<RowWindow>& windows, size_t cap) {
  if (cap == 0 || cap >= windows.size()) return windows;
  if (cap == 1) return {windows.front()};
  std::vector<RowWindow> out;
  const double step = static_cast<double>(windows.size() - 1) / static_cast<double>(cap - 1);
  for (size_t i = 0; i < cap; ++i) out.push_back(windows[static_cast<size_t>(std::lround(step * static_cast<double>(i)))]);
  return out;
}

BoundCost estimate_bound_cost(const std::vector<RowWindow>& windows, int ny, int nz, bool lower_ends) {
  BoundCost c;
  for (const RowWindow& w : windows) {
    const double size = static_cast<double>(w.second - w.first) * static_cast<double>(ny + nz);
    const double each = kBoundSeconds * std::pow(size / 400.0, 3.0) * std::pow(static_cast<double>(ny * nz), 0.8);
    c.seconds += 2.0 * each * (lower_ends ? kLowerEndFactor : 1.0);  // before and after
    // A compact dual certificate holds n·ny + L·ny·nz numbers of about 40 bytes
    // (measured: 31 kB at SISO n = 400, 103 kB at 2×2 n = 400).
    const double rows = static_cast<double>(w.second - w.first);
    c.megabytes += 2.0 * (0.01 + (lower_ends ? 40e-6 * rows * ny * (1.0 + nz) : 0.0));
  }
  return c;
}

namespace {

/// "40 s", "3 min", "1.5 h": a duration as a progress line says it.
std::string duration_text(double seconds) {
  char buf[32];
  if (seconds < 90) std::snprintf(buf, sizeof buf, "%.0f s", seconds);
  else if (seconds < 5400) std::snprintf(buf, sizeof buf, "%.0f min", seconds / 60);
  else std::snprintf(buf, sizeof buf, "%.1f h", seconds / 3600);
  return buf;
}

}  // namespace

std::string observed_rate_text(size_t done, size_t total, double elapsed_seconds) {
  if (done == 0 || !(elapsed_seconds >= 0)) return "";
  const double each = elapsed_seconds / static_cast<double>(done);
  char buf[32];
  std::snprintf(buf, sizeof buf, each < 10 ? "%.1f s" : "%.0f s", each);
  std::string out = std::string(buf) + " per bound so far";
  if (done < total) out += ", ~" + duration_text(each * static_cast<double>(total - done)) + " left";
  return out;
}

}  // namespace lpvid
