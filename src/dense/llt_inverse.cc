#include "dense/llt_inverse.h"

#include <algorithm>

#include "core/helper_thread.h"
#include "dense/identity_forward_solve.h"
#include "dense/split_llt.h"

namespace lpvid {

namespace {

using Index = Eigen::Index;
using Dense = Eigen::MatrixXd;

/// The first column of the helper's part of X = L⁻¹: a multiple of 4 (the
/// forward solve's column groups) where the work, (n − c)² for column c, is
/// shared evenly.
Index forward_split(Index n) {
  double total = 0;
  for (Index c = 0; c < n; ++c) total += static_cast<double>((n - c) * (n - c));
  double left = 0;
  Index split = 0;
  while (split < n && left + static_cast<double>((n - split) * (n - split)) <= total / 2)
    left += static_cast<double>((n - split) * (n - split)), ++split;
  return std::clamp<Index>(split / 4 * 4, 4, n / 4 * 4 - 4);
}

/// X ← L⁻¹ (lower triangular; zeros above the diagonal).
void lower_inverse(const Eigen::LLT<Dense>& llt, Dense& X, HelperThread* helper) {
  const Index n = llt.rows();
  X.resize(n, n);
  if (!identity_forward_solve_available()) {
    X.setIdentity();
    llt.matrixL().solveInPlace(X);
    return;
  }
  if (helper == nullptr || n < 64) {
    identity_forward_solve(llt.matrixLLT(), 0, X.middleCols(0, n));
    return;
  }
  const Index split = forward_split(n);
  fork_join(
      helper, [&] { identity_forward_solve(llt.matrixLLT(), split, X.middleCols(split, n - split)); },
      [&] { identity_forward_solve(llt.matrixLLT(), 0, X.middleCols(0, split)); });
}

}  // namespace

void llt_inverse(const Eigen::LLT<Dense>& llt, Dense& P, Dense& scratch, HelperThread* helper) {
  const Index n = llt.rows();
  lower_inverse(llt, scratch, helper);
  scratch.transposeInPlace();  // B = Xᵀ: B(i, k) = X(k, i), zero for i > k
  P.setZero(n, n);
  for (Index k0 = 0; k0 < n; k0 += kGramDepth) {
    const Index depth = std::min(kGramDepth, n - k0), rows = k0 + depth;
    Eigen::Block<Dense> lower(P, 0, 0, rows, rows);
    const Eigen::Block<Dense> columns(scratch, 0, k0, rows, depth);
    lower_rank_update(lower, columns, helper);  // P −= B(:, k0 …)·B(:, k0 …)ᵀ
  }
  for (Index j = 0; j < n; ++j) {
    P(j, j) = -P(j, j);
    for (Index i = j + 1; i < n; ++i) P(j, i) = P(i, j) = -P(i, j);
  }
}

}  // namespace lpvid
