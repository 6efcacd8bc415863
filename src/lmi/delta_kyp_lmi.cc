#include "lmi/delta_kyp_lmi.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/rms.h"
#include "lmi/delta_form_lmi.h"

namespace lpvid {
namespace {

struct KypLayout {
  LmiProgram program;
  Eigen::Index K = 0, ny = 0, nz = 0;
  int tap0 = -1;  ///< h_l(i, j) is tap0 + l·ny·nz + i·nz + j
  int t = -1, s = -1;
  int g0 = -1;            ///< first extra coefficient g'_j (scaled: g_j = g'_j·σ_r / e_j)
  Vec<double> e_scale;    ///< RMS of each extra column (1 for a zero column)
  double sigma_z = 1.0, sigma_r = 1.0;
};

/// (KYP) as one LMI block, in ξ order: rows 0 … K·nz−1 are z_k, z_{k−1}, …;
/// then ny rows of w; P (state x = ξ rows nz … S−1) enters with + P at the
/// x_k rows and − P at the x_{k+1} rows (ξ rows 0 … S−nz−1).
void add_kyp_block(KypLayout& f, const BoundObjective& obj, double kz) {
  LmiProgram& p = f.program;
  const Eigen::Index q = f.ny * f.nz;
  const int S = static_cast<int>(f.K * f.nz), W = static_cast<int>(f.ny);
  const int A = p.add_block("kyp_bounded_real", S + W);
  const int nzi = static_cast<int>(f.nz);
  for (int i = 0; i < nzi; ++i) {
    if (f.t >= 0)
      p.add_entry(A, f.t, i, i, 1.0);
    else
      p.add_entry(A, -1, i, i, obj.delta.approx * obj.delta.approx * kz * kz);
  }
  for (int i = 0; i < W; ++i) p.add_entry(A, -1, S + i, S + i, 1.0);
  for (Eigen::Index l = 0; l < f.K; ++l)
    for (Eigen::Index i = 0; i < f.ny; ++i)
      for (Eigen::Index j = 0; j < f.nz; ++j)
        p.add_entry(A, static_cast<int>(f.tap0 + l * q + i * f.nz + j), static_cast<int>(l * f.nz + j),
                    S + static_cast<int>(i), 1.0);
  const int s_dim = S - nzi;
  for (int a = 0; a < s_dim; ++a)
    for (int b = a; b < s_dim; ++b) {
      const int v = p.add_variable();
      p.add_entry(A, v, a + nzi, b + nzi, 1.0);
      p.add_entry(A, v, a, b, -1.0);
    }
}

/// (C2) through a thin QR of [Z E r] (scaled): ‖r − Z h − E g‖ = ‖c − R [h; g]‖,
/// so the block has min(n·ny, unknowns + 1) + 1 rows instead of n·ny + 1.
void add_noise_qr_block(KypLayout& f, const BoundObjective& obj, const Mat<double>& zs, const Mat<double>& rs,
                        const Mat<double>& E) {
  LmiProgram& p = f.program;
  const Eigen::Index n = zs.rows(), q = f.ny * f.nz, nt = f.K * q;
  const Eigen::Index rows = n * f.ny, m = E.cols(), nv = nt + m;
  if (m > 0 && E.rows() != rows) throw std::invalid_argument("delta form (KYP): extra regressors have the wrong length");
  if (m > 0) f.g0 = p.add_variables(static_cast<int>(m));
  f.e_scale = Vec<double>::Ones(m);
  Mat<double> G = Mat<double>::Zero(rows, nv + 1);
  for (Eigen::Index j = 0; j < m; ++j) {
    const double e = E.col(j).norm() / std::sqrt(static_cast<double>(rows));
    if (e > 0.0) f.e_scale(j) = e;
    G.col(nt + j) = E.col(j) / f.e_scale(j);
  }
  for (Eigen::Index k = 0; k < n; ++k)
    for (Eigen::Index i = 0; i < f.ny; ++i) {
      G(k * f.ny + i, nv) = rs(k, i);
      for (Eigen::Index l = 0; l <= std::min(k, f.K - 1); ++l)
        for (Eigen::Index j = 0; j < f.nz; ++j) G(k * f.ny + i, l * q + i * f.nz + j) = zs(k - l, j);
    }
  Eigen::HouseholderQR<Mat<double>> qr(G);
  const Eigen::Index rr = std::min(rows, nv + 1);
  const Mat<double> R = qr.matrixQR().topRows(rr).triangularView<Eigen::Upper>();
  const double N = static_cast<double>(rows);
  const int B = p.add_block("C2_noise_qr", static_cast<int>(rr + 1));
  if (f.s >= 0)
    p.add_entry(B, f.s, 0, 0, N);
  else
    p.add_entry(B, -1, 0, 0, N * obj.dmax.approx * obj.dmax.approx / (f.sigma_r * f.sigma_r));
  for (Eigen::Index a = 0; a < rr; ++a) {
    p.add_entry(B, -1, static_cast<int>(1 + a), static_cast<int>(1 + a), 1.0);
    if (R(a, nv) != 0.0) p.add_entry(B, -1, 0, static_cast<int>(1 + a), R(a, nv));
  }
  for (Eigen::Index c = 0; c < nv; ++c) {
    const int var = static_cast<int>(c < nt ? f.tap0 + c : f.g0 + (c - nt));
    for (Eigen::Index a = 0; a <= std::min(c, rr - 1); ++a)
      if (R(a, c) != 0.0) p.add_entry(B, var, 0, static_cast<int>(1 + a), -R(a, c));
  }
}

KypLayout build(const Mat<double>& z, const Mat<double>& r, const BoundObjective& obj, Eigen::Index taps,
                const Mat<double>& E) {
  obj.validate();
  if (z.rows() != r.rows()) throw std::invalid_argument("delta form (KYP): z and r have different lengths");
  check_uncertainty_excited(z);
  KypLayout f;
  const Eigen::Index n = z.rows();
  f.nz = z.cols();
  f.ny = r.cols();
  f.K = std::clamp<Eigen::Index>(taps, 1, n);
  f.sigma_z = rms(z);
  f.sigma_r = rms(r);
  if (!(f.sigma_r > 0.0)) f.sigma_r = 1.0;
  const double kz = f.sigma_z / f.sigma_r;  // h' = kz·h, t' = kz²·t (as delta_form_lmi.cc)

  LmiProgram& p = f.program;
  f.tap0 = p.add_variables(static_cast<int>(f.K * f.ny * f.nz));
  if (!obj.delta_fixed())
    f.t = p.add_variable("", obj.kind == BoundObjective::Kind::kWeighted ? obj.lambda / (f.sigma_z * f.sigma_z) : 1.0);
  if (!obj.dmax_fixed())
    f.s = p.add_variable("", obj.kind == BoundObjective::Kind::kWeighted ? 1.0 - obj.lambda : 1.0);
  add_kyp_block(f, obj, kz);
  add_noise_qr_block(f, obj, Mat<double>(z / f.sigma_z), Mat<double>(r / f.sigma_r), E);
  return f;
}

}  // namespace

DeltaKypSolution solve_delta_kyp(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective,
                                 SdpSolver& solver, const SolverOptions& options, Eigen::Index taps,
                                 const Mat<double>& extra) {
  KypLayout f = build(z, r, objective, taps, extra);
  DeltaKypSolution out;
  out.solve = solver.solve(f.program, options);
  read_delta_solution(out.solve, {f.K, f.ny, f.nz, f.tap0, f.t, f.s, f.sigma_z, f.sigma_r}, objective, out.taps,
                      out.delta2, out.dmax2);
  out.g = Vec<double>::Zero(extra.cols());
  if (has_solution(out.solve.status))
    for (Eigen::Index j = 0; j < extra.cols(); ++j)
      out.g(j) = out.solve.x[static_cast<size_t>(f.g0 + j)] * f.sigma_r / f.e_scale(j);
  return out;
}

}  // namespace lpvid
