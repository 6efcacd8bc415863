#pragma once
/// The first half of P = F⁻¹ = L⁻ᵀ·L⁻¹ (F = L·Lᵀ): X = L⁻¹ on a range of
/// the identity's columns, by Eigen 3.4's own blocked triangular solve (the
/// algorithm of its TriangularSolverMatrix.h for a lower column-major L and
/// column-major right-hand sides: the same blocking, the same packing, the
/// same matrix kernels, called with the same arguments) with one change: the
/// work on columns that are still zero is left out. Column c of the identity
/// stays +0 above row c through every step (+0 scaled by 1/L(i,i) > 0, and
/// +0 minus products with +0 stays +0; a kernel's sum of such products is
/// +0 and leaves an entry unchanged), so a row block [k2, k2 + kc) of the
/// solve need not touch the columns from k2 + kc on: they are skipped in
/// groups of 4 counted from the range's first column, the grouping of
/// Eigen's kernels, so every other column is computed by the same
/// operations. The result is bit for bit that of
/// `llt.matrixL().solveInPlace(X)` on the same columns of the identity —
/// tests/dense/split_factorisations_test.cc checks it — in a third of the
/// work on a whole identity.
///
/// Used only where no fused multiply-add is compiled in (the scalar updates
/// of the solve would then depend on the compiler's contraction choices):
/// `identity_forward_solve_available()`.

#include <Eigen/Core>

namespace lpvid {

bool identity_forward_solve_available();

/// X ← L⁻¹·I(:, c0 : c0 + X.cols()), L the lower triangle of `lower` (its
/// upper triangle is not read). X keeps its size (X.rows() = lower.rows());
/// its outer stride is that of the caller's matrix, as in Eigen's solve.
void identity_forward_solve(const Eigen::MatrixXd& lower, Eigen::Index c0,
                            Eigen::Block<Eigen::MatrixXd, Eigen::Dynamic, Eigen::Dynamic, true> X);

}  // namespace lpvid
