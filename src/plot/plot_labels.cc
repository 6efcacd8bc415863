#include "plot/plot_labels.h"

namespace lpvid {

std::string unit_suffix(const std::string& unit) { return unit.empty() ? " (data units)" : " [" + unit + "]"; }

std::string common_unit(const SignalInfo& info, const std::vector<std::string>& columns) {
  const std::string u = columns.empty() ? "" : info.unit_of(columns.front());
  for (const std::string& c : columns)
    if (info.unit_of(c) != u) return "";
  return u;
}

std::string title_without_folders(const std::string& title) {
  std::string out, word;
  const auto flush = [&] {
    const size_t slash = word.rfind('/');
    out += slash != std::string::npos && slash + 1 < word.size() ? word.substr(slash + 1) : word;
    word.clear();
  };
  for (char c : title) {
    if (c == ' ') {
      flush();
      out += c;
    } else {
      word += c;
    }
  }
  flush();
  return out;
}

}  // namespace lpvid
