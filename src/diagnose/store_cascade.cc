#include "diagnose/store_cascade.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "model/state_scheduling.h"

namespace lpvid {

namespace {

/// The two slowest stable real poles of the constant A term as time
/// constants 1/(1 − p) in samples (largest first); a complex pair counts
/// with its modulus. Fewer than two: the missing ones are 4 and 16 samples.
std::vector<double> time_constants(const LpvModel<double>& m) {
  std::vector<double> tau;
  for (const auto& t : m.A.terms) {
    if (t.basis.degree() != 0 || t.value.rows() == 0) continue;
    const Eigen::VectorXcd ev = Eigen::EigenSolver<Mat<double>>(t.value, false).eigenvalues();
    for (Eigen::Index i = 0; i < ev.size(); ++i) {
      const double p = std::abs(ev(i));
      if (p > 0 && p < 1) tau.push_back(1.0 / (1.0 - p));
    }
  }
  std::sort(tau.rbegin(), tau.rend());
  for (double d : {16.0, 4.0})
    if (tau.size() < 2) tau.push_back(d);
  return {tau[0], tau[1]};
}

}  // namespace

LpvModel<double> store_cascade_model(const StoreCascadeShape& s, const LpvModel<double>& like) {
  LpvModel<double> m;
  m.nx = 2;
  m.nu = m.ny = 1;
  // the data scheduling columns of `like` first (the experiment carries them), then the stores' own
  m.scheduling = like.scheduling;
  m.columns = like.columns;
  for (const char* name : {"sqrt_store1", "sqrt_store2", "overflow_store1", "overflow_store2"})
    m.scheduling.push_back(name);
  for (const std::string& c : {state_column_text(StateFunction::kSqrtPos, 0, s.c1), state_column_text(StateFunction::kSqrtPos, 1, s.c2),
                               state_column_text(StateFunction::kHinge, 0, s.o1), state_column_text(StateFunction::kHinge, 1, s.o2)})
    m.columns.rho.push_back(c);
  const size_t first = like.scheduling.size();
  const Monomial one = constant_monomial(m.scheduling.size());
  m.A = ParamMatrix<double>(2, 2);
  m.A.add(one, Mat<double>::Identity(2, 2));
  Mat<double> b(2, 1);
  b << s.b1, 0;
  m.B = ParamMatrix<double>(2, 1);
  m.B.add(one, b);
  Mat<double> c(1, 2);
  c << 0, 1;
  m.C = ParamMatrix<double>(1, 2);
  m.C.add(one, c);
  m.D = ParamMatrix<double>(1, 1);
  m.D.add(one, Mat<double>::Zero(1, 1));
  const double e[4][2] = {{-s.k1, s.k12}, {0, -s.k2}, {s.e1, s.e12}, {0, s.e2}};
  for (int j = 0; j < 4; ++j) {
    Monomial h = one;
    h.powers[first + static_cast<size_t>(j)] = 1;
    m.state_offset.basis.push_back(h);
    Vec<double> v(2);
    v << e[j][0], e[j][1];
    m.state_offset.values.push_back(v);
  }
  m.offset.basis = {one};
  m.offset.values = {Vec<double>::Constant(1, s.phi)};
  m.x0 = Vec<double>(2);
  m.x0 << s.h1, s.h2;
  return m;
}

std::vector<LpvModel<double>> store_cascade_starts(const LpvModel<double>& linear, const Experiment<double>& est) {
  if (linear.nu != 1 || linear.ny != 1 || !linear.statics.empty() || !linear.state_offset.empty() ||
      !linear.correction.basis.empty() || !state_scheduled(linear.columns.rho, linear.nx).empty() || est.n() < 2)
    return {};
  for (const ParamMatrix<double>* pm : {&linear.A, &linear.B, &linear.C, &linear.D})
    for (const auto& t : pm->terms)
      if (t.basis.degree() != 0) return {};  // an LPV model: not the LTI starting point this family replaces
  const double u_mean = est.u.col(0).mean(), y_mean = est.y.col(0).mean();
  const double y_max = est.y.col(0).maxCoeff(), y_min = est.y.col(0).minCoeff();
  if (!(u_mean > 0) || !(y_mean > 0) || !(y_max > y_min)) return {};
  const std::vector<double> tau = time_constants(linear);
  const double pairs[3][2] = {{tau[1], tau[0]}, {tau[0], tau[1]}, {std::sqrt(tau[0] * tau[1]), std::sqrt(tau[0] * tau[1])}};
  std::vector<LpvModel<double>> starts;
  for (double overflow : {0.8, 1.0, 1.2})
  for (const auto& p : pairs)
    for (double level1 : {0.5, 1.0, 1.5}) {
      StoreCascadeShape s;
      const double rest2 = y_mean, rest1 = level1 * y_mean;  // the levels at rest
      // linearised outflow k/(2√h) = 1/τ at the resting level; inflow balances outflow
      s.k1 = 2.0 * std::sqrt(rest1) / p[0];
      s.k2 = 2.0 * std::sqrt(rest2) / p[1];
      s.b1 = s.k1 * std::sqrt(rest1) / u_mean;
      s.k12 = s.k2 * std::sqrt(rest2) / std::sqrt(rest1);
      s.o1 = overflow * y_max;
      s.o2 = y_max - 0.01 * (y_max - y_min);
      // x0 = the levels at the first sample: store 2 from the output, store 1 at its resting ratio
      s.h2 = est.y(0, 0) > 0 ? est.y(0, 0) : y_mean;
      s.h1 = level1 * s.h2;
      starts.push_back(store_cascade_model(s, linear));
    }
  return starts;
}

}  // namespace lpvid
