#pragma once
/// The Cholesky factorisation F = L·Lᵀ of the structured barrier's LMI matrix
/// (lmi/delta_form_barrier.cc, once per trial point), shared with a helper
/// thread so that every number is still computed by the same operations as
/// by Eigen::LLT::compute alone.
///
/// Eigen 3.4's blocked algorithm (llt_inplace<Lower>::blocked: blocks of
/// `size/8` rounded down to 16, between 8 and 128, columns) is run as it is,
/// with its two costly statements shared out:
///  - A21 ← A21·A11⁻ᵀ (a triangular solve on the right): rows are
///    independent; Eigen's own solve is called on the top and the bottom
///    rows, cut at a multiple of 4 (its kernels treat rows in groups of 4
///    counted from the first, and the last rows(mod 4) alike) with the
///    blocking of the whole call;
///  - A22 −= A21·A21ᵀ (the lower triangle's rank update, `lower_rank_update`):
///    Eigen's kernel walks the triangle in column panels of 4, each panel's
///    entries its own (a 4 × 4 diagonal block through a buffer, then the rows
///    below); the panels are shared between the threads, packed once.
/// So the factor is bit for bit Eigen's — tests/dense/split_llt_test.cc
/// checks it — on one thread or two. Shared only from 1 024 rows on (below,
/// one thread measured faster here).

#include <Eigen/Cholesky>
#include <Eigen/Dense>

namespace lpvid {

class HelperThread;

class SplitLlt : public Eigen::LLT<Eigen::MatrixXd> {
 public:
  SplitLlt() = default;
  explicit SplitLlt(const Eigen::MatrixXd& a) : Eigen::LLT<Eigen::MatrixXd>(a) {}
  /// As Eigen::LLT::compute(a); `helper` (may be null: one thread) takes a share of the work.
  SplitLlt& compute_split(const Eigen::MatrixXd& a, HelperThread* helper);
};

/// A22 −= A21·A21ᵀ on the lower triangle (the upper one is not touched), bit
/// for bit `A22.selfadjointView<Eigen::Lower>().rankUpdate(A21, -1.0)` on one
/// thread or two (`helper` may be null): Eigen's blocking and packing, its
/// kernel or rank_update_kernel's lane-for-lane copy of it, and every entry's
/// products summed by the same operations whichever thread computes it.
void lower_rank_update(Eigen::Block<Eigen::MatrixXd>& A22, const Eigen::Block<Eigen::MatrixXd>& A21, HelperThread* helper);

}  // namespace lpvid
