#pragma once
/// Paths of the repository's fixtures, shared by the tests that read them.

#include <string>

namespace lpvid::gen {

/// fixtures/example1/: Example 1's data, model and basis (with a trailing slash).
inline const std::string kExample1Fixtures = std::string(LPVID_SOURCE_DIR) + "/fixtures/example1/";

}  // namespace lpvid::gen
