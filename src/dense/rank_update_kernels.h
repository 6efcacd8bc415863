#pragma once
/// The micro-kernel of the Cholesky factorisation's rank update
/// A22 −= A21·A21ᵀ (dense/split_llt.cc), written with 4-wide vector
/// instructions (AVX2) but with the operations of Eigen's 2-wide
/// general block-panel kernel (gebp, its 2pX4 micro block): each entry's sum
/// starts at 0.0 and adds its products a·b one by one in the order of the
/// packed depth (a product rounded, then the sum rounded: no fused
/// multiply-add), and is then subtracted from the entry. A vector lane does
/// exactly what Eigen's 2-wide lane does, so the factor is the same bits as
/// Eigen's on any machine; the kernel only decides how fast.
///
/// It covers the rows Eigen treats in groups of 4 (counted from the first)
/// and the column panels of 4; the remaining rows and columns stay with
/// Eigen's own kernel (its 1- and 2-row paths order their sums otherwise).
/// Only used where the processor has AVX2 and the build did not enable fused
/// multiply-adds (as dense/ldlt_panel_kernels.h): `available()`; with
/// AVX-512F two row groups share an 8-wide vector (the code is compiled with
/// contraction off, since AVX-512F has fused multiply-adds). Measured on the
/// 3×3 n = 200 case (the Newton system of order 1 801 factored ~110 times):
/// the solve 17.6 s with Eigen's 2-wide kernel, 13.9 s 4-wide, 12.1–13 s 8-wide.

#include <cstddef>

namespace lpvid::rank_update_kernel {

using Index = std::ptrdiff_t;

/// AVX2 (4-wide vectors) and a build without fused multiply-adds.
bool available();
/// AVX-512F as well (8-wide vectors: two row groups in one).
bool wide_available();

/// For rows i < rows (a multiple of 4) and columns c < 4·panels:
/// res[c·stride + i] −= Σ_{k < depth} a(i, k)·b(k, c), the sum in k order from 0.0, with
/// a(i, k) = blockA[(i/4)·4·depth + 4k + i mod 4] (Eigen's packed lhs, 4-row panels) and
/// b(k, c) = blockB[(c/4)·4·depth + 4k + c mod 4] (its packed rhs, 4-column panels).
/// In the widest vectors the processor has (only when available()).
void minus_products(const double* blockA, const double* blockB, Index depth, Index rows, Index panels, double* res,
                    Index stride);
/// The same with vectors of `width` doubles, 4 or 8 (8 only when wide_available()): for tests.
void minus_products_at(int width, const double* blockA, const double* blockB, Index depth, Index rows, Index panels,
                       double* res, Index stride);

}  // namespace lpvid::rank_update_kernel
