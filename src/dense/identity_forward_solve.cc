#include "dense/identity_forward_solve.h"

#include <algorithm>

#include <Eigen/Dense>

#include "dense/rank_update_kernels.h"

namespace lpvid {

#ifndef __FMA__

bool identity_forward_solve_available() { return true; }

namespace {

namespace ei = Eigen::internal;
using Index = Eigen::Index;
using Traits = ei::gebp_traits<double, double>;
using TriMapper = ei::const_blas_data_mapper<double, Index, Eigen::ColMajor>;
using OtherMapper = ei::blas_data_mapper<double, Index, Eigen::ColMajor, Eigen::Unaligned, 1>;
/// The blocking of Eigen's triangular_solver_selector for a dynamic column-major right-hand side.
using Blocking = ei::gemm_blocking_space<Eigen::ColMajor, double, double, Eigen::Dynamic, Eigen::Dynamic, Eigen::Dynamic, 4>;
constexpr Index kSmallPanel = std::max<Index>(Traits::mr, Traits::nr);

/// What one row block [k2, k2 + kc) of the solve needs.
struct SolveParts {
  TriMapper tri;
  OtherMapper other;
  double* blockA;
  double* blockB;
  Index size, kc, mc, subcols;
};

/// The small triangle of rows [k2 + k1, k2 + k1 + width) on columns [j2, j2 + cols), unblocked.
void small_triangle(const SolveParts& s, Index k2, Index k1, Index width, Index j2, Index cols) {
  for (Index k = 0; k < width; ++k) {
    const Index i = k2 + k1 + k, rs = width - k - 1, below = i + 1;
    const double a = 1.0 / s.tri(i, i);
    for (Index j = j2; j < j2 + cols; ++j) {
      double& otherij = s.other(i, j);
      otherij *= a;
      const double b = otherij;
      OtherMapper::LinearMapper r = s.other.getLinearMapper(below, j);
      TriMapper::LinearMapper l = s.tri.getLinearMapper(below, i);
      for (Index i3 = 0; i3 < rs; ++i3) r(i3) -= b * l(i3);
    }
  }
}

/// R1 = A11⁻¹·B on the row block's columns [0, live), B packed as it goes (Eigen's "tricky part").
void diagonal_block(const SolveParts& s, Index k2, Index actual_kc, Index live) {
  ei::gebp_kernel<double, double, Index, OtherMapper, Traits::mr, Traits::nr, false, false> gebp;
  ei::gemm_pack_lhs<double, Index, TriMapper, Traits::mr, Traits::LhsProgress, Traits::LhsPacket4Packing, Eigen::ColMajor>
      pack_lhs;
  ei::gemm_pack_rhs<double, Index, OtherMapper, Traits::nr, Eigen::ColMajor, false, true> pack_rhs;
  for (Index j2 = 0; j2 < live; j2 += s.subcols) {
    const Index cols = std::min(live - j2, s.subcols);
    for (Index k1 = 0; k1 < actual_kc; k1 += kSmallPanel) {
      const Index width = std::min(actual_kc - k1, kSmallPanel);
      small_triangle(s, k2, k1, width, j2, cols);
      const Index target_rows = actual_kc - k1 - width, start_block = k2 + k1;
      pack_rhs(s.blockB + actual_kc * j2, s.other.getSubMapper(start_block, j2), width, cols, actual_kc, k1);
      if (target_rows > 0) {
        const Index start_target = start_block + width;
        pack_lhs(s.blockA, s.tri.getSubMapper(start_target, start_block), width, target_rows);
        gebp(s.other.getSubMapper(start_target, j2), s.blockA, s.blockB + actual_kc * j2, target_rows, width, cols, -1.0,
             width, actual_kc, 0, k1);
      }
    }
  }
}

/// R2 −= A21·B below the row block, columns [0, live) (Eigen's "GEPP"). The
/// rows in groups of 4 times the full column panels of 4 by
/// rank_update_kernel (Eigen's kernel's operations lane for lane, where the
/// processor has AVX2), the rest by Eigen's kernel: the same bits either way.
void below_block(const SolveParts& s, Index k2, Index actual_kc, Index live) {
  static const bool vectors = rank_update_kernel::available();
  ei::gebp_kernel<double, double, Index, OtherMapper, Traits::mr, Traits::nr, false, false> gebp;
  ei::gemm_pack_lhs<double, Index, TriMapper, Traits::mr, Traits::LhsProgress, Traits::LhsPacket4Packing, Eigen::ColMajor>
      pack_lhs;
  const Index full = vectors ? live / 4 * 4 : 0;  // columns in full panels of 4
  for (Index i2 = k2 + s.kc; i2 < s.size; i2 += s.mc) {
    const Index actual_mc = std::min(s.mc, s.size - i2);
    pack_lhs(s.blockA, s.tri.getSubMapper(i2, k2), actual_kc, actual_mc);
    const Index quick = full > 0 ? actual_mc / 4 * 4 : 0;
    if (quick > 0) {
      rank_update_kernel::minus_products(s.blockA, s.blockB, actual_kc, quick, full / 4, &s.other(i2, 0),
                                         s.other.stride());
      if (full < live)
        gebp(s.other.getSubMapper(i2, full), s.blockA, s.blockB + actual_kc * full, quick, actual_kc, live - full, -1.0, -1,
             -1, 0, 0);
    }
    if (quick < actual_mc)
      gebp(s.other.getSubMapper(i2 + quick, 0), s.blockA + actual_kc * quick, s.blockB, actual_mc - quick, actual_kc, live,
           -1.0, -1, -1, 0, 0);
  }
}

}  // namespace

void identity_forward_solve(const Eigen::MatrixXd& lower, Index c0,
                            Eigen::Block<Eigen::MatrixXd, Eigen::Dynamic, Eigen::Dynamic, true> X) {
  const Index size = lower.rows(), cols = X.cols();
  X.setZero();
  for (Index c = 0; c < cols && c0 + c < size; ++c) X(c0 + c, c) = 1.0;
  if (size == 0 || cols == 0) return;
  Blocking blocking(size, cols, size, 1, false);
  const Index kc = blocking.kc(), mc = std::min(size, blocking.mc());
  Eigen::VectorXd blockA(kc * mc), blockB(kc * cols);  // scratch (Eigen's aligned allocation)
  std::ptrdiff_t l1 = 0, l2 = 0, l3 = 0;
  ei::manage_caching_sizes(Eigen::GetAction, &l1, &l2, &l3);
  const Index stride = X.outerStride();
  Index subcols = l2 / (4 * static_cast<Index>(sizeof(double)) * std::max(stride, size));
  subcols = std::max<Index>((subcols / Traits::nr) * Traits::nr, Traits::nr);
  const SolveParts s{TriMapper(lower.data(), lower.outerStride()), OtherMapper(X.data(), stride, 1), blockA.data(),
                     blockB.data(), size, kc, mc, subcols};
  for (Index k2 = 0; k2 < size; k2 += kc) {
    const Index actual_kc = std::min(size - k2, kc);
    // Columns c0 + c ≥ k2 + actual_kc are still zero in every row the block reads or writes.
    const Index nonzero = std::max<Index>(0, k2 + actual_kc - c0);
    const Index live = std::min(cols, (nonzero + Traits::nr - 1) / Traits::nr * Traits::nr);
    if (live == 0) continue;
    diagonal_block(s, k2, actual_kc, live);
    below_block(s, k2, actual_kc, live);
  }
}

#else

bool identity_forward_solve_available() { return false; }

void identity_forward_solve(const Eigen::MatrixXd& lower, Eigen::Index c0,
                            Eigen::Block<Eigen::MatrixXd, Eigen::Dynamic, Eigen::Dynamic, true> X) {
  X = Eigen::MatrixXd::Identity(lower.rows(), lower.rows()).middleCols(c0, X.cols());
  lower.triangularView<Eigen::Lower>().solveInPlace(X);
}

#endif

}  // namespace lpvid
