#include "core/limits.h"

#include <sstream>

namespace lpvid {

InputLimits& input_limits() {
  static InputLimits limits;
  return limits;
}

std::string limit_hint(long double limit, const std::string& option) {
  std::ostringstream o;
  o << " (limit " << limit << "; raise it with " << option << ")";
  return o.str();
}

}  // namespace lpvid
