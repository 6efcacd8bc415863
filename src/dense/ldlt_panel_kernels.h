#pragma once
/// The two inner loops of the LDLᵀ factorisation in panels
/// (dense/split_factorisations.cc), written with 4-wide vector instructions
/// (AVX2) but with the operations of Eigen's 2-wide column-major
/// matrix-vector kernel: each sum starts at 0.0, adds its products a·b one
/// by one in column order (a product rounded, then the sum rounded: no fused
/// multiply-add), and is then subtracted from the entry. A vector lane does
/// exactly what a 2-wide lane or a scalar does, so the factors are the same
/// bits as Eigen's on any machine; the kernels only decide how fast.
///
/// Only used where the processor has AVX2 and the build did not enable fused
/// multiply-adds (-mfma/-march=native let Eigen fuse, and these kernels do
/// not): `panel_kernels_available()`; elsewhere the factorisation keeps
/// Eigen's column-at-a-time loop.

#include <cstddef>

namespace lpvid::ldlt_panel {

using Index = std::ptrdiff_t;

/// Columns a panel holds (the kernels' width).
constexpr Index kWidth = 16;

bool panel_kernels_available();

/// For rows i ∈ [r0, r1) and panel columns t < kWidth:
/// R[t·ldr + i] −= c_0, −= c_1, …, c_b = Σ_{j ∈ [b·bc, (b+1)·bc)} L[j·ld + row0 + i]·W[j·kWidth + t]
/// over the blocks of bc columns (4 or 16) covering [0, k0).
void bulk(const double* L, Index ld, Index row0, Index k0, Index bc, const double* W, double* R, Index ldr, Index r0,
          Index r1);

/// Column t's remaining blocks [k0, k0 + t) (block width bc, the last one
/// cut at k0 + t) for rows i ∈ [r0, r1): Rt[i] −= Σ_{j ∈ block} L[j·ld + row0 + i]·w[j].
void column_tail(const double* L, Index ld, Index row0, Index k0, Index t, Index bc, const double* w, double* Rt,
                 Index r0, Index r1);

}  // namespace lpvid::ldlt_panel
