#pragma once
/// The colours of the models of one figure (compare): a model named "before"
/// or "after" takes its role's colour (plot/palette.h: before orange, after
/// blue, as in every diagnose figure); every other model takes the next
/// colour of palette::kOtherModels that no model of the figure uses yet.

#include <string>
#include <vector>

namespace lpvid {

/// One colour per name, in order.
std::vector<std::string> model_colours(const std::vector<std::string>& names);

}  // namespace lpvid
