#pragma once
/// The pivoted LDLᵀ of the structured barrier's Newton system
/// (lmi/delta_form_barrier.cc), shared with a helper thread so that every
/// number is still computed by the same operations as by Eigen alone.
///
/// SplitLdlt: Eigen's LDLᵀ factorisation (diagonal pivoting, the unblocked algorithm of
/// Eigen 3.4's ldlt_inplace<Lower>) with its one costly operation, the
/// column update A21 −= A20·(D·A10ᵀ), split by rows between the caller and a
/// helper thread. A row's update is one matrix-vector product row whichever
/// thread computes it (Eigen's column-major kernel forms every row's sum by
/// the same operations: the split keeps at least two rows per part, since a
/// one-row product is evaluated as a dot product), so the factors, the
/// pivots and every solve are bit for bit those of Eigen::LDLT::compute —
/// tests/dense/split_factorisations_test.cc checks it. From 256 rows on, on
/// processors with AVX2, the loop runs in panels of 16 columns with the pivot
/// order found first (split_factorisations.cc says why the bits stay Eigen's).
/// The structured barrier (lmi/delta_form_barrier.cc, lmi/newton_factor.h)
/// uses it where the Newton system's Cholesky meets a pivot that is not
/// positive, and for the final tight centering.

#include <Eigen/Cholesky>
#include <Eigen/Dense>

namespace lpvid {

class HelperThread;

class SplitLdlt : public Eigen::LDLT<Eigen::MatrixXd> {
 public:
  /// As Eigen::LDLT::compute(a); `helper` (may be null: one thread) takes a
  /// share of the long column updates.
  SplitLdlt& compute_split(const Eigen::MatrixXd& a, HelperThread* helper);
};

/// The largest absolute column sum of the symmetric matrix held in a's lower
/// triangle, as Eigen's LLT::compute and LDLT::compute record it (their
/// rcond() reads it): the same sums in the same order.
double lower_triangle_l1_norm(const Eigen::MatrixXd& a);

}  // namespace lpvid
