#include "lmi/relaxed_bmi_lmi.h"

#include <algorithm>
#include <cmath>

#include "lmi/noise_block.h"
#include "core/deadline.h"
#include "core/rms.h"
#include "core/input_error.h"
#include "lmi/delta_form_lmi.h"
#include "toeplitz/toeplitz_gram.h"

namespace lpvid {
namespace {

struct Layout {
  LmiProgram program;
  Eigen::Index n = 0, ny = 0, nz = 0, m = 0, L = 0;
  int q0 = 0, w0 = 0, t = -1, s = -1;
  double sigma_z = 1, sigma_r = 1;
  std::vector<double> qscale;  ///< q_j = q'_j / qscale_j
};

/// Upper triangle of a dense symmetric L × L matrix into block b, variable v.
void add_dense_upper(LmiProgram& p, int b, int v, const Mat<double>& M) {
  for (Eigen::Index j = 0; j < M.cols(); ++j)
    for (Eigen::Index i = 0; i <= j; ++i)
      if (M(i, j) != 0.0) p.add_entry(b, v, static_cast<int>(i), static_cast<int>(j), M(i, j));
}

/// Horizon and scales: drop the leading samples where z̄ = 0 (signal mode),
/// or the trailing zero columns of T_z (paper mode): both force w_k = 0 for
/// k < m. σ_z from z̄ (or T_z's first column), σ_r from r̄; each unknown
/// scaled so that a unit step moves z and r by about their RMS.
void set_horizon_and_scales(Layout& f, const AffineSignals& sig, const Mat<double>& zbar, bool paper) {
  if (paper) {
    Eigen::Index m = 0;
    while (m < f.n && sig.Tz_paper.col(f.n - 1 - m).isZero(0.0)) ++m;
    f.m = m;
  } else {
    f.m = leading_zero_samples(zbar);
  }
  f.L = f.n - f.m;
  if (f.L == 0 || f.nz == 0)
    throw InputError(
        "ill-posed data: the uncertainty channel z is identically zero along the experiment (for example u = 0 "
        "with x0 = 0), so the data says nothing about the uncertainty and delta is undetermined");
  for (const auto& Zj : sig.Z)
    if (!Zj.topRows(f.m).isZero(0.0))
      throw std::invalid_argument("relaxed program: an unknown moves z at a sample the relaxation pins to zero");
  f.sigma_z = paper ? std::sqrt(sig.Tz_paper.col(0).squaredNorm() / static_cast<double>(f.n * f.nz))
                    : rms(zbar.bottomRows(f.L));
  if (!(f.sigma_z > 0.0)) f.sigma_z = 1.0;
  f.sigma_r = rms(sig.rb);
  if (!(f.sigma_r > 0.0)) f.sigma_r = 1.0;
  f.qscale.assign(static_cast<size_t>(sig.nq()), 1.0);
  for (Eigen::Index j = 0; j < sig.nq(); ++j) {
    const double a = rms(sig.Z[static_cast<size_t>(j)]) / f.sigma_z, b = rms(sig.R[static_cast<size_t>(j)]) / f.sigma_r;
    const double c = std::max(a, b);
    f.qscale[static_cast<size_t>(j)] = c > 0.0 ? c : 1.0;
  }
}

/// (C1): [Lin(q), T_wᵀ; T_w, t I], size L + L·ny; Lin(q) the linearisation of
/// T_z(q)ᵀT_z(q) at q̄ (T_zᵀT_z itself in paper mode, where q is empty).
void add_c1_block(Layout& f, const AffineSignals& sig, const Mat<double>& zbar, bool paper, const BoundObjective& obj) {
  LmiProgram& p = f.program;
  const int A = p.add_block("C1_relaxed", static_cast<int>(f.L * (1 + f.ny)));
  if (paper) {
    const Mat<double> Tz = sig.Tz_paper / f.sigma_z;
    const Mat<double> G = (Tz.transpose() * Tz).topLeftCorner(f.L, f.L);
    add_dense_upper(p, A, -1, G);
  } else {
    const Mat<double> zb = Mat<double>(sig.zb.bottomRows(f.L)) / f.sigma_z;
    const Mat<double> zs = Mat<double>(zbar.bottomRows(f.L)) / f.sigma_z;
    const Mat<double> Gss = toeplitz_gram(zs, zs);
    const Mat<double> Gsb = toeplitz_gram(zs, zb);
    add_dense_upper(p, A, -1, Mat<double>(Gsb + Gsb.transpose() - Gss));
    for (Eigen::Index j = 0; j < sig.nq(); ++j) {
      const Mat<double> Zj =
          Mat<double>(sig.Z[static_cast<size_t>(j)].bottomRows(f.L)) / (f.sigma_z * f.qscale[static_cast<size_t>(j)]);
      const Mat<double> Gj = toeplitz_gram(zs, Zj);
      add_dense_upper(p, A, static_cast<int>(f.q0 + j), Mat<double>(Gj + Gj.transpose()));
    }
  }
  const double kz = f.sigma_z / f.sigma_r;
  const double t_fixed = obj.delta.approx * obj.delta.approx * kz * kz;
  for (Eigen::Index a = 0; a < f.L; ++a) {
    check_deadline("the relaxed program was built");  // O(L^2) entries: a stop request is seen once per row
    for (Eigen::Index i = 0; i < f.ny; ++i) {
      const int row = static_cast<int>(f.L + a * f.ny + i);
      if (f.t >= 0)
        p.add_entry(A, f.t, row, row, 1.0);
      else
        p.add_entry(A, -1, row, row, t_fixed);
      for (Eigen::Index b = 0; b <= a; ++b)
        p.add_entry(A, static_cast<int>(f.w0 + (a - b) * f.ny + i), static_cast<int>(b), row, 1.0);
    }
  }
}

Layout build(const AffineSignals& sig, const Vec<double>& q_bar, const BoundObjective& obj) {
  obj.validate();
  Layout f;
  f.n = sig.n();
  f.nz = sig.zb.cols();
  f.ny = sig.rb.cols();
  const bool paper = sig.Tz_paper.size() > 0;
  if (paper && sig.nq() > 0) throw std::invalid_argument("relaxed program: paper mode needs a fixed model");
  if (q_bar.size() != sig.nq()) throw std::invalid_argument("relaxed program: q_bar has the wrong size");
  const Mat<double> zbar = sig.z_at(q_bar);
  set_horizon_and_scales(f, sig, zbar, paper);

  LmiProgram& p = f.program;
  f.q0 = sig.nq() ? p.add_variables(static_cast<int>(sig.nq())) : 0;
  f.w0 = p.add_variables(static_cast<int>(f.L * f.ny));
  if (!obj.delta_fixed())
    f.t = p.add_variable("delta2", obj.kind == BoundObjective::Kind::kWeighted ? obj.lambda / (f.sigma_z * f.sigma_z) : 1.0);
  if (!obj.dmax_fixed())
    f.s = p.add_variable("dmax2", obj.kind == BoundObjective::Kind::kWeighted ? 1.0 - obj.lambda : 1.0);
  add_c1_block(f, sig, zbar, paper, obj);

  // (C2): [N s, dᵀ; d, I], d = rb − R q − w.
  const int B = add_noise_block(p, f.s, obj.dmax.approx * obj.dmax.approx / (f.sigma_r * f.sigma_r), Mat<double>(sig.rb / f.sigma_r));
  for (Eigen::Index k = 0; k < f.n; ++k)
    for (Eigen::Index i = 0; i < f.ny; ++i) {
      const int row = static_cast<int>(1 + k * f.ny + i);
      for (Eigen::Index j = 0; j < sig.nq(); ++j) {
        const double v = sig.R[static_cast<size_t>(j)](k, i) / (f.sigma_r * f.qscale[static_cast<size_t>(j)]);
        if (v != 0.0) p.add_entry(B, static_cast<int>(f.q0 + j), 0, row, -v);
      }
      if (k >= f.m) p.add_entry(B, static_cast<int>(f.w0 + (k - f.m) * f.ny + i), 0, row, -1.0);
    }
  return f;
}

}  // namespace

Mat<double> AffineSignals::z_at(const Vec<double>& q) const {
  Mat<double> z = zb;
  for (Eigen::Index j = 0; j < nq(); ++j) z += q(j) * Z[static_cast<size_t>(j)];
  return z;
}

Mat<double> AffineSignals::r_at(const Vec<double>& q) const {
  Mat<double> r = rb;
  for (Eigen::Index j = 0; j < nq(); ++j) r -= q(j) * R[static_cast<size_t>(j)];
  return r;
}

RelaxedSolution solve_relaxed(const AffineSignals& sig, const Vec<double>& q_bar, const BoundObjective& objective,
                              SdpSolver& solver, const SolverOptions& options) {
  Layout f = build(sig, q_bar, objective);
  RelaxedSolution out;
  out.solve = solver.solve(f.program, options);
  out.leading_zeros = f.m;
  out.q = Vec<double>::Zero(sig.nq());
  out.w = Mat<double>::Zero(f.n, f.ny);
  const double kz = f.sigma_z / f.sigma_r;
  const bool ok = has_solution(out.solve.status);
  if (ok) {
    const auto& x = out.solve.x;
    for (Eigen::Index j = 0; j < sig.nq(); ++j)
      out.q(j) = x[static_cast<size_t>(f.q0 + j)] / f.qscale[static_cast<size_t>(j)];
    for (Eigen::Index k = f.m; k < f.n; ++k)
      for (Eigen::Index i = 0; i < f.ny; ++i)
        out.w(k, i) = x[static_cast<size_t>(f.w0 + (k - f.m) * f.ny + i)] * f.sigma_r;
  }
  // δ² and d_max² are ≥ 0 on the feasible set: a negative value is the
  // solver's tolerance on t' magnified by 1/kz² (large when σ_z ≪ σ_r, e.g.
  // when the iteration shrinks z), so it is read as 0.
  out.delta2 = f.t >= 0 && ok ? std::max(0.0, out.solve.x[static_cast<size_t>(f.t)] / (kz * kz))
                              : objective.delta.approx * objective.delta.approx;
  out.dmax2 = f.s >= 0 && ok ? std::max(0.0, out.solve.x[static_cast<size_t>(f.s)] * f.sigma_r * f.sigma_r)
                             : objective.dmax.approx * objective.dmax.approx;
  return out;
}

}  // namespace lpvid
