#include "plot/model_colours.h"

#include <algorithm>
#include <iterator>

#include "plot/palette.h"

namespace lpvid {

namespace {

const char* role_colour(const std::string& name) {
  if (name == "before") return palette::kModelBefore;
  if (name == "after") return palette::kModelAfter;
  return nullptr;
}

}  // namespace

std::vector<std::string> model_colours(const std::vector<std::string>& names) {
  std::vector<std::string> used;
  for (const std::string& name : names)
    if (const char* c = role_colour(name)) used.emplace_back(c);
  std::vector<std::string> out;
  size_t next = 0;
  const size_t others = std::size(palette::kOtherModels);
  for (const std::string& name : names) {
    if (const char* c = role_colour(name)) {
      out.emplace_back(c);
      continue;
    }
    // The next colour no role took; past the end of the list, the last one again.
    while (next + 1 < others &&
           std::find(used.begin(), used.end(), std::string(palette::kOtherModels[next])) != used.end())
      ++next;
    out.emplace_back(palette::kOtherModels[next]);
    used.push_back(out.back());
    if (next + 1 < others) ++next;
  }
  return out;
}

}  // namespace lpvid
