// lpvid-verify: the exact verifier's program. Its command line is
// verify/verify_command_line.h (the Python module runs it in-process).
#include <string>
#include <vector>

#include "verify/verify_command_line.h"

int main(int argc, char** argv) {
  if (argc < 1) return lpvid::run_lpvid_verify({});
  return lpvid::run_lpvid_verify(std::vector<std::string>(argv + 1, argv + argc), argv[0]);
}
