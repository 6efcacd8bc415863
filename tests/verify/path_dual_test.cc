// The compact dual form (verify/certificate/path_dual.h) against its dense expansion:
// for random recipes, the O(L²) exact sums must equal what the dense dual
// point Y1 = J [U', E; Eᵀ, x·I] Jᵀ gives through the dense formulas of
// toeplitz/delta_form_dual.h (dual equality, tr U, β), and whenever the
// compact checks accept (‖E‖_F² ≤ x·γ, U − γ·I ⪰ 0) the dense Y1 must
// be PSD, decided by exact elimination. The known answers are the dense
// formulas themselves, computed independently of the compact sums.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <Eigen/Cholesky>

#include "core/number_text.h"
#include "toeplitz/delta_form_dual.h"
#include "toeplitz/tap_toeplitz.h"
#include "verify/psd/exact_psd.h"
#include "verify/certificate/path_dual.h"
#include "verify/psd/power_of_two.h"

namespace lpvid {
namespace {

struct Case {
  Eigen::Index ny, nz, L, n;
  PathDualRecipe recipe;
  Mat<Rational> g, z, r;
  Rational sigma;
};

Mat<double> random_matrix(Eigen::Index rows, Eigen::Index cols, double scale) {
  Mat<double> m(rows, cols);
  for (Eigen::Index i = 0; i < rows; ++i)
    for (Eigen::Index j = 0; j < cols; ++j) m(i, j) = scale * (*rc::gen::inRange(-1000, 1001)) / 1000.0;
  return m;
}

Mat<Rational> exact(const Mat<double>& m) {
  Mat<Rational> q(m.rows(), m.cols());
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) q(i, j) = exact_rational_of_double(m(i, j));
  return q;
}

Case random_case() {
  Case c;
  c.ny = *rc::gen::inRange(1, 3);
  c.nz = *rc::gen::inRange(1, 3);
  c.L = *rc::gen::inRange(1, 8);
  c.n = c.L + *rc::gen::inRange(0, 3);
  const Mat<double> h = random_matrix(c.L, c.ny * c.nz, 0.5);
  double frob2 = 0;  // ‖T‖_F² = Σ (L − l)‖h_l‖² ≥ ‖T‖²: t above it keeps t·I − TTᵀ ≻ 0
  for (Eigen::Index l = 0; l < c.L; ++l) frob2 += static_cast<double>(c.L - l) * h.row(l).squaredNorm();
  c.recipe.taps = exact(h);
  c.recipe.t = exact_rational_of_double(frob2 * (1.0 + *rc::gen::inRange(1, 100) / 100.0) + 0.01);
  c.recipe.mu = exact_rational_of_double(*rc::gen::inRange(1, 200) / 100.0);
  c.recipe.x = *rc::gen::arbitrary<bool>() ? c.recipe.mu : exact_rational_of_double(*rc::gen::inRange(1, 300) / 100.0);
  c.g = exact(random_matrix(c.n, c.ny, 1.0));
  c.z = exact(random_matrix(c.n, c.nz, 1.0));
  c.r = exact(random_matrix(c.n, c.ny, 1.0));
  c.sigma = exact_rational_of_double(*rc::gen::inRange(1, 500) / 100.0);
  return c;
}


RC_GTEST_PROP(PathDual, CompactSumsEqualTheDenseFormulasOfTheExpandedPoint, ()) {
  Case c = random_case();
  std::string problem;
  const Mat<double> U_d = path_dual_floating_u(c.recipe, c.ny, c.nz, problem);
  RC_ASSERT(problem.empty());
  c.recipe.u_exponent = path_dual_exponent(U_d) + *rc::gen::inRange(0, 30);  // the builder's grid or coarser ones
  const PathDualGrid grid = path_dual_round(U_d, c.recipe.u_exponent);
  RC_ASSERT(grid.problem.empty());
  // The floating recipe against a direct dense computation of μ(t·I − TTᵀ)⁻¹.
  const Mat<double> Td = nearest_double(tap_toeplitz_dense(c.recipe.taps, c.ny, c.nz));
  Mat<double> S = -Td * Td.transpose();
  S.diagonal().array() += nearest_double(c.recipe.t);
  const Mat<double> U_direct = nearest_double(c.recipe.mu) * S.llt().solve(Mat<double>::Identity(S.rows(), S.rows()));
  RC_ASSERT((U_direct - U_d).cwiseAbs().maxCoeff() <= 1e-9 * U_direct.cwiseAbs().maxCoeff());

  const PathDualSums sums = path_dual_sums(c.recipe, grid.U, c.ny, c.nz);
  RC_ASSERT(sums.problem.empty());
  const Mat<Rational> C = fir_adjoint(c.g, c.z, c.L);
  // The floor γ: 0 or a random one; then x: random, or exactly / 1.5× what
  // the E-check needs (x does not enter R or E).
  const int which = *rc::gen::inRange(0, 4);
  c.recipe.floor = which == 0 ? Rational(0) : Rational(*rc::gen::inRange(1, 100000)) / Rational(100000);
  const Rational E_at = path_dual_value(c.recipe, sums, C, c.g, c.sigma, c.r, c.ny, c.nz).E_norm2;
  if (which >= 2 && E_at > 0) c.recipe.x = E_at / c.recipe.floor * (which == 2 ? Rational(1) : Rational(3, 2));
  const PathDualValue v = path_dual_value(c.recipe, sums, C, c.g, c.sigma, c.r, c.ny, c.nz);
  Mat<Rational> R;
  RC_ASSERT(path_dual_residual(c.recipe, sums, C, &R).E_norm2 == v.E_norm2);

  const Mat<Rational> Y1 = path_dual_expand(c.recipe, grid.U, R, c.ny, c.nz);
  // Dual equality, exactly, by the dense formula.
  RC_ASSERT(block_diagonal_sums(Y1, c.L, c.ny, c.nz) == C);
  // tr U, N·σ, β by the dense formula.
  const DualTerms<Rational> dense = dual_terms(Y1, c.g, c.sigma, c.r, c.L);
  RC_ASSERT(dense.trace_U == v.terms.trace_U);
  RC_ASSERT(dense.N_sigma == v.terms.N_sigma);
  RC_ASSERT(dense.beta == v.terms.beta);
  // ‖E‖_F² from the expanded W: E = W + UT.
  const Eigen::Index P = c.L * c.ny, Q = c.L * c.nz;
  const Mat<Rational> E = Y1.topRightCorner(P, Q) + Y1.topLeftCorner(P, P) * tap_toeplitz_dense(c.recipe.taps, c.ny, c.nz);
  Rational e2(0);
  for (Eigen::Index i = 0; i < P; ++i)
    for (Eigen::Index j = 0; j < Q; ++j) e2 += E(i, j) * E(i, j);
  RC_ASSERT(e2 == v.E_norm2);
  // Soundness of the PSD argument: compact accepts ⇒ the dense Y1 is PSD (exact).
  const bool e_ok = v.E_norm2 <= c.recipe.x * c.recipe.floor;
  const PsdResult psd = path_dual_psd(c.recipe, grid.U, true);
  if (e_ok && psd.verdict != PsdVerdict::kNotPsd) {
    PsdOptions exact_only;
    exact_only.use_filter = false;
    RC_ASSERT(decide_psd(Y1, exact_only).verdict != PsdVerdict::kNotPsd);
  }
  RC_TAG(e_ok ? "E absorbed" : "E too large", psd.verdict != PsdVerdict::kNotPsd ? "U - floor PSD" : "U - floor not PSD");
}

// A recipe whose t·I − TTᵀ is indefinite gives no point: the verifier refuses.
TEST(PathDual, IndefiniteRecipeIsRefused) {
  PathDualRecipe r;
  r.taps = Mat<Rational>::Constant(3, 1, Rational(1));
  r.t = Rational(1, 2);  // ‖T‖ ≥ |h_0| = 1 > √t
  r.mu = Rational(1);
  r.x = Rational(1);
  const PathDualGrid g = path_dual_grid(r, 1, 1);
  EXPECT_FALSE(g.problem.empty());
}

// A non-dyadic tap cannot enter the integer sums: refused, not rounded.
TEST(PathDual, NonDyadicTapIsRefused) {
  PathDualRecipe r;
  r.taps = Mat<Rational>::Constant(2, 1, Rational(1, 3));
  r.t = Rational(4);
  r.mu = Rational(1);
  r.x = Rational(1);
  const PathDualGrid g = path_dual_grid(r, 1, 1);
  ASSERT_TRUE(g.problem.empty());
  EXPECT_FALSE(path_dual_sums(r, g.U, 1, 1).problem.empty());
}

}  // namespace
}  // namespace lpvid
