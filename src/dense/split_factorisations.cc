#include "dense/split_factorisations.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include "core/helper_thread.h"
#include "dense/ldlt_panel_kernels.h"

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

/// The pivot checks of Eigen's loop after step k's pivot akk: A21 = column k
/// below the pivot (divided by akk when it is not zero).
struct PivotState {
  bool found_zero_pivot = false, ret = true;
  void after(Dense& mat, Index k, Sign& sign) {
    const Index rs = mat.rows() - k - 1;
    const double akk = mat(k, k);
    const bool valid = std::abs(akk) > 0;
    Eigen::Block<Dense, Eigen::Dynamic, 1> A21(mat, k + 1, k, rs, 1);
    if (rs > 0 && valid) A21 /= akk;
    else if (rs > 0) ret = ret && (A21.array() == 0.0).all();
    if (found_zero_pivot && valid) ret = false;
    else if (!valid) found_zero_pivot = true;
    update_sign(sign, akk);
  }
};

/// Step k's diagonal entry: temp.head(k) = D·A10ᵀ, a_kk −= A10·temp (Eigen's statements).
void diagonal_update(Dense& mat, Index k, Eigen::VectorXd& temp) {
  Eigen::Block<Dense, 1, Eigen::Dynamic> A10(mat, k, 0, 1, k);
  temp.head(k) = mat.diagonal().real().head(k).asDiagonal() * A10.adjoint();
  mat.coeffRef(k, k) -= (A10 * temp.head(k)).value();
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
  PivotState state;
  for (Index k = 0; k < size; ++k) {
    Index biggest = 0;
    mat.diagonal().tail(size - k).cwiseAbs().maxCoeff(&biggest);
    biggest += k;
    transpositions.coeffRef(k) = static_cast<int>(biggest);
    if (k != biggest) pivot(mat, k, biggest);
    const Index rs = size - k - 1;
    if (k > 0) {
      diagonal_update(mat, k, temp);
      if (rs > 0) column_update(mat, k, rs, temp, helper);
    }
    if (k == 0 && !(std::abs(mat(0, 0)) > 0)) {
      sign = Eigen::internal::ZeroSign;
      for (Index j = 0; j < size; ++j) {
        transpositions.coeffRef(j) = static_cast<int>(j);
        state.ret = state.ret && (mat.col(j).tail(size - j - 1).array() == 0.0).all();
      }
      return state.ret;
    }
    state.after(mat, k, sign);
  }
  return state.ret;
}

// ---------------------------------------------------------------------------
// The same factorisation in panels of columns, every entry by the same
// operations. Two facts make it possible:
//  - Eigen's loop chooses its pivot among the diagonal entries not yet
//    reached, which it has not changed (the algorithm is left-looking): the
//    pivot order is a function of the input's diagonal alone and can be
//    found first, the symmetric swaps made first, and the loop run unpivoted
//    (a row's entries are computed by the same operations wherever the row
//    sits).
//  - the column update's matrix-vector product (Eigen's column-major kernel,
//    GeneralMatrixVector.h) forms entry i as r_i − c_1 − c_2 − …, c_b the sum
//    of L(i, j)·w(j) over the b-th block of `block_cols` columns from 0 on,
//    summed in column order from 0.0 (16 columns a block when the matrix has
//    fewer than 4000 rows, else 4; one block below 128 columns).
// The blocks that end before a panel's first column are the same for all of
// its columns: they are applied to the whole panel at once, reading each L
// entry once per panel instead of once per column, by 4-wide vector kernels
// (dense/ldlt_panel_kernels.h) that keep Eigen's operations. Measured at
// n = 1 800 (random SPD): Eigen 0.21–0.32 s, panels 0.10 s on one thread;
// n = 3 600: 2.9–3.6 s against 1.7 s (one thread) and 1.0 s (two).

constexpr Index kPanel = ldlt_panel::kWidth;  ///< columns per panel (a multiple of both block widths)
constexpr Index kFirstPanel = 128;            ///< columns before it keep one block per column update
constexpr Index kRowChunk = 8;

/// Eigen's block width for a column update of ≥ 128 columns on a matrix with `stride` rows.
Index block_cols(Index stride) { return stride * static_cast<Index>(sizeof(double)) < 32000 ? 16 : 4; }

/// Rows [a, b) split in two at a multiple of the row chunk, the upper part on the helper.
void split_rows(HelperThread* helper, Index a, Index b, const std::function<void(Index, Index)>& work) {
  const Index half = a + (b - a) / 2 / kRowChunk * kRowChunk;
  if (helper == nullptr || b - a < 4 * kRowChunk) {
    work(a, b);
    return;
  }
  fork_join(helper, [&] { work(half, b); }, [&] { work(a, half); });
}

