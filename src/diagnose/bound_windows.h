#pragma once
/// Which rows of the estimation record get verified bounds (issue 9 item 5).
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

}  // namespace lpvid
