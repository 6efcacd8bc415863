#include "explore/block_model.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "core/rms.h"
#include "fit/levenberg_marquardt.h"

namespace lpvid {
namespace {

/// g_in(v) of block_model.h.
double input_block(const BlockModel& m, double v) {
  const EffectSet& e = m.effects;
  double out = v;
  if (e.dead_zone) out = (v > 0 ? 1.0 : -1.0) * std::max(std::abs(v) - e.dead_zone_width, 0.0);
  if (e.input_saturation) out = std::min(out, e.input_level);
  double power = 1.0;
  for (Eigen::Index p = 0; p < m.alpha.size(); ++p) {
    power = p == 0 ? (v - m.v_mean) * (v - m.v_mean) : power * (v - m.v_mean);
    out += m.alpha(p) * power;
  }
  return out;
}

/// g_out(ŷ) + c of block_model.h.
double output_block(const BlockModel& m, double yhat) {
  double out = yhat, power = 1.0;
  for (Eigen::Index q = 0; q < m.beta.size(); ++q) {
    power = q == 0 ? (yhat - m.y_mean) * (yhat - m.y_mean) : power * (yhat - m.y_mean);
    out += m.beta(q) * power;
  }
  if (m.effects.output_saturation) out = std::min(out, m.output_level);
  return out + (m.linear.has_offset ? m.linear.offset : 0.0);
}

/// The input after delay and input block (N-vector).
Vec<double> block_input(const BlockModel& m, const Vec<double>& u) {
  Vec<double> v(u.size());
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    const Eigen::Index j = std::max<Eigen::Index>(k - m.effects.delay, 0);  // u_{k−d}, u_0 before the record
    v(k) = input_block(m, u(j));
  }
  return v;
}

}  // namespace

std::string EffectSet::name(bool offset) const {
  std::string s = offset ? "offset" : "linear";
  if (delay > 0) s += "+delay" + std::to_string(delay);
  if (input_degree > 1) s += "+input_poly" + std::to_string(input_degree);
  if (input_paths > 1) s += "+input_paths" + std::to_string(input_paths);
  if (input_saturation) s += "+input_sat";
  if (dead_zone) s += "+dead_zone";
  if (lpv == Scheduling::kInput) s += "+lpv(rho=u)";
  if (lpv == Scheduling::kOutputLag) s += "+lpv(rho=y[k-1])";
  if (output_degree > 1) s += "+output_poly" + std::to_string(output_degree);
  if (output_saturation) s += "+output_sat";
  return s;
}

Vec<double> BlockModel::parameters() const {
  const Vec<double> lin = linear.parameters();
  const bool lpv = effects.lpv != Scheduling::kNone;
  Vec<double> p(lin.size() + alpha.size() + (lpv ? c1.size() + 1 : 0) + beta.size() +
                (effects.output_saturation ? 1 : 0));
  Eigen::Index i = 0;
  p.segment(i, lin.size()) = lin, i += lin.size();
  p.segment(i, alpha.size()) = alpha, i += alpha.size();
  if (lpv) p.segment(i, c1.size()) = c1, i += c1.size(), p(i++) = d1;
  p.segment(i, beta.size()) = beta, i += beta.size();
  if (effects.output_saturation) p(i) = output_level;
  return p;
}

void BlockModel::set_parameters(const Vec<double>& p) {
  const Eigen::Index nl = linear.parameter_count();
  linear.set_parameters(p.head(nl));
  Eigen::Index i = nl;
  alpha = p.segment(i, alpha.size()), i += alpha.size();
  if (effects.lpv != Scheduling::kNone) c1 = p.segment(i, c1.size()), i += c1.size(), d1 = p(i++);
  beta = p.segment(i, beta.size()), i += beta.size();
  if (effects.output_saturation) output_level = p(i);
}

