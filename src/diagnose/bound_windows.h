#pragma once
/// Which rows of the estimation record get verified bounds.
///
/// By default the WHOLE estimation record is covered by consecutive windows
/// of kDefaultWindowLength rows (Theorem 2.1's LMIs grow with the window, so
/// the record is cut, not solved at once; diagnose/window_bounds.h). A last
/// window shorter than the minimum is merged into the one before it, so no
/// window is a scrap of a few rows whose bounds say little.

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace lpvid {

using RowWindow = std::pair<Eigen::Index, Eigen::Index>;  ///< rows [first, second), 0-based

constexpr Eigen::Index kDefaultWindowLength = 200;
constexpr Eigen::Index kDefaultMinLastWindow = 50;

/// [0, L), [L, 2L), … covering [0, n); a last window shorter than
/// `min_last` joins the previous one (a record shorter than `length` is one
/// window). Empty for n ≤ 0. Requires length ≥ 1.
std::vector<RowWindow> tile_windows(Eigen::Index n, Eigen::Index length, Eigen::Index min_last);

/// The default of `lpvid diagnose`: tile_windows(n, 200, 50).
std::vector<RowWindow> default_bound_windows(Eigen::Index n);

/// At most `cap` of `windows`, spread evenly over them (the first and the
/// last always kept; index round(i·(W−1)/(cap−1))); all of them when cap is
/// 0 or not smaller than their number.
std::vector<RowWindow> spread_windows(const std::vector<RowWindow>& windows, size_t cap);

/// What certifying `windows` is expected to cost, before it starts: an
/// a-priori figure from the bench table (bench/README.md), not a promise.
struct BoundCost {
  double seconds = 0;   ///< wall time, all certifications in sequence
  double megabytes = 0;  ///< certificate files written
};

/// The estimate for every window certified twice (before and after): per
/// certification of L rows with ny outputs and nz uncertainty channels,
/// seconds ≈ kBoundSeconds·(L·(ny+nz)/400)³·(ny·nz)^0.8 of one core's time
/// for the upper end (the structured barrier's Newton steps cost O(L³) and
/// their number grows with L on measured records; the exact check of the
/// certificate is a fifth of it), × kLowerEndFactor with `lower_ends` (the
/// dual certificate built and checked too). Calibrated on the cascaded-tanks
/// record (dataBenchmark.csv, the linear model of scripts/demo.sh, λ = 0.99
/// in the data's units, one thread, 2-core machine at load ~2): upper end
/// 2.6–3.0 s at 200 rows (2.2 s solve + 0.6 s exact check), 21 s at 400;
/// both ends 4.7 s at 200 and 39 s at 400. Windows run in parallel
/// (--threads) divide the wall time by at most the thread count. Files: a
/// primal certificate ≈ 10 kB, and with `lower_ends` a compact dual
/// certificate of n·ny + L·ny·nz numbers at about 40 bytes each.
constexpr double kBoundSeconds = 2.7;   ///< one upper end, SISO, 200 rows (see estimate_bound_cost)
constexpr double kLowerEndFactor = 1.8;  ///< both ends / the upper end alone (measured 4.7/2.7 and 39/21)
BoundCost estimate_bound_cost(const std::vector<RowWindow>& windows, int ny, int nz, bool lower_ends);

/// The rate the bounds actually run at, for the progress lines: after
/// `done` of `total` certifications in `elapsed_seconds` of wall time,
/// "11 s per bound so far, ~2 min left" (wall time per finished bound at the
/// parallelism used; the rest at that rate). Empty before the first.
std::string observed_rate_text(size_t done, size_t total, double elapsed_seconds);

}  // namespace lpvid
