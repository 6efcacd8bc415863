#pragma once
/// Which rows of the estimation record get verified bounds.
///
/// By default the WHOLE estimation record is covered by consecutive windows
/// of kDefaultWindowLength rows (Theorem 2.1's LMIs grow with the window, so
/// the record is cut, not solved at once; diagnose/window_bounds.h). A last
/// window shorter than the minimum is merged into the one before it, so no
/// window is a scrap of a few rows whose bounds say little.

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
/// seconds ≈ 3·(L·(ny+nz)/800)^2.4·(ny·nz)^0.8 of wall time, both ends of
/// the interval (the structured barrier, bench/README.md `interval_bench`
/// 2026-11-26: SISO 2.9 s at 400 rows and 15 s at 800, 2×2 42 s at 400, 3×3
/// 33 s at 200), a primal certificate ≈ 10 kB, and with `lower_ends` a compact
/// dual certificate of n·ny + L·ny·nz numbers at about 40 bytes each.
BoundCost estimate_bound_cost(const std::vector<RowWindow>& windows, int ny, int nz, bool lower_ends);

}  // namespace lpvid
