#include "core/input_error.h"

#include <cstdio>

namespace lpvid {

std::string printable_excerpt(std::string_view text, size_t max_chars) {
  std::string out;
  for (char c : text.substr(0, max_chars)) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", u);
      out += buf;
    } else {
      out += c;
    }
  }
  if (text.size() > max_chars) out += "...";
  return out;
}

std::string input_location(const std::string& file, long line, const std::string& field) {
  std::string where = file.empty() ? std::string("<input>") : file;
  if (line > 0) where += ":" + std::to_string(line);
  if (!field.empty()) where += ": " + field;
  return where;
}

void throw_input_error(const std::string& file, long line, const std::string& field,
                       const std::string& reason) {
  throw InputError(input_location(file, line, field) + ": " + reason);
}

}  // namespace lpvid