/// Columns [k0, k0 + 16) of the unpivoted loop (k0 ≥ 128 a multiple of
/// the block width, every column with at least two rows below it).
void factor_panel(Dense& mat, Index k0, Eigen::VectorXd& temp, Sign& sign, PivotState& state, Dense& W, Dense& R,
                  HelperThread* helper) {
  const Index n = mat.rows(), bc = block_cols(n), row0 = k0 + 1, rows = n - row0;
  W.resize(kPanel, k0);  // W(t, j) = w_{k0+t}(j) = D(j)·L(k0 + t, j): column j holds the panel's 16 weights
  for (Index t = 0; t < kPanel; ++t)
    W.row(t) = mat.diagonal().head(k0).cwiseProduct(mat.row(k0 + t).head(k0).transpose()).transpose();
  R = mat.block(row0, k0, rows, kPanel);
  split_rows(helper, 0, rows, [&](Index a, Index b) {
    ldlt_panel::bulk(mat.data(), n, row0, k0, bc, W.data(), R.data(), rows, a, b);
  });
  for (Index t = 0; t < kPanel; ++t) {
    const Index k = k0 + t;
    diagonal_update(mat, k, temp);
    double* Rt = R.col(t).data();
    split_rows(helper, t, rows, [&](Index a, Index b) {
      ldlt_panel::column_tail(mat.data(), n, row0, k0, t, bc, temp.data(), Rt, a, b);
      for (Index i = a; i < b; ++i) mat.coeffRef(row0 + i, k) = Rt[i];
    });
    state.after(mat, k, sign);
  }
}

/// The pivot order Eigen's loop will choose (see above), the swaps made on `mat`.
template <typename Transpositions>
void pivot_first(Dense& mat, Transpositions& transpositions) {
  const Index size = mat.rows();
  Eigen::VectorXd diagonal = mat.diagonal();
  for (Index k = 0; k < size; ++k) {
    Index biggest = 0;
    diagonal.tail(size - k).cwiseAbs().maxCoeff(&biggest);
    biggest += k;
    transpositions.coeffRef(k) = static_cast<int>(biggest);
    if (k == biggest) continue;
    std::swap(diagonal(k), diagonal(biggest));
    pivot(mat, k, biggest);
  }
}

/// factor() in panels: columns < 128 and the last two one at a time (Eigen's
/// statements), the rest in panels of 16. Only for a finite diagonal whose
/// largest entry is not zero (else Eigen's loop ends at its first step).
template <typename Transpositions>
bool factor_in_panels(Dense& mat, Transpositions& transpositions, Eigen::VectorXd& temp, Sign& sign,
                      HelperThread* helper) {
  const Index size = mat.rows();
  pivot_first(mat, transpositions);
  PivotState state;
  const auto one_column = [&](Index k) {
    if (k > 0) {
      diagonal_update(mat, k, temp);
      if (size - k - 1 > 0) column_update(mat, k, size - k - 1, temp, helper);
    }
    state.after(mat, k, sign);
  };
  for (Index k = 0; k < kFirstPanel; ++k) one_column(k);
  Dense W, R;
  Index k0 = kFirstPanel;
  for (; k0 + kPanel <= size - 2; k0 += kPanel) factor_panel(mat, k0, temp, sign, state, W, R, helper);
  for (Index k = k0; k < size; ++k) one_column(k);
  return state.ret;
}

/// Whether factor_in_panels applies (large enough to pay; see its conditions).
bool panels_apply(const Dense& a) {
  constexpr Index kMinSize = 256;
  if (a.rows() < kMinSize || !ldlt_panel::panel_kernels_available() || !a.diagonal().allFinite()) return false;
  return a.diagonal().cwiseAbs().maxCoeff() > 0;
}

}  // namespace

double lower_triangle_l1_norm(const Eigen::MatrixXd& a) {
  const Eigen::Index size = a.rows();
  double norm = 0;
  for (Eigen::Index col = 0; col < size; ++col) {
    const double sum = a.col(col).tail(size - col).lpNorm<1>() + a.row(col).head(col).lpNorm<1>();
    if (sum > norm) norm = sum;
  }
  return norm;
}

SplitLdlt& SplitLdlt::compute_split(const Dense& a, HelperThread* helper) {
  const Index size = a.rows();
  m_matrix = a;
  m_l1_norm = lower_triangle_l1_norm(m_matrix);
  m_transpositions.resize(size);
  m_isInitialized = false;
  m_temporary.resize(size);
  m_sign = Eigen::internal::ZeroSign;
  const bool ok = panels_apply(a) ? factor_in_panels(m_matrix, m_transpositions, m_temporary, m_sign, helper)
                                  : factor(m_matrix, m_transpositions, m_temporary, m_sign, helper);
  m_info = ok ? Eigen::Success : Eigen::NumericalIssue;
  m_isInitialized = true;
  return *this;
}

}  // namespace lpvid
