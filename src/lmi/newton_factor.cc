#include "lmi/newton_factor.h"

namespace lpvid {

void NewtonFactor::compute(const Eigen::MatrixXd& h, HelperThread* helper, bool pivoted) {
  if (!pivoted) llt_.compute_split(h, helper);
  pivoted_ = pivoted || llt_.info() != Eigen::Success;
  if (pivoted_) {
    llt_.compute(Eigen::MatrixXd(0, 0));  // one factor in memory at a time
    ldlt_.compute_split(h, helper);
  }
}

void NewtonFactor::release() {
  llt_.compute(Eigen::MatrixXd(0, 0));
  ldlt_.compute(Eigen::MatrixXd(0, 0));
  pivoted_ = false;
}

bool NewtonFactor::positive() const {
  if (!pivoted_) return llt_.info() == Eigen::Success && llt_.matrixLLT().size() > 0;
  return ldlt_.info() == Eigen::Success && ldlt_.isPositive();
}

Eigen::VectorXd NewtonFactor::solve(const Eigen::VectorXd& b) const { return pivoted_ ? Eigen::VectorXd(ldlt_.solve(b)) : Eigen::VectorXd(llt_.solve(b)); }

}  // namespace lpvid