BlockModel neutral_block_model(const ObserverForm& linear, const EffectSet& effects, const Vec<double>& u,
                               const Vec<double>& y) {
  BlockModel m;
  m.linear = linear;
  m.effects = effects;
  m.alpha = Vec<double>::Zero(std::max(effects.input_degree - 1, 0));
  const int paths = std::max(effects.input_paths, 1);
  m.linear.B.conservativeResize(Eigen::NoChange, paths);
  m.linear.D.conservativeResize(Eigen::NoChange, paths);
  m.linear.B.rightCols(paths - 1).setZero();
  m.linear.D.rightCols(paths - 1).setZero();
  m.beta = Vec<double>::Zero(std::max(effects.output_degree - 1, 0));
  m.c1 = Vec<double>::Zero(effects.lpv != Scheduling::kNone ? linear.order() : 0);
  m.v_mean = u.mean();
  m.path_mean = u.mean();  // ū' ≈ ū: the paths only need a fixed centre
  m.y_mean = y.mean() - (linear.has_offset ? linear.offset : 0.0);  // ŷ is before the offset
  m.rho_mean = effects.lpv == Scheduling::kInput ? u.mean() : y.mean();
  m.output_level = y.maxCoeff() - (linear.has_offset ? linear.offset : 0.0);
  return m;
}

Vec<double> simulate_block_model(const BlockModel& m, const Vec<double>& u) {
  const ObserverForm& f = m.linear;
  const int n = f.order();
  const Vec<double> v = block_input(m, u);
  Vec<double> y(u.size());
  Vec<double> x = f.x0, next(n), phi(f.inputs());
  double y_prev = 0;
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    phi(0) = v(k);
    for (Eigen::Index r = 1; r < phi.size(); ++r) phi(r) = (r == 1 ? (v(k) - m.path_mean) : phi(r - 1)) * (v(k) - m.path_mean);
    const double lin = (n > 0 ? x(0) : 0.0) + f.D.row(0).dot(phi);
    double yhat = lin;
    if (m.effects.lpv != Scheduling::kNone) {
      const double rho = m.effects.lpv == Scheduling::kInput ? u(k) : (k == 0 ? lin : y_prev);
      yhat += (rho - m.rho_mean) * (m.c1.dot(x) + m.d1 * v(k));
    }
    y(k) = output_block(m, yhat);
    y_prev = y(k);
    for (int i = 0; i < n; ++i) next(i) = (i + 1 < n ? x(i + 1) : 0.0) - f.a(i) * x(0) + f.B.row(i).dot(phi);
    x.swap(next);
  }
  return y;
}

double fit_block_model(BlockModel& m, const Vec<double>& u, const Vec<double>& y, bool fix_dynamics,
                       int max_iterations) {
  const int n = m.linear.order();
  const Vec<double> full = m.parameters();
  // Free parameters: all, or all but a (first n) and B (next n, one input).
  const Eigen::Index fixed = fix_dynamics ? 2 * n : 0;
  BlockModel trial = m;
  const Residual residual = [&](const Vec<double>& q) {
    Vec<double> p = full;
    p.tail(p.size() - fixed) = q;
    trial.set_parameters(p);
    return Vec<double>(simulate_block_model(trial, u) - y);
  };
  const Admissible stable = [&](const Vec<double>& q) {
    return fix_dynamics || spectral_radius(q.head(n)) < kStableRadius;
  };
  LmOptions options;
  options.max_iterations = max_iterations;
  const LmResult r = levenberg_marquardt(residual, full.tail(full.size() - fixed), options, stable);
  Vec<double> p = full;
  p.tail(p.size() - fixed) = r.p;
  m.set_parameters(p);
  return rms(simulate_block_model(m, u) - y);
}

double block_validation_rms(const BlockModel& m, const Vec<double>& u, const Vec<double>& y, int init_samples) {
  BlockModel trial = m;
  const int n = m.linear.order();
  if (init_samples > 0 && n > 0) {
    // Start from the steady state of the first (block) input: x = (I − A)⁻¹ B u'_0.
    const Vec<double> v0 = block_input(m, u.head(1));
    const Mat<double> I = Mat<double>::Identity(n, n);
    Vec<double> phi0(m.linear.inputs());
    for (Eigen::Index r = 0; r < phi0.size(); ++r) phi0(r) = r == 0 ? v0(0) : std::pow(v0(0) - m.path_mean, double(r + 1));
    const Vec<double> x_ss = (I - m.linear.A()).partialPivLu().solve(m.linear.B * phi0);
    const Eigen::Index s = std::min<Eigen::Index>(init_samples, u.size());
    const Residual residual = [&](const Vec<double>& x0) {
      trial.linear.x0 = x0;
      return Vec<double>(simulate_block_model(trial, u.head(s)) - y.head(s));
    };
    trial.linear.x0 = levenberg_marquardt(residual, x_ss).p;
  } else {
    trial.linear.x0 = Vec<double>::Zero(n);
  }
  return rms(simulate_block_model(trial, u) - y);
}

}  // namespace lpvid
