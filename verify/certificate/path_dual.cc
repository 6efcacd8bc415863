#include "verify/certificate/path_dual.h"

#include <gmp.h>

#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Cholesky>

#include "core/helper_thread.h"
#include "core/number_text.h"
#include "dense/llt_inverse.h"
#include "dense/split_llt.h"
#include "toeplitz/tap_toeplitz.h"
#include "core/gmp_raii.h"
#include "core/integer_form.h"
#include "verify/psd/power_of_two.h"
#include "verify/psd/psd_filter.h"
#include "verify/certificate/verdict_text.h"

namespace lpvid {
namespace {


/// z·2^k as a rational.
Rational scaled(mpz_srcptr z, long k) { return mpz_to_rational(z) * power_of_two(k); }

/// The taps as H·2^f with H integer, f = −(largest binary exponent of a
/// denominator), into H column by column: Hcol[j][k·ny + i'] = H(k, i'·nz + j).
/// Returns f; sets `problem` when a tap is not dyadic.
long dyadic_tap_columns(const Mat<Rational>& taps, Eigen::Index ny, Eigen::Index nz, MpzArray& H, std::string& problem) {
  const Eigen::Index L = taps.rows();
  const std::size_t Pu = static_cast<std::size_t>(L * ny);
  long max_den_bits = 0;
  for (Eigen::Index l = 0; l < L; ++l)
    for (Eigen::Index c = 0; c < ny * nz; ++c) {
      mpz_srcptr den = mpq_denref(taps(l, c).mpq());
      if (mpz_popcount(den) != 1) {
        problem = "tap " + std::to_string(l) + " entry " + std::to_string(c) + " is not a dyadic rational";
        return 0;
      }
      max_den_bits = std::max(max_den_bits, static_cast<long>(mpz_sizeinbase(den, 2)) - 1);
    }
  for (Eigen::Index k = 0; k < L; ++k)
    for (Eigen::Index i = 0; i < ny; ++i)
      for (Eigen::Index j = 0; j < nz; ++j) {
        mpq_srcptr h = taps(k, i * nz + j).mpq();
        const long bits = static_cast<long>(mpz_sizeinbase(mpq_denref(h), 2)) - 1;
        mpz_mul_2exp(H[static_cast<std::size_t>(j) * Pu + static_cast<std::size_t>(k * ny + i)], mpq_numref(h),
                     static_cast<mp_bitcnt_t>(max_den_bits - bits));
      }
  return -max_den_bits;
}

/// NOT_PSD of U − γ·I from its diagonal entry i < 0 (witness eᵢ), exactly.
PsdResult negative_diagonal(Eigen::Index i, Eigen::Index P, const Rational& floor) {
  PsdResult out;
  out.verdict = PsdVerdict::kNotPsd;
  out.pivot_index = static_cast<long>(i);
  out.witness = Vec<Rational>::Zero(P);
  out.witness(i) = Rational(1);
  out.reason = "diagonal entry " + std::to_string(i) + " of U is below u_floor = " + approx_text(floor, 8) +
               " (exact comparison)";
  return out;
}


}  // namespace

Mat<double> path_dual_floating_u(const PathDualRecipe& recipe, Eigen::Index ny, Eigen::Index nz, std::string& problem) {
  const Eigen::Index L = recipe.taps.rows(), P = L * ny;
  if (recipe.taps.cols() != ny * nz || L == 0) {
    problem = "the taps have the wrong shape";
    return {};
  }
  const Mat<double> h = nearest_double(recipe.taps);
  const double t = nearest_double(recipe.t), mu = nearest_double(recipe.mu);
  if (!h.allFinite() || !std::isfinite(t) || !(mu > 0) || !std::isfinite(mu)) {
    problem = "the recipe's taps, t or mu are not finite positive doubles";
    return {};
  }
  // S = t·I − T Tᵀ, T Tᵀ by the block recursion of toeplitz/tap_toeplitz.h.
  Mat<double> S = tap_gram(h, ny, nz);
  S = -S;
  S.diagonal().array() += t;
  // U = μ·L⁻ᵀL⁻¹ from the Cholesky factor (dense/llt_inverse.h: a third of the
  // work of two triangular solves on I, in wide vectors, shared with a helper
  // thread where the machine has two cores; the same bits either way)
  const std::unique_ptr<HelperThread> helper = helper_for_order(static_cast<long>(P));
  SplitLlt llt;
  llt.compute_split(S, helper.get());
  S = Mat<double>();
  if (llt.info() != Eigen::Success) {
    problem = "t*I - T*T^T is not positive definite in floating point (the recipe gives no U)";
    return {};
  }
  Mat<double> U, scratch;
  llt_inverse(llt, U, scratch, helper.get());
  U *= mu;
  return U;
}

long path_dual_exponent(const Mat<double>& U_d) {
  const double m = U_d.size() ? U_d.cwiseAbs().maxCoeff() : 0.0;
  if (!(m > 0) || !std::isfinite(m)) return 0;
  return static_cast<long>(std::ilogb(m)) - 51;
}

PathDualGrid path_dual_round(const Mat<double>& U_d, long u_exponent) {
  PathDualGrid out;
  const Eigen::Index P = U_d.rows();
  out.U.resize(P, P);
  const double limit = 0x1.0p53;
  for (Eigen::Index i = 0; i < P; ++i)
    for (Eigen::Index j = i; j < P; ++j) {
      const double v = std::nearbyint(std::ldexp(U_d(i, j), static_cast<int>(-u_exponent)));
      if (!std::isfinite(v) || std::fabs(v) >= limit) {
        out.problem = "U = mu*(t*I - T*T^T)^-1 does not fit the grid 2^" + std::to_string(u_exponent) +
                      " (an entry reaches 2^53 grid units)";
        out.U.resize(0, 0);
        return out;
      }
      out.U(i, j) = v;
      out.U(j, i) = v;
    }
  return out;
}

PathDualGrid path_dual_grid(const PathDualRecipe& recipe, Eigen::Index ny, Eigen::Index nz) {
  PathDualGrid out;
  const Mat<double> U_d = path_dual_floating_u(recipe, ny, nz, out.problem);
  if (!out.problem.empty()) return out;
  return path_dual_round(U_d, recipe.u_exponent);
}

PathDualSums path_dual_sums(const PathDualRecipe& recipe, const Mat<double>& U_grid, Eigen::Index ny, Eigen::Index nz) {
  PathDualSums out;
  const Eigen::Index L = recipe.taps.rows(), P = L * ny, q = ny * nz;
  const std::size_t Pu = static_cast<std::size_t>(P), Nz = static_cast<std::size_t>(nz);
  MpzArray H(Pu * Nz);
  const long f = dyadic_tap_columns(recipe.taps, ny, nz, H, out.problem);
  if (!out.problem.empty()) return out;
  // D(p, p2) = Ũ(p, p2) + D(p + ny, p2 + ny): partial block-diagonal sums,
  // row p from row p + ny, so ny rows are kept (row p replaces row p + ny
  // in slot p mod ny; ascending p2 reads p2 + ny before it is overwritten).
  const std::size_t s = static_cast<std::size_t>(ny);
  MpzArray D(s * Pu);
  // M(p, j) = Σ_p2 D(p, p2)·Hcol_j(p2): Ω_l(UT)(i, j) = M(l·ny + i, j)·2^(e+f),
  // tr(TᵀUT) = Σ_{p, j} Hcol_j(p)·M(p, j)·2^(e+2f).
  out.omega_UT = Mat<Rational>(L, q);
  Mpz acc, tr;
  for (std::size_t p = Pu; p-- > 0;) {
    const std::size_t base = (p % s) * Pu;
    for (std::size_t p2 = 0; p2 < Pu; ++p2) {
      mpz_ptr d = D[base + p2];
      mpz_set_d(d, U_grid(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(p2)));
      if (p + s < Pu && p2 + s < Pu) mpz_add(d, d, D[base + p2 + s]);  // D(p + ny, p2 + ny), not yet overwritten
    }
    for (std::size_t j = 0; j < Nz; ++j) {
      mpz_set_ui(acc.z, 0);
      for (std::size_t p2 = 0; p2 < Pu; ++p2) mpz_addmul(acc.z, D[base + p2], H[j * Pu + p2]);
      const Eigen::Index l = static_cast<Eigen::Index>(p) / ny, i = static_cast<Eigen::Index>(p) % ny;
      out.omega_UT(l, i * nz + static_cast<Eigen::Index>(j)) = scaled(acc.z, recipe.u_exponent + f);
      mpz_addmul(tr.z, H[j * Pu + p], acc.z);
    }
  }
  out.tr_TUT = scaled(tr.z, recipe.u_exponent + 2 * f);
  Mpz diag;
  for (std::size_t p = 0; p < Pu; ++p) {
    Mpz v;
    mpz_set_d(v.z, U_grid(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(p)));
    mpz_add(diag.z, diag.z, v.z);
  }
  out.tr_U = scaled(diag.z, recipe.u_exponent);
  return out;
}

namespace {

/// path_dual_residual rational by rational (when an integer form is refused).
PathDualResidual rational_residual(const PathDualRecipe& recipe, const PathDualSums& sums, const Mat<Rational>& C,
                                   Mat<Rational>* R_out) {
  const Eigen::Index L = recipe.taps.rows(), q = C.cols();
  PathDualResidual out{Rational(0), Rational(0)};
  for (Eigen::Index l = 0; l < L; ++l) {
    Rational row(0);
    for (Eigen::Index c = 0; c < q; ++c) {
      const Rational R = C(l, c) + sums.omega_UT(l, c);
      row += R * R;
      out.h_dot_R += recipe.taps(l, c) * R;
      if (R_out) (*R_out)(l, c) = R;
    }
    out.E_norm2 += row / Rational(static_cast<long>(L - l));
  }
  return out;
}

}  // namespace

PathDualResidual path_dual_residual(const PathDualRecipe& recipe, const PathDualSums& sums, const Mat<Rational>& C,
                                    Mat<Rational>* R_out) {
  const Eigen::Index L = recipe.taps.rows(), q = C.cols();
  if (R_out) *R_out = Mat<Rational>(L, q);
  const std::unique_ptr<IntegerForm> ci = integer_form(C), wi = integer_form(sums.omega_UT), hi = integer_form(recipe.taps);
  if (!ci || !wi || !hi) return rational_residual(recipe, sums, C, R_out);
  // R = (C̃·ω.den + ω̃·C.den)/den, den = C.den·ω.den; Σ_l row_l/(L − l) over M = lcm(1, …, L).
  Mpz den, M, Rn, t, row, e_num, hr, share;
  mpz_mul(den.z, ci->den.z, wi->den.z);
  mpz_set_ui(M.z, 1);
  for (Eigen::Index l = 1; l <= L; ++l) mpz_lcm_ui(M.z, M.z, static_cast<unsigned long>(l));
  Mpq value;
  for (Eigen::Index l = 0; l < L; ++l) {
    mpz_set_ui(row.z, 0);
    for (Eigen::Index c = 0; c < q; ++c) {
      mpz_mul(Rn.z, ci->at(l, c), wi->den.z);
      mpz_mul(t.z, wi->at(l, c), ci->den.z);
      mpz_add(Rn.z, Rn.z, t.z);
      mpz_addmul(row.z, Rn.z, Rn.z);
      mpz_addmul(hr.z, hi->at(l, c), Rn.z);
      if (R_out) {
        mpz_set(mpq_numref(value.q), Rn.z);
        mpz_set(mpq_denref(value.q), den.z);
        mpq_canonicalize(value.q);
        (*R_out)(l, c) = Rational(value.q);
      }
    }
    mpz_divexact_ui(share.z, M.z, static_cast<unsigned long>(L - l));
    mpz_addmul(e_num.z, row.z, share.z);
  }
  PathDualResidual out;
  mpz_set(mpq_numref(value.q), e_num.z);
  mpz_mul(mpq_denref(value.q), den.z, den.z);
  mpz_mul(mpq_denref(value.q), mpq_denref(value.q), M.z);
  mpq_canonicalize(value.q);
  out.E_norm2 = Rational(value.q);
  mpz_set(mpq_numref(value.q), hr.z);
  mpz_mul(mpq_denref(value.q), den.z, hi->den.z);
  mpq_canonicalize(value.q);
  out.h_dot_R = Rational(value.q);
  return out;
}

GProducts g_products(const Mat<Rational>& g, const Mat<Rational>& r) { return {exact_dot(g, g), exact_dot(g, r)}; }

DualTerms<Rational> path_dual_terms(const PathDualRecipe& recipe, const PathDualSums& sums, const PathDualResidual& res,
                                    const GProducts& gp, const Rational& sigma, Eigen::Index N, Eigen::Index nz) {
  DualTerms<Rational> terms;
  const Rational Q(static_cast<long>(recipe.taps.rows() * nz));
  terms.trace_U = sums.tr_U;
  const Rational trV = sums.tr_TUT - Rational(2) * res.h_dot_R + recipe.x * Q;
  terms.N_sigma = Rational(static_cast<long>(N)) * sigma;
  terms.beta = -(trV + gp.gg / sigma + Rational(2) * gp.gr);
  return terms;
}

PathDualValue path_dual_value(const PathDualRecipe& recipe, const PathDualSums& sums, const Mat<Rational>& C,
                              const Mat<Rational>& g, const Rational& sigma, const Mat<Rational>& r, Eigen::Index ny,
                              Eigen::Index nz) {
  PathDualValue out;
  const PathDualResidual res = path_dual_residual(recipe, sums, C);
  out.E_norm2 = res.E_norm2;
  out.terms = path_dual_terms(recipe, sums, res, g_products(g, r), sigma, g.rows() * ny, nz);
  return out;
}

PsdResult path_dual_psd(const PathDualRecipe& recipe, const Mat<double>& U_grid, bool exact_fallback) {
  const Eigen::Index P = U_grid.rows();
  // A = Ũ − γ·2^−e·I with the diagonal rounded down: A ⪰ 0 implies the exact matrix is.
  // A diagonal entry below the floor decides at once (eᵢᵀ(U − γ·I)eᵢ < 0);
  // the others lie in [0, Ũᵢᵢ] ⊂ [0, 2^53), so their doubles are finite.
  // A is formed straight into the filter's buffer (upper triangle, row-major):
  // no copy of Ũ, whose entries are exact doubles (radius 0).
  const Rational floor_units = recipe.floor * power_of_two(-recipe.u_exponent);
  const std::size_t n = static_cast<std::size_t>(P);
  std::vector<double> A(n * n, 0.0);
  PsdResult out;
  for (Eigen::Index i = 0; i < P; ++i) {
    const Rational exact = Rational(U_grid(i, i)) - floor_units;
    if (exact < 0) return negative_diagonal(i, P, recipe.floor);
    double d = nearest_double(exact);
    if (Rational(d) > exact) d = std::nextafter(d, -INFINITY);
    const std::size_t row = static_cast<std::size_t>(i) * n;
    A[row + static_cast<std::size_t>(i)] = d;
    for (Eigen::Index j = i + 1; j < P; ++j) A[row + static_cast<std::size_t>(j)] = U_grid(i, j);
  }
  const PsdFilterResult f = run_psd_filter_within_radius(std::move(A), n, Rational(0));
  if (f.proved_pd) {
    out.verdict = PsdVerdict::kPositiveDefinite;
    out.reason = f.reason;
    out.decided_by_filter = true;
    out.method = PsdMethod::kFloatingFilter;
    return out;
  }
  if (!exact_fallback) {
    out.verdict = PsdVerdict::kNotPsd;
    out.reason = "not proved by the floating filter (" + f.reason + "); exact elimination not run";
    return out;
  }
  const Rational unit = power_of_two(recipe.u_exponent);
  Mat<Rational> M(P, P);
  for (Eigen::Index i = 0; i < P; ++i)
    for (Eigen::Index j = i; j < P; ++j) {
      M(i, j) = Rational(U_grid(i, j)) * unit;
      if (i == j) M(i, i) -= recipe.floor;
      M(j, i) = M(i, j);
    }
  return decide_psd(M);
}

Mat<Rational> path_dual_expand(const PathDualRecipe& recipe, const Mat<double>& U_grid, const Mat<Rational>& R,
                               Eigen::Index ny, Eigen::Index nz) {
  const Eigen::Index L = recipe.taps.rows(), P = L * ny, Q = L * nz;
  const Rational unit = power_of_two(recipe.u_exponent);
  Mat<Rational> U(P, P);
  for (Eigen::Index i = 0; i < P; ++i)
    for (Eigen::Index j = 0; j < P; ++j) U(i, j) = Rational(U_grid(i, j)) * unit;
  Mat<Rational> E = Mat<Rational>::Zero(P, Q);
  for (Eigen::Index l = 0; l < L; ++l)
    for (Eigen::Index b = 0; b + l < L; ++b)
      for (Eigen::Index i = 0; i < ny; ++i)
        for (Eigen::Index j = 0; j < nz; ++j)
          E((b + l) * ny + i, b * nz + j) = R(l, i * nz + j) / Rational(static_cast<long>(L - l));
  const Mat<Rational> T = tap_toeplitz_dense(recipe.taps, ny, nz);
  const Mat<Rational> UT = U * T;
  Mat<Rational> Y1(P + Q, P + Q);
  Y1.topLeftCorner(P, P) = U;
  Y1.topRightCorner(P, Q) = E - UT;
  Y1.bottomLeftCorner(Q, P) = (E - UT).transpose();
  Mat<Rational> V = T.transpose() * UT - T.transpose() * E - E.transpose() * T;
  for (Eigen::Index i = 0; i < Q; ++i) V(i, i) += recipe.x;
  Y1.bottomRightCorner(Q, Q) = V;
  return Y1;
}

}  // namespace lpvid
