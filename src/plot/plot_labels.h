#pragma once
/// Labels shared by every figure: axis units and titles without folders.

#include <string>
#include <vector>

#include "data/signal_info.h"

namespace lpvid {

/// An axis label's unit: " [V]", or " (data units)" when the unit is not known ("").
std::string unit_suffix(const std::string& unit);

/// The unit all the columns share (SignalInfo::unit_of), "" when unknown or mixed.
std::string common_unit(const SignalInfo& info, const std::vector<std::string>& columns);

/// The title with every file path shortened to its base name ("fit on
/// /data/run 3/a.csv rows 0:9" keeps "a.csv"): a word holding a '/' with
/// text after its last '/' is cut to that text. A title names no folders (it
/// must fit above the figure and not show where the user keeps files).
std::string title_without_folders(const std::string& title);

}  // namespace lpvid
