#include "core/input_error.h"

namespace lpvid {

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
