#include "lmi/split_factorisations.h"

#include <cmath>
#include <utility>

#include "core/helper_thread.h"

namespace lpvid {

namespace {

using Index = Eigen::Index;
using Dense = Eigen::MatrixXd;
using Sign = Eigen::internal::SignMatrix;

/// A21 −= A20·w, rows [0, rs) of the panel below the pivot k, in two parts
/// when there is enough work (both parts at least two rows: a one-row
/// product would be evaluated as a dot product, in another order).
void column_update(Dense& mat, Index k, Index rs, const Eigen::VectorXd& temp, HelperThread* helper) {
  Eigen::Block<Dense, Eigen::Dynamic, 1> A21(mat, k + 1, k, rs, 1);  // Eigen's own block types
  Eigen::Block<Dense, Eigen::Dynamic, Eigen::Dynamic> A20(mat, k + 1, 0, rs, k);
  const auto part = [&](Index r0, Index n) { A21.segment(r0, n).noalias() -= A20.middleRows(r0, n) * temp.head(k); };
  constexpr Index kMinWork = 1 << 15;  // multiply-adds: below, a hand-over costs more than it saves
  if (helper == nullptr || rs < 64 || rs * k < kMinWork) {
    A21.noalias() -= A20 * temp.head(k);  // Eigen's own statement
    return;
  }
  const Index half = rs / 2;
  fork_join(helper, [&] { part(half, rs - half); }, [&] { part(0, half); });
}

/// Step k's symmetric pivot: the largest remaining diagonal entry moves to
/// (k, k), rows and columns swapped in the lower triangle.
void pivot(Dense& mat, Index k, Index biggest) {
  const Index size = mat.rows();
  const Index s = size - biggest - 1;
  mat.row(k).head(k).swap(mat.row(biggest).head(k));
  mat.col(k).tail(s).swap(mat.col(biggest).tail(s));
  std::swap(mat.coeffRef(k, k), mat.coeffRef(biggest, biggest));
  for (Index i = k + 1; i < biggest; ++i) std::swap(mat.coeffRef(i, k), mat.coeffRef(biggest, i));
}

/// The sign bookkeeping of Eigen's loop after pivot value a.
void update_sign(Sign& sign, double a) {
  if (sign == Eigen::internal::PositiveSemiDef) {
    if (a < 0) sign = Eigen::internal::Indefinite;
  } else if (sign == Eigen::internal::NegativeSemiDef) {
    if (a > 0) sign = Eigen::internal::Indefinite;
  } else if (sign == Eigen::internal::ZeroSign) {
    if (a > 0) sign = Eigen::internal::PositiveSemiDef;
    else if (a < 0) sign = Eigen::internal::NegativeSemiDef;
  }
}

/// Eigen 3.4's ldlt_inplace<Lower>::unblocked with the split column update.
template <typename Transpositions>
bool factor(Dense& mat, Transpositions& transpositions, Eigen::VectorXd& temp, Sign& sign, HelperThread* helper) {
  const Index size = mat.rows();
  if (size <= 1) {
    transpositions.setIdentity();
    sign = size == 0 ? Eigen::internal::ZeroSign
           : mat(0, 0) > 0 ? Eigen::internal::PositiveSemiDef
           : mat(0, 0) < 0 ? Eigen::internal::NegativeSemiDef
                           : Eigen::internal::ZeroSign;
    return true;
  }
  bool found_zero_pivot = false, ret = true;
  for (Index k = 0; k < size; ++k) {
    Index biggest = 0;
    mat.diagonal().tail(size - k).cwiseAbs().maxCoeff(&biggest);
    biggest += k;
    transpositions.coeffRef(k) = static_cast<int>(biggest);
    if (k != biggest) pivot(mat, k, biggest);
    const Index rs = size - k - 1;
    if (k > 0) {
      Eigen::Block<Dense, 1, Eigen::Dynamic> A10(mat, k, 0, 1, k);
      temp.head(k) = mat.diagonal().real().head(k).asDiagonal() * A10.adjoint();
      mat.coeffRef(k, k) -= (A10 * temp.head(k)).value();
      if (rs > 0) column_update(mat, k, rs, temp, helper);
    }
    const double akk = mat(k, k);
    const bool valid = std::abs(akk) > 0;
    if (k == 0 && !valid) {
      sign = Eigen::internal::ZeroSign;
      for (Index j = 0; j < size; ++j) {
        transpositions.coeffRef(j) = static_cast<int>(j);
        ret = ret && (mat.col(j).tail(size - j - 1).array() == 0.0).all();
      }
      return ret;
    }
    Eigen::Block<Dense, Eigen::Dynamic, 1> A21(mat, k + 1, k, rs, 1);
    if (rs > 0 && valid) A21 /= akk;
    else if (rs > 0) ret = ret && (A21.array() == 0.0).all();
    if (found_zero_pivot && valid) ret = false;
    else if (!valid) found_zero_pivot = true;
    update_sign(sign, akk);
  }
  return ret;
}

}  // namespace

SplitLdlt& SplitLdlt::compute_split(const Dense& a, HelperThread* helper) {
  const Index size = a.rows();
  m_matrix = a;
  m_l1_norm = 0;
  for (Index col = 0; col < size; ++col) {  // as LDLT::compute: the lower triangle's largest absolute column sum
    const double sum = m_matrix.col(col).tail(size - col).lpNorm<1>() + m_matrix.row(col).head(col).lpNorm<1>();
    if (sum > m_l1_norm) m_l1_norm = sum;
  }
  m_transpositions.resize(size);
  m_isInitialized = false;
  m_temporary.resize(size);
  m_sign = Eigen::internal::ZeroSign;
  m_info = factor(m_matrix, m_transpositions, m_temporary, m_sign, helper) ? Eigen::Success : Eigen::NumericalIssue;
  m_isInitialized = true;
  return *this;
}

void llt_inverse_split(const Eigen::LLT<Dense>& llt, Dense& P, HelperThread* helper) {
  const Index n = llt.rows();
  if (helper == nullptr || n < 64) {
    P = llt.solve(Dense::Identity(n, n));
    return;
  }
  P.resize(n, n);
  const Index split = n / 8 * 4;  // about half, a multiple of 4
  const auto part = [&](Index c0, Index c1) {
    P.middleCols(c0, c1 - c0) = llt.solve(Dense::Identity(n, n).middleCols(c0, c1 - c0));
  };
  fork_join(helper, [&] { part(split, n); }, [&] { part(0, split); });
}

}  // namespace lpvid
