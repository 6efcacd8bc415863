/// (C1) of Theorem 2.1 for form "w" (verify/certificate/c1_check.h).
///
/// EQUIVALENCE USED. Let G = T_zᵀT_z (n × n), T_w (n·ny × n), δ² ≥ 0 and
///   M = [G, T_wᵀ; T_w, δ²I]   ((C1) of Theorem 2.1 with G11 = 0, docs/design.md §7.1).
///  (a) T_w = 0: M = diag(G, δ²I) ⪰ 0, because G is a Gram matrix and δ² ≥ 0.
///      T_w = 0 ⇔ w = 0 (column 0 of T_w is the stacked w, eq. 3).
///  (b) δ² = 0, T_w ≠ 0: M is not PSD. With T_w's entry b ≠ 0 in row r,
///      column c, the 2×2 principal submatrix of M on rows c and n + r is
///      [G_cc, b; b, 0], determinant −b² < 0; a principal submatrix of a PSD
///      matrix is PSD.
///  (c) δ² > 0: with P = [I, −T_wᵀ/δ²; 0, I] (nonsingular),
///        P M Pᵀ = diag(G − T_wᵀT_w/δ², δ²I),
///      so by Sylvester's law of inertia and δ²I ≻ 0 (Schur complement):
///        M ⪰ 0  ⇔  G − T_wᵀT_w/δ² ⪰ 0  ⇔  δ²·G − T_wᵀT_w ⪰ 0  (times δ² > 0).
///      That matrix is n × n instead of (n + n·ny)², and T_wᵀT_w is a
///      Toeplitz Gram matrix (toeplitz/toeplitz_gram.h, O(n²·ny)).
/// The matrix decided is then multiplied by a power of two 2^−e, e the
/// binary magnitude of its largest entry, when |e| > 256 (a positive
/// multiple: same verdict), so that a δ² far outside the double range
/// (1e4000, 1e−5000) leaves the floating filter a matrix it can read.

#include <algorithm>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "toeplitz/toeplitz_gram.h"
#include "verify/certificate/c1_check.h"
#include "verify/psd/exact_psd.h"
#include "verify/psd/power_of_two.h"
#include "verify/certificate/verdict_text.h"

namespace lpvid {
namespace {

/// Largest binary magnitude of the entries of the symmetric R (empty if R = 0).
std::optional<long> largest_magnitude(const Mat<Rational>& R) {
  std::optional<long> e;
  for (Eigen::Index j = 0; j < R.cols(); ++j)
    for (Eigen::Index i = 0; i <= j; ++i)
      if (const auto m = binary_magnitude(R(i, j))) e = e ? std::max(*e, *m) : *m;
  return e;
}

constexpr long kBalanceBits = 256;

}  // namespace

namespace {
/// Throws unless `gram_z` is n × n for the n samples of w.
void require_gram_size(const Mat<Rational>& gram_z, const Mat<Rational>& w) {
  const Eigen::Index n = gram_z.rows();
  if (gram_z.cols() != n || w.rows() != n)
    throw std::invalid_argument("check_c1_w_form: T_z'T_z is " + std::to_string(n) + "x" + std::to_string(gram_z.cols()) +
                                " but w has " + std::to_string(w.rows()) + " samples");
}
}  // namespace

C1Outcome check_c1_w_form(Mat<Rational> gram_z, const Mat<Rational>& w, const Rational& delta2) {
  require_gram_size(gram_z, w);
  return check_c1_w_form([&gram_z] { return std::move(gram_z); }, w, delta2);
}

C1Outcome check_c1_w_form(const std::function<Mat<Rational>()>& make_gram, const Mat<Rational>& w, const Rational& delta2) {
  const std::string full = "[T_z'T_z, T_w'; T_w, delta2*I]";
  const Eigen::Index n = w.rows(), ny = w.cols();
  // (a) T_w = 0.
  Eigen::Index first_k = -1, first_i = -1;
  for (Eigen::Index k = 0; k < w.rows() && first_k < 0; ++k)
    for (Eigen::Index i = 0; i < ny; ++i)
      if (!CGAL::is_zero(w(k, i))) {
        first_k = k;
        first_i = i;
        break;
      }
  if (first_k < 0)
    return C1Outcome::holding("(C1) holds: w = 0, so " + full + " = diag(T_z'T_z, delta2*I) is PSD (a Gram matrix and delta2 >= 0)");
  // (b) δ² = 0 with T_w ≠ 0.
  if (CGAL::is_zero(delta2)) {
    const Eigen::Index row = n + first_k * ny + first_i;
    return C1Outcome::failing("(C1) fails: delta2 = 0 but w(" + std::to_string(first_k) + "," + std::to_string(first_i) + ") = " +
                       approx_text(w(first_k, first_i)) + " is not zero: the 2x2 principal submatrix of " + full +
                       " on rows 0 and " + std::to_string(row) + " is [T_z'T_z(0,0), w; w, 0], determinant -w^2 < 0");
  }
  // (c) δ² > 0: the Schur complement of δ²I, times δ².
  Mat<Rational> gram_z = make_gram();
  require_gram_size(gram_z, w);
  gram_z *= delta2;
  gram_z -= toeplitz_gram(w, w);
  std::string which = "delta2*T_z'T_z - T_w'T_w (the Schur complement of delta2*I in " + full + ", times delta2)";
  if (const auto e = largest_magnitude(gram_z); e && (*e > kBalanceBits || *e < -kBalanceBits)) {
    gram_z *= power_of_two(-*e);
    which += " (scaled by 2^" + std::to_string(-*e) + ")";
  }
  const PsdResult psd = decide_psd(gram_z);
  if (psd.verdict == PsdVerdict::kNotPsd) return C1Outcome::failing("(C1) fails: " + which + " is not PSD (" + psd.reason + ")");
  return C1Outcome::holding("(C1) holds: " + which + " (size " + std::to_string(gram_z.rows()) + ") is " + psd_note(psd));
}

}  // namespace lpvid
