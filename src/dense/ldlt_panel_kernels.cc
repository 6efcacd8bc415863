#include "dense/ldlt_panel_kernels.h"

#if defined(__x86_64__) && !defined(__FMA__)
#include <immintrin.h>
#define LPVID_LDLT_PANEL_KERNELS 1
#endif

namespace lpvid::ldlt_panel {

#ifdef LPVID_LDLT_PANEL_KERNELS

bool panel_kernels_available() { return __builtin_cpu_supports("avx2"); }

namespace {

/// One block [j0, j1) of four panel columns t … t+3 for rows i … i+7: the
/// eight sums, then R −= each (the operations of the header).
__attribute__((target("avx2"))) void block_8x4(const double* L, Index ld, Index row, Index j0, Index j1,
                                               const double* W, Index t, double* R, Index ldr, Index i) {
  __m256d s[2][4];
  for (auto& half : s)
    for (auto& v : half) v = _mm256_setzero_pd();
  for (Index j = j0; j < j1; ++j) {
    const double* l = L + j * ld + row;
    const __m256d l0 = _mm256_loadu_pd(l), l1 = _mm256_loadu_pd(l + 4);
    const double* w = W + j * kWidth + t;
    for (int q = 0; q < 4; ++q) {
      const __m256d wq = _mm256_broadcast_sd(w + q);
      s[0][q] = _mm256_add_pd(s[0][q], _mm256_mul_pd(l0, wq));
      s[1][q] = _mm256_add_pd(s[1][q], _mm256_mul_pd(l1, wq));
    }
  }
  for (int q = 0; q < 4; ++q) {
    double* r = R + (t + q) * ldr + i;
    _mm256_storeu_pd(r, _mm256_sub_pd(_mm256_loadu_pd(r), s[0][q]));
    _mm256_storeu_pd(r + 4, _mm256_sub_pd(_mm256_loadu_pd(r + 4), s[1][q]));
  }
}

/// The same sum for one row and one column, in scalar operations (no fused multiply-add in this build).
double block_sum(const double* L, Index ld, Index row, Index j0, Index j1, const double* w, Index w_stride) {
  double c = 0;
  for (Index j = j0; j < j1; ++j) c += L[j * ld + row] * w[j * w_stride];
  return c;
}

}  // namespace

__attribute__((target("avx2"))) void bulk(const double* L, Index ld, Index row0, Index k0, Index bc, const double* W,
                                          double* R, Index ldr, Index r0, Index r1) {
  Index i = r0;
  for (; i + 8 <= r1; i += 8)
    for (Index j2 = 0; j2 < k0; j2 += bc)
      for (Index t = 0; t < kWidth; t += 4) block_8x4(L, ld, row0 + i, j2, j2 + bc, W, t, R, ldr, i);
  for (; i < r1; ++i)
    for (Index j2 = 0; j2 < k0; j2 += bc)
      for (Index t = 0; t < kWidth; ++t) R[t * ldr + i] -= block_sum(L, ld, row0 + i, j2, j2 + bc, W + t, kWidth);
}

__attribute__((target("avx2"))) void column_tail(const double* L, Index ld, Index row0, Index k0, Index t, Index bc,
                                                 const double* w, double* Rt, Index r0, Index r1) {
  const Index k = k0 + t;
  for (Index j2 = k0; j2 < k; j2 += bc) {
    const Index j1 = j2 + bc < k ? j2 + bc : k;
    Index i = r0;
    for (; i + 4 <= r1; i += 4) {
      __m256d s = _mm256_setzero_pd();
      for (Index j = j2; j < j1; ++j)
        s = _mm256_add_pd(s, _mm256_mul_pd(_mm256_loadu_pd(L + j * ld + row0 + i), _mm256_broadcast_sd(w + j)));
      _mm256_storeu_pd(Rt + i, _mm256_sub_pd(_mm256_loadu_pd(Rt + i), s));
    }
    for (; i < r1; ++i) Rt[i] -= block_sum(L, ld, row0 + i, j2, j1, w, 1);
  }
}

#else

bool panel_kernels_available() { return false; }
void bulk(const double*, Index, Index, Index, Index, const double*, double*, Index, Index, Index) {}
void column_tail(const double*, Index, Index, Index, Index, Index, const double*, double*, Index, Index) {}

#endif

}  // namespace lpvid::ldlt_panel
