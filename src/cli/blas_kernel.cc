#include "cli/blas_kernel.h"

#include <cstdlib>
#include <cstring>
#include <unistd.h>

namespace lpvid::cli {

namespace {

bool cpu_runs_pinned_kernel() {
#if defined(__x86_64__)
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
  return false;
#endif
}

bool pinned_now() {
  const char* core = std::getenv("OPENBLAS_CORETYPE");
  return core != nullptr && std::strcmp(core, kPinnedBlasCore) == 0;
}

}  // namespace

void pin_blas_kernel(char** argv) {
  if (!cpu_runs_pinned_kernel() || pinned_now() || std::getenv("LPVID_BLAS_PINNED") != nullptr) return;
  if (setenv("OPENBLAS_CORETYPE", kPinnedBlasCore, 1) != 0 || setenv("LPVID_BLAS_PINNED", "1", 1) != 0) return;
  execv("/proc/self/exe", argv);
  // the restart failed (no /proc): go on with the kernels already loaded
}

const char* blas_kernel_text() {
  if (pinned_now() && cpu_runs_pinned_kernel()) return "OpenBLAS Haswell kernels (OPENBLAS_CORETYPE=Haswell)";
  return "OpenBLAS kernels chosen for this CPU (not pinned: no AVX2/FMA, or the restart failed)";
}

}  // namespace lpvid::cli
