#pragma once
/// One BLAS code path on every machine (docs/determinism.md).
///
/// Debian's OpenBLAS picks its kernels by the CPU when it is loaded, before
/// main(): an AVX-512 machine runs other dgemm/dpotrf kernels than an AVX2
/// one, and CSDP's and SDPA's points (so the certified numbers of the
/// Theorem 3.1 stage, the fallback bounds) differ in their last digits
/// between machines. OpenBLAS reads OPENBLAS_CORETYPE only at load time, so
/// the program pins it and starts itself again.

namespace lpvid::cli {

/// The kernel lpvid pins: OpenBLAS's Haswell kernels (AVX2 + FMA), which
/// every x86-64 CPU since 2013 runs (Intel Haswell and later, AMD Zen).
inline constexpr const char* kPinnedBlasCore = "Haswell";

/// If this CPU runs the pinned kernels and OPENBLAS_CORETYPE is not already
/// kPinnedBlasCore, sets it and replaces the process by /proc/self/exe with
/// the same arguments (once: LPVID_BLAS_PINNED marks the second start).
/// Returns only when nothing was to be done or the restart failed; then the
/// program goes on with the kernels OpenBLAS chose.
void pin_blas_kernel(char** argv);

/// The BLAS kernels in use as a report states them: the pinned ones, or
/// OpenBLAS's own choice for this CPU.
const char* blas_kernel_text();

}  // namespace lpvid::cli
