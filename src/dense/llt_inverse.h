#pragma once
/// P = F⁻¹ from the Cholesky factor F = L·Lᵀ of the structured barrier's LMI
/// matrix (lmi/delta_form_barrier.cc, once per Newton step), as
/// P = L⁻ᵀ·L⁻¹ = XᵀX with X = L⁻¹ (LAPACK's dpotri does the same):
///  1. X = L⁻¹ by the forward solve that skips the identity's zeros
///     (dense/identity_forward_solve.h), the columns in two parts of equal work;
///  2. P's lower triangle = Σ_k X(k, i)·X(k, j) over k ≥ max(i, j), as rank
///     updates of depth kGramDepth (dense/split_llt.h's lower_rank_update on
///     Xᵀ's columns [k0, k0 + kGramDepth)), each on the leading
///     (k0 + kGramDepth)-square block only: the rows below it are zero in
///     those columns, since X is lower triangular;
///  3. the upper triangle mirrored (P is exactly symmetric).
/// Work: n³/6 multiply-adds for each of the two steps against n³/6 + n³/2
/// for L⁻ᵀ·(L⁻¹·I) by two triangular solves. Every entry is computed by the
/// same operations on one thread or two (the forward solve treats its
/// columns alike, the rank update its entries), so P does not depend on the
/// helper: tests/dense/llt_inverse_test.cc checks it, and P against Eigen's
/// llt.solve(I).

#include <Eigen/Cholesky>
#include <Eigen/Dense>

namespace lpvid {

class HelperThread;

/// Xᵀ's columns per rank update in step 2 (a multiple of 4).
inline constexpr Eigen::Index kGramDepth = 256;

/// P ← F⁻¹ (P resized to n × n); `scratch` holds X (resized to n × n);
/// `helper` (may be null: one thread) takes half the work.
void llt_inverse(const Eigen::LLT<Eigen::MatrixXd>& llt, Eigen::MatrixXd& P, Eigen::MatrixXd& scratch, HelperThread* helper);

}  // namespace lpvid
