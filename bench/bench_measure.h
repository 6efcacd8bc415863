#pragma once
// What the table benches measure alike: a comma-separated list of sizes from
// the command line, seconds since a time point, the process's CPU seconds, a
// file's size and the process's peak resident memory.
#include <sys/resource.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace lpvid::bench {

/// "100,200,400" → {100, 200, 400}.
inline std::vector<int> int_list(const char* text) {
  std::vector<int> out;
  std::stringstream ss(text);
  for (std::string b; std::getline(ss, b, ',');)
    if (!b.empty()) out.push_back(std::atoi(b.c_str()));
  return out;
}

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// CPU seconds (user + system) this process has used so far: unlike wall
/// time, not inflated by other jobs on a busy machine.
inline double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  const auto s = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return s(u.ru_utime) + s(u.ru_stime);
}

/// A stage's wall and CPU seconds: started at construction.
struct StageClock {
  std::chrono::steady_clock::time_point wall0 = std::chrono::steady_clock::now();
  double cpu0 = cpu_seconds();
  double wall() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count(); }
  double cpu() const { return cpu_seconds() - cpu0; }
};

/// The file's size in kB (0 when it does not exist).
inline double kilobytes(const std::string& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  return ec ? 0.0 : static_cast<double>(size) / 1024.0;
}

/// Peak resident memory of this process so far (VmHWM), MB.
inline double peak_mb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) / 1024.0;
  return 0.0;
}

}  // namespace lpvid::bench
