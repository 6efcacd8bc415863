#pragma once
// A table cell of the paper-table benches: a certified bound, or
// "unverified" when the exact verifier did not confirm it.
#include <cstdio>

namespace lpvid::bench {

/// "%10.3g" of x if verified, else "unverified"; four rotating buffers, so
/// up to four cells can appear in one printf.
inline const char* certified_cell(bool verified, double x) {
  static char buf[4][32];
  static int k = 0;
  k = (k + 1) % 4;
  if (verified)
    std::snprintf(buf[k], sizeof buf[k], "%10.3g", x);
  else
    std::snprintf(buf[k], sizeof buf[k], "%10s", "unverified");
  return buf[k];
}

}  // namespace lpvid::bench
