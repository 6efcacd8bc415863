#include "toeplitz/fftw_support.h"

namespace lpvid::fftw {

std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

Eigen::Index smooth_size(Eigen::Index n) {
  for (Eigen::Index m = n > 1 ? n : 1;; ++m) {
    Eigen::Index k = m;
    for (const Eigen::Index f : {2, 3, 5})
      while (k % f == 0) k /= f;
    if (k == 1) return m;
  }
}

}  // namespace lpvid::fftw
