#include "lmi/delta_form_barrier.h"

#include <chrono>
#include <cmath>
#include <limits>

#include "core/rms.h"
#include "toeplitz/correlation_2d.h"
#include "toeplitz/fir.h"

namespace lpvid {

bool barrier_applies(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective) {
  return z.cols() == 1 && r.cols() == 1 && objective.kind != BoundObjective::Kind::kMinDelta &&
         !(objective.kind == BoundObjective::Kind::kWeighted && !(objective.lambda > 0 && objective.lambda < 1)) &&
         !(objective.delta_fixed() && !(objective.delta > 0));
}

namespace {

using Index = Eigen::Index;
using Vecd = Eigen::VectorXd;
using Dense = Eigen::MatrixXd;

/// L × L lower-triangular Toeplitz matrix with first column c.
Dense lower_toeplitz(const Vecd& c) {
  const Index L = c.size();
  Dense T = Dense::Zero(L, L);
  for (Index j = 0; j < L; ++j) T.col(j).tail(L - j) = c.head(L - j);
  return T;
}

/// Ω_l(M) = Σ_{a−b=l} M(a, b), l = 0 … L−1 (subdiagonal sums).
Vecd subdiagonal_sums(const Dense& M) {
  const Index L = M.rows();
  Vecd out = Vecd::Zero(L);
  for (Index b = 0; b < L; ++b)
    for (Index a = b; a < L; ++a) out(a - b) += M(a, b);
  return out;
}

/// The scaled problem. Variables x = (h, t) (t only when δ is free); s is
/// eliminated (see the header).
struct Problem {
  Index n = 0, m = 0, L = 0;
  double N = 0;
  Vecd r_head, r_tail;  ///< scaled residual: rows < m (no Δ acts there) and rows ≥ m
  Dense Z;              ///< L × L lower-triangular Toeplitz of the scaled z (rows ≥ m)
  Dense G;              ///< ZᵀZ
  bool t_var = false;
  double t_fix = 0, s_fix = 0;
  double ct = 0, cs = 0;  ///< objective weights of t, s (cs > 0)
  double nu = 0;          ///< 2L + N + 1

