#include "fit/levenberg_marquardt.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/deadline.h"

namespace lpvid {

Mat<double> forward_difference_jacobian(const JacobianColumns& columns, const Vec<double>& p, const Vec<double>& r0) {
  const double root_eps = std::sqrt(std::numeric_limits<double>::epsilon());
  if (columns.at) columns.at(p);
  Mat<double> J(r0.size(), p.size());
  Vec<double> q = p;
  for (Eigen::Index j = 0; j < p.size(); ++j) {
    const double h = root_eps * std::max(1.0, std::abs(p(j)));
    q(j) = p(j) + h;
    J.col(j) = (columns.column(q, j) - r0) / h;
    q(j) = p(j);
  }
  return J;
}

Mat<double> forward_difference_jacobian(const Residual& r, const Vec<double>& p, const Vec<double>& r0) {
  return forward_difference_jacobian(JacobianColumns{nullptr, [&](const Vec<double>& q, Eigen::Index) { return r(q); }},
                                     p, r0);
}

namespace {

/// The damped Gauss-Newton step with Marquardt's scaling: damp each direction
/// by its own curvature; the floor keeps a parameter with a zero column (no
/// influence) well posed. Solved in the scaled variables z = S p,
/// S = diag(JᵀJ)^½, so that columns of very different size (a term x₁³ next
/// to x₁) do not ruin the solve: (S⁻¹JᵀJS⁻¹ + λI) z = −S⁻¹g, step = S⁻¹z (the
/// same step in exact arithmetic).
Vec<double> lm_scaled_step(const Mat<double>& JtJ, const Vec<double>& g, double lambda) {
  const double floor = 1e-12 * std::max(1.0, JtJ.diagonal().maxCoeff());
  const Vec<double> scale = JtJ.diagonal().cwiseMax(floor).cwiseSqrt();
  Mat<double> H = scale.cwiseInverse().asDiagonal() * JtJ * scale.cwiseInverse().asDiagonal();
  H.diagonal().array() += lambda;
  return scale.cwiseInverse().cwiseProduct(H.ldlt().solve(-g.cwiseQuotient(scale)));
}

}  // namespace

LmResult levenberg_marquardt(const Residual& r, const Vec<double>& p0, const LmOptions& options,
                             const Admissible& admissible, const JacobianColumns* columns) {
  const auto jacobian = [&](const Vec<double>& p, const Vec<double>& r0) {
    return columns ? forward_difference_jacobian(*columns, p, r0) : forward_difference_jacobian(r, p, r0);
  };
  auto finite = [](const Vec<double>& v) { return v.allFinite(); };
  if (admissible && !admissible(p0)) throw std::invalid_argument("levenberg_marquardt: start point not admissible");
  LmResult out;
  out.p = p0;
  Vec<double> res = r(p0);
  if (!finite(res)) throw std::invalid_argument("levenberg_marquardt: residual at the start point is not finite");
  out.cost = 0.5 * res.squaredNorm();
  if (p0.size() == 0) {
    out.converged = true;
    return out;
  }
  Mat<double> J = jacobian(out.p, res);
  Mat<double> JtJ = J.transpose() * J;
  Vec<double> g = J.transpose() * res;
  double lambda = options.initial_damping;
  int small_decreases = 0;
  while (out.iterations < options.max_iterations) {
    ++out.iterations;
    check_deadline("a model was fitted");  // the user's --timeout, between steps
    const Vec<double> step = lm_scaled_step(JtJ, g, lambda);
    const Vec<double> trial = out.p + step;
    bool ok = step.allFinite() && (!admissible || admissible(trial));
    Vec<double> trial_res;
    double trial_cost = std::numeric_limits<double>::infinity();
    if (ok) {
      trial_res = r(trial);
      if (finite(trial_res)) trial_cost = 0.5 * trial_res.squaredNorm();
    }
    if (trial_cost < out.cost) {
      const double decrease = (out.cost - trial_cost) / std::max(out.cost, std::numeric_limits<double>::min());
      out.p = trial;
      out.cost = trial_cost;
      res = trial_res;
      lambda = std::max(lambda / 3.0, 1e-15);
      small_decreases = decrease < options.relative_tolerance ? small_decreases + 1 : 0;
      if (small_decreases >= 2 || out.cost == 0) {
        out.converged = true;
        break;
      }
      J = jacobian(out.p, res);
      JtJ = J.transpose() * J;
      g = J.transpose() * res;
    } else {
      lambda *= 4.0;
      if (lambda > 1e16) {  // no descent direction left: a (local) minimum
        out.converged = true;
        break;
      }
    }
  }
  return out;
}

}  // namespace lpvid
