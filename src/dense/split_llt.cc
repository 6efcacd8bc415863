#include "dense/split_llt.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/helper_thread.h"
#include "dense/rank_update_kernels.h"
#include "dense/split_factorisations.h"

namespace lpvid {

namespace {

namespace ei = Eigen::internal;
using Index = Eigen::Index;
using Dense = Eigen::MatrixXd;
using Block = Eigen::Block<Dense>;
using Traits = ei::gebp_traits<double, double>;
using ResMapper = ei::blas_data_mapper<double, Index, Eigen::ColMajor, Eigen::Unaligned, 1>;
/// The blockings Eigen builds for the two statements (triangular_solver_selector; selfadjoint_product_selector).
using SolveBlocking = ei::gemm_blocking_space<Eigen::ColMajor, double, double, Eigen::Dynamic, Eigen::Dynamic, Eigen::Dynamic, 4>;
using RankBlocking = ei::gemm_blocking_space<Eigen::ColMajor, double, double, Eigen::Dynamic, Eigen::Dynamic, Eigen::Dynamic>;
/// Eigen's triangular solve on the right for A21 ← A21·A11⁻ᵀ (A11ᵀ: an upper row-major view).
using RightSolve = ei::triangular_solve_matrix<double, Index, Eigen::OnTheRight, Eigen::Upper, false, Eigen::RowMajor,
                                               Eigen::ColMajor, 1>;
constexpr Index kTribbPanel = 4;  ///< tribb_kernel's block size: lcm(max(mr, nr), min(mr, nr)) with mr = nr = 4
static_assert(Traits::mr == 4 && Traits::nr == 4, "the row and panel cuts below assume Eigen's 4 × 4 double kernels");

/// Below this many rows a hand-over costs more than it saves.
constexpr Index kMinSharedRows = 128;
/// Below this size one thread is faster in the barrier: measured, a 600 × 600
/// factor took 5 ms on two threads against 4 ms on one, and the 3×3 n = 200
/// interval 17–18 s against 14.4–14.8 s (the helper's spinning after each
/// hand-over slows the caller's own work on this 2-vCPU machine); 1 200 × 1 200:
/// 24 against 35 ms, 3 200 × 3 200: 0.44 against 0.73 s.
constexpr Index kMinSharedSize = 1024;

/// A21 ← A21·A11⁻ᵀ, the rows in two parts cut at a multiple of 4, each by
/// Eigen's own solve with the blocking of the whole call.
void solve_right(const Block& A11, Block& A21, HelperThread* helper) {
  const Index rows = A21.rows(), size = A11.rows();
  const Index cut = rows / 8 * 4;
  const auto part = [&](Index r0, Index r1) {
    SolveBlocking blocking(rows, size, size, 1, false);
    RightSolve::run(size, r1 - r0, A11.data(), A11.outerStride(), A21.data() + r0, 1, A21.outerStride(), blocking);
  };
  fork_join(helper, [&] { part(cut, rows); }, [&] { part(0, cut); });
}

/// The leading rows of a gebp call that rank_update_kernel takes (its groups
/// of 4; none where the processor lacks AVX2).
Index vector_rows(Index rows) {
  static const bool available = rank_update_kernel::available();
  return available ? rows / 4 * 4 : 0;
}

/// Column panels [j0, j1) (multiples of 4) of tribb_kernel<Lower> on the
/// m × m diagonal block at `res`: each panel's 4 × 4 diagonal block through
/// a zeroed buffer, then the rows below it.
void triangle_panels(double* res, Index stride, const double* blockA, const double* blockB, Index m, Index depth,
                     Index j0, Index j1) {
  ei::gebp_kernel<double, double, Index, ResMapper, Traits::mr, Traits::nr, false, false> gebp;
  const ResMapper out(res, stride, 1);
  Eigen::Matrix<double, kTribbPanel, kTribbPanel, Eigen::ColMajor> buffer;
  for (Index j = j0; j < j1; j += kTribbPanel) {
    const Index width = std::min<Index>(kTribbPanel, m - j);
    const double* b = blockB + j * depth;
    buffer.setZero();
    gebp(ResMapper(buffer.data(), kTribbPanel, 1), blockA + depth * j, b, width, depth, width, -1.0, -1, -1, 0, 0);
    for (Index j1c = 0; j1c < width; ++j1c) {
      ResMapper::LinearMapper r = out.getLinearMapper(j, j + j1c);
      for (Index i1 = j1c; i1 < width; ++i1) r(i1) += buffer(i1, j1c);
    }
    const Index below = j + width;
    const Index quick = width == kTribbPanel ? vector_rows(m - below) : 0;
    if (quick > 0) rank_update_kernel::minus_products(blockA + depth * below, b, depth, quick, 1, &out(below, j), stride);
    if (below + quick < m)
      gebp(out.getSubMapper(below + quick, j), blockA + depth * (below + quick), b, m - below - quick, depth, width, -1.0,
           -1, -1, 0, 0);
  }
}

/// Columns [c0, c1) (multiples of 4) of the rows [i2, i2 + m) left of their
/// diagonal block: the vector kernel on the leading rows in groups of 4
/// (`quick`), Eigen's kernel on the rest; each entry by the same operations
/// whatever the column range.
void rectangle_columns(const ResMapper& res, Index stride, const double* blockA, const double* blockB, Index i2, Index m,
                       Index depth, Index quick, Index c0, Index c1) {
  if (c1 <= c0) return;
  if (quick > 0)
    rank_update_kernel::minus_products(blockA, blockB + depth * c0, depth, quick, (c1 - c0) / 4, &res(i2, c0), stride);
  if (quick < m) {
    ei::gebp_kernel<double, double, Index, ResMapper, Traits::mr, Traits::nr, false, false> gebp;
    gebp(res.getSubMapper(i2 + quick, c0), blockA + depth * quick, blockB + depth * c0, m - quick, depth, c1 - c0, -1.0, -1,
         -1, 0, 0);
  }
}

}  // namespace

/// Eigen's general_matrix_matrix_triangular_product<Lower> loop; per row
/// block, the columns left of the diagonal block are cut in two halves and
/// the diagonal block's column panels where the two shares of its triangle
/// are equal, one of each for each thread.
void lower_rank_update(Eigen::Block<Eigen::MatrixXd>& A22, const Eigen::Block<Eigen::MatrixXd>& A21, HelperThread* helper) {
  const Index size = A22.cols(), depth = A21.cols(), stride = A22.outerStride();
  if (size == 0 || depth == 0) return;
  RankBlocking blocking(size, size, depth, 1, false);
  const Index kc = blocking.kc();
  Index mc = std::min(size, blocking.mc());
  if (mc > Traits::nr) mc = (mc / Traits::nr) * Traits::nr;
  std::vector<double, Eigen::aligned_allocator<double>> blockA(static_cast<size_t>(kc * mc)),
      blockB(static_cast<size_t>(kc * size));
  const ei::const_blas_data_mapper<double, Index, Eigen::ColMajor> lhs(A21.data(), A21.outerStride());
  const ei::const_blas_data_mapper<double, Index, Eigen::RowMajor> rhs(A21.data(), A21.outerStride());
  ei::gemm_pack_lhs<double, Index, decltype(lhs), Traits::mr, Traits::LhsProgress, Traits::LhsPacket4Packing, Eigen::ColMajor>
      pack_lhs;
  ei::gemm_pack_rhs<double, Index, decltype(rhs), Traits::nr, Eigen::RowMajor> pack_rhs;
  const ResMapper res(A22.data(), stride, 1);
  for (Index k2 = 0; k2 < depth; k2 += kc) {
    const Index actual_kc = std::min(k2 + kc, depth) - k2;
    pack_rhs(blockB.data(), rhs.getSubMapper(k2, 0), actual_kc, size);
    for (Index i2 = 0; i2 < size; i2 += mc) {
      const Index m = std::min(i2 + mc, size) - i2;
      pack_lhs(blockA.data(), lhs.getSubMapper(i2, k2), actual_kc, m);
      const Index left = std::min(size, i2);  // the columns left of the diagonal block: i2 is a multiple of mc, of nr = 4
      const Index quick = left % 4 == 0 ? vector_rows(m) : 0;
      const Index half = helper == nullptr ? left : left / 8 * 4;
      double* diagonal = A22.data() + stride * i2 + i2;
      const double* b = blockB.data() + actual_kc * i2;
      const Index cut = std::min(m, static_cast<Index>(std::ceil(0.2929 * static_cast<double>(m) / kTribbPanel)) * kTribbPanel);
      fork_join(
          helper,
          [&] {
            rectangle_columns(res, stride, blockA.data(), blockB.data(), i2, m, actual_kc, quick, half, left);
            triangle_panels(diagonal, stride, blockA.data(), b, m, actual_kc, cut, m);
          },
          [&] {
            rectangle_columns(res, stride, blockA.data(), blockB.data(), i2, m, actual_kc, quick, 0, half);
            triangle_panels(diagonal, stride, blockA.data(), b, m, actual_kc, 0, cut);
          });
    }
  }
}

namespace {

/// Eigen 3.4's llt_inplace<double, Lower>::blocked with the two statements
/// shared out where the rows below the block are many enough.
Index llt_blocked(Dense& m, HelperThread* helper) {
  const Index size = m.rows();
  if (size < 32) return ei::llt_inplace<double, Eigen::Lower>::unblocked(m);
  if (size < kMinSharedSize) helper = nullptr;
  Index block = size / 8;
  block = std::min<Index>(std::max<Index>(block / 16 * 16, 8), 128);
  for (Index k = 0; k < size; k += block) {
    const Index bs = std::min(block, size - k), rs = size - k - bs;
    Block A11(m, k, k, bs, bs), A21(m, k + bs, k, rs, bs), A22(m, k + bs, k + bs, rs, rs);
    const Index ret = ei::llt_inplace<double, Eigen::Lower>::unblocked(A11);
    if (ret >= 0) return k + ret;
    if (rs <= 0) continue;
    if (rs < kMinSharedRows) {
      A11.adjoint().template triangularView<Eigen::Upper>().template solveInPlace<Eigen::OnTheRight>(A21);
      A22.template selfadjointView<Eigen::Lower>().rankUpdate(A21, -1.0);
    } else {
      solve_right(A11, A21, helper);
      lower_rank_update(A22, A21, helper);
    }
  }
  return -1;
}

}  // namespace

SplitLlt& SplitLlt::compute_split(const Dense& a, HelperThread* helper) {
  m_matrix = a;
  m_l1_norm = lower_triangle_l1_norm(m_matrix);
  m_isInitialized = true;
  m_info = llt_blocked(m_matrix, helper) == -1 ? Eigen::Success : Eigen::NumericalIssue;
  return *this;
}

}  // namespace lpvid