  Index dim() const { return L + (t_var ? 1 : 0); }
  double t_of(const Vecd& x) const { return t_var ? x(L) : t_fix; }
};

/// F_μ at x, or +∞ outside the interior, with what the derivatives reuse.
struct Point {
  bool interior = false;
  double value = std::numeric_limits<double>::infinity();
  Dense T;
  /// Computed on an empty matrix until evaluate() factors F1: a default-
  /// constructed LLT leaves its status uninitialised, and moving a Point
  /// that returned early (t <= 0) read it (UBSan: invalid ComputationInfo).
  Eigen::LLT<Dense> llt{Dense(0, 0)};
  Vecd d_tail;
  double D = 0;  ///< ‖d‖² (all rows)
};

Point evaluate(const Problem& p, const Vecd& x, double mu) {
  Point pt;
  const Vecd h = x.head(p.L);
  const double t = p.t_of(x);
  pt.d_tail = p.r_tail - p.Z * h;
  pt.D = p.r_head.squaredNorm() + pt.d_tail.squaredNorm();
  if (!(t > 0) || !std::isfinite(pt.D)) return pt;
  pt.T = lower_toeplitz(h);
  Dense F1 = -pt.T * pt.T.transpose();
  F1.diagonal().array() += t;
  pt.llt.compute(F1);
  if (pt.llt.info() != Eigen::Success) return pt;
  const Vecd diag = pt.llt.matrixLLT().diagonal();
  if (!(diag.minCoeff() > 0)) return pt;
  pt.value = (p.t_var ? p.ct * t / mu : 0.0) + p.cs * pt.D / (p.N * mu) - 2.0 * diag.array().log().sum();
  pt.interior = std::isfinite(pt.value);
  return pt;
}

/// Gradient and Hessian of F_μ at an interior point; P, Q, R as in the header.
void derivatives(const Problem& p, const Point& pt, double mu, const CorrelationGrid& grid, Vecd& g, Dense& H, Dense& P,
                 Dense& Q, Dense& R) {
  const Index L = p.L;
  P = pt.llt.solve(Dense::Identity(L, L));
  P = 0.5 * (P + P.transpose());
  Q = P * pt.T;
  R = pt.T.transpose() * Q;
  R = 0.5 * (R + R.transpose());
  g = Vecd::Zero(p.dim());
  H = Dense::Zero(p.dim(), p.dim());

  // −log det(tI − TTᵀ)
  g.head(L) = 2.0 * subdiagonal_sums(Q);
  Dense diag_sums(L, L);  // Σ_c P(c+k, c+l)
  for (Index k = L - 1; k >= 0; --k)
    for (Index l = L - 1; l >= 0; --l) diag_sums(k, l) = P(k, l) + (k + 1 < L && l + 1 < L ? diag_sums(k + 1, l + 1) : 0.0);
  const Eigen::MatrixXcd P_hat = grid.spectrum(P), R_hat = grid.spectrum(R);
  const Eigen::MatrixXcd Q_hat = grid.spectrum(Q), Qt_hat = grid.spectrum(Q.transpose());
  const Dense Hh = diag_sums + grid.correlate(Q_hat, Qt_hat, -1) + grid.correlate(P_hat, R_hat, +1);
  H.topLeftCorner(L, L) = Hh + Hh.transpose();  // 2·(symmetric part)
  if (p.t_var) {
    g(L) = p.ct / mu - P.trace();
    H.block(0, L, L, 1) = -2.0 * subdiagonal_sums(P * Q);
    H.block(L, 0, 1, L) = H.block(0, L, L, 1).transpose();
    H(L, L) = P.squaredNorm();
  }
  // c_s·‖d‖²/(N μ), d = r − Z h
  const double w = p.cs / (p.N * mu);
  g.head(L) -= 2.0 * w * (p.Z.transpose() * pt.d_tail);
  H.topLeftCorner(L, L) += 2.0 * w * p.G;
}

/// The scaled problem of solve_delta_form_barrier (σ_z, σ_r returned).
Problem make_problem(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective, double& sigma_z,
                     double& sigma_r) {
  Problem p;
  p.n = z.rows();
  p.m = check_uncertainty_excited(z);
  p.L = p.n - p.m;
  p.N = static_cast<double>(p.n);
  p.nu = 2.0 * static_cast<double>(p.L) + p.N + 1.0;
  sigma_z = rms(z.bottomRows(p.L));
  sigma_r = rms(r);
  if (!(sigma_r > 0.0)) sigma_r = 1.0;
  const double kz = sigma_z / sigma_r;
  const Vecd zs = z.col(0).tail(p.L) / sigma_z;
  const Vecd rs = r.col(0) / sigma_r;
  p.r_head = rs.head(p.m);
  p.r_tail = rs.tail(p.L);
  p.Z = lower_toeplitz(zs);
  p.G = p.Z.transpose() * p.Z;
  p.t_var = !objective.delta_fixed();
  p.t_fix = objective.delta * objective.delta * kz * kz;
  p.s_fix = objective.dmax * objective.dmax / (sigma_r * sigma_r);
  if (objective.kind == BoundObjective::Kind::kWeighted) {
    p.ct = objective.lambda / (sigma_z * sigma_z);
    p.cs = 1.0 - objective.lambda;
  } else {
    p.ct = p.t_var ? 1.0 : 0.0;
    p.cs = 1.0;
  }
  return p;
}

DeltaFormSolution fail(DeltaFormSolution out, const std::string& why) {
  out.solve.status = SolveStatus::kBackendError;
  out.solve.message = "structured barrier: " + why;
  return out;
}

}  // namespace

DeltaFormSolution solve_delta_form_barrier(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective,
                                           const BarrierOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  objective.validate();
  DeltaFormSolution out;
  out.solve.backend = "barrier";
  if (z.rows() != r.rows() || !barrier_applies(z, r, objective))
    return fail(out, "applies to SISO signals and the objectives min dmax, weighted (0 < lambda < 1), fixed bounds");
  double sigma_z = 1, sigma_r = 1;
  const Problem p = make_problem(z, r, objective, sigma_z, sigma_r);
  out.leading_zeros = p.m;
  out.horizon = p.L;
  const double kz = sigma_z / sigma_r;  // h' = kz·h, t' = kz²·t, s' = s/σ_r²
  const bool feasibility = objective.kind == BoundObjective::Kind::kFeasibility;
  const Index L = p.L;

  // Start: h = 0 and, for a free δ, t central for μ₀ (c_t/μ = tr P = L/t);
  // μ₀ puts the eliminated s at twice the residual's mean square.
  Vecd x = Vecd::Zero(p.dim());
  const double D0 = p.r_head.squaredNorm() + p.r_tail.squaredNorm();
  double mu = p.cs * std::max(D0 / p.N, 1e-12);
  if (p.t_var) x(L) = mu * static_cast<double>(L) / p.ct;
  Point pt = evaluate(p, x, mu);
  if (!pt.interior) return fail(out, "the start is not interior");
  const auto s_of = [&](const Point& q) { return q.D / p.N + mu / p.cs; };  // the eliminated s
  const auto objective_of = [&](const Vecd& y, const Point& q) { return (p.t_var ? p.ct * y(L) : 0.0) + p.cs * s_of(q); };

  const CorrelationGrid grid(L);
  int newton = 0;
  Vecd g;
  Dense H, P, Q, R;
  // Newton on F_μ until the decrement λ² is below `tol`; "" on success.
  const auto center = [&](double tol, int max_steps) -> std::string {
    for (int inner = 0; inner < max_steps; ++inner) {
      if (++newton > options.max_newton) return "no convergence within " + std::to_string(options.max_newton) + " Newton steps";
      derivatives(p, pt, mu, grid, g, H, P, Q, R);
      Eigen::LDLT<Dense> ldlt(H);
      const Vecd dx = ldlt.solve(-g);
      if (ldlt.info() != Eigen::Success || !dx.allFinite()) return "the Newton system is singular";
      const double dec2 = -g.dot(dx);
      if (!(dec2 >= 0)) return "not a descent direction (the Hessian lost definiteness)";
      if (dec2 < tol) return "";
      // Backtracking (Armijo) from the full step; F_μ changes are O(1)
      // numbers (the objective enters divided by μ but as a difference).
      double alpha = 1.0;
      Point trial;
      for (int ls = 0; ls < 60; ++ls, alpha *= 0.5) {
        trial = evaluate(p, x + alpha * dx, mu);
        if (trial.interior && (dec2 < 1e-6 || trial.value - pt.value <= -0.25 * alpha * dec2)) break;
      }
      if (!trial.interior) return "the line search found no interior point";
      if (alpha < 1e-12) return "";  // no progress possible in floating point: as central as it gets
      x += alpha * dx;
      pt = std::move(trial);
    }
    return "not centred within " + std::to_string(max_steps) + " Newton steps";
  };

  bool infeasible = false, found_feasible = false;
  for (;;) {
    if (const std::string err = center(0.25, 60); !err.empty()) return fail(out, err);
    const double obj = objective_of(x, pt);
    if (feasibility) {
      if (s_of(pt) <= p.s_fix) {  // a feasible point: the taps certify "consistent" (no polishing: keep it)
        found_feasible = true;
        break;
      }
      if (obj - 2.0 * p.nu * mu > p.s_fix) {  // the central path's lower estimate is above d_max²
        infeasible = true;
        break;
      }
    }
    if (p.nu * mu <= std::max((feasibility ? options.feasibility_rel_gap : options.rel_gap) * std::abs(obj), options.abs_gap))
      break;
    mu /= options.mu_factor;
    pt = evaluate(p, x, mu);  // same x, new μ (always interior: F_μ's domain does not depend on μ)
  }
  // Y = μ·C⁻¹ is dual feasible only on the central path: centre tightly first
  // (the residual is what identify/dual_certify.h must project away and
  // cover with a PSD margin).
  if (!found_feasible)
    if (const std::string err = center(1e-14, 30); !err.empty() && err.rfind("not centred", 0) != 0) return fail(out, err);
  derivatives(p, pt, mu, grid, g, H, P, Q, R);
  const double s = s_of(pt);
  if (feasibility && !(s <= p.s_fix)) infeasible = true;  // undecided at the smallest gap: the dual certificate decides

  // Dual matrices (scaled), then original units as solve_delta_form.
  out.dual_c1 = Dense::Zero(2 * L, 2 * L);
  out.dual_c1.topLeftCorner(L, L) = mu * P;
  out.dual_c1.topRightCorner(L, L) = -mu * Q;
  out.dual_c1.bottomLeftCorner(L, L) = -mu * Q.transpose();
  out.dual_c1.bottomRightCorner(L, L) = mu * (Dense::Identity(L, L) + R);
  Vecd d(p.n);
  d << p.r_head, pt.d_tail;
  const double phi = p.N * s - pt.D;  // = N μ / c_s on the path
  out.dual_c2 = Dense::Zero(p.n + 1, p.n + 1);
  out.dual_c2(0, 0) = mu / phi;
  out.dual_c2.block(1, 0, p.n, 1) = -mu * d / phi;
  out.dual_c2.block(0, 1, 1, p.n) = out.dual_c2.block(1, 0, p.n, 1).transpose();
  out.dual_c2.bottomRightCorner(p.n, p.n) = mu * (Dense::Identity(p.n, p.n) + d * d.transpose() / phi);
  out.dual_c1.topRows(L) *= kz;
  out.dual_c1.leftCols(L) *= kz;
  out.dual_c2.row(0) /= sigma_r;
  out.dual_c2.col(0) /= sigma_r;

  out.taps = x.head(L) / kz;
  out.delta2 = p.t_var ? x(L) / (kz * kz) : objective.delta * objective.delta;
  out.dmax2 = feasibility ? objective.dmax * objective.dmax : s * sigma_r * sigma_r;
  out.solve.status = infeasible ? SolveStatus::kPrimalInfeasible : SolveStatus::kOptimal;
  out.solve.iterations = newton;
  const double scale = sigma_r * sigma_r;  // objective in original units = σ_r²·(scaled)
  out.solve.objective = objective_of(x, pt) * scale;
  out.solve.dual_objective = (objective_of(x, pt) - p.nu * mu) * scale;
  out.solve.message = "structured barrier: " + std::to_string(newton) + " Newton steps, final mu " + std::to_string(mu);
  out.solve.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

BarrierDerivatives barrier_derivatives(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective,
                                       const Eigen::VectorXd& x, double mu) {
  double sigma_z = 1, sigma_r = 1;
  const Problem p = make_problem(z, r, objective, sigma_z, sigma_r);
  BarrierDerivatives out;
  const Point pt = evaluate(p, x, mu);
  out.value = pt.value;
  if (!pt.interior) return out;
  const CorrelationGrid grid(p.L);
  Dense P, Q, R;
  derivatives(p, pt, mu, grid, out.gradient, out.hessian, P, Q, R);
  return out;
}

}  // namespace lpvid
