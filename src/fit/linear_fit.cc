#include "fit/linear_fit.h"

#include <cmath>
#include <string>

#include <Eigen/QR>

#include "core/rms.h"
#include "core/input_error.h"
#include "model/simulate.h"

namespace lpvid {
namespace {

void check_inputs(const Experiment<double>& est, int order) {
  if (order < 1 || order > kMaxLinearOrder)
    throw InputError("fit-linear: order must be between 1 and " + std::to_string(kMaxLinearOrder) + ", got " +
                     std::to_string(order));
  if (est.ny() != 1)
    throw InputError("fit-linear: exactly one output column is supported, got " + std::to_string(est.ny()));
  if (est.nu() < 1) throw InputError("fit-linear: at least one input column is needed");
  for (Eigen::Index k = 0; k < est.n(); ++k)
    if (!est.u.row(k).allFinite() || !est.y.row(k).allFinite())
      throw InputError(est.source + ": fit-linear: sample " + std::to_string(k) + " is not a finite number");
}

/// Step 1: ARX least squares. Row k: [−y_{k−1} … −y_{k−n}, u_kᵀ … u_{k−n}ᵀ (, 1)].
/// Returns the observer form of (b_0 + … + b_n z⁻ⁿ)/(1 + a_1 z⁻¹ + … + a_n z⁻ⁿ):
/// D = b_0, B_i = b_i − a_i b_0 (Kailath §2.1.3), c = e / (1 + Σ a_i).
ObserverForm arx_initialisation(const Experiment<double>& est, int n, bool offset) {
  const Eigen::Index N = est.n(), m = est.nu();
  const Eigen::Index unknowns = n + (n + 1) * m + (offset ? 1 : 0);
  if (N - n < 2 * unknowns)
    throw InputError(est.source + ": fit-linear: " + std::to_string(N) + " samples are too few for order " +
                     std::to_string(n) + " (need at least " + std::to_string(n + 2 * unknowns) + ")");
  Mat<double> Phi(N - n, unknowns);
  Vec<double> target(N - n);
  for (Eigen::Index k = n; k < N; ++k) {
    const Eigen::Index r = k - n;
    for (int i = 1; i <= n; ++i) Phi(r, i - 1) = -est.y(k - i, 0);
    for (int i = 0; i <= n; ++i) Phi.block(r, n + i * m, 1, m) = est.u.row(k - i);
    if (offset) Phi(r, unknowns - 1) = 1.0;
    target(r) = est.y(k, 0);
  }
  const Vec<double> theta = Phi.colPivHouseholderQr().solve(target);
  ObserverForm f = zero_observer_form(n, static_cast<int>(m), offset);
  f.a = stabilise_denominator(theta.head(n));
  const Mat<double> b0 = theta.segment(n, m).transpose();
  f.D = b0;
  for (int i = 1; i <= n; ++i) f.B.row(i - 1) = theta.segment(n + i * m, m).transpose() - theta(i - 1) * b0;
  if (offset) f.offset = theta(unknowns - 1) / (1.0 + theta.head(n).sum());
  return f;
}

/// Step 2: with a fixed, ŷ is linear in (B, D, x0, c) (zero when they are):
/// its Jacobian columns are the simulations with one unit parameter.
void refit_numerator(ObserverForm& f, const Experiment<double>& est) {
  const int n = f.order();
  Vec<double> p = f.parameters();
  const Eigen::Index q = p.size() - n;  // all parameters after a
  Mat<double> J(est.n(), q);
  ObserverForm g = f;
  for (Eigen::Index j = 0; j < q; ++j) {
    Vec<double> e = Vec<double>::Zero(p.size());
    e.head(n) = f.a;
    e(n + j) = 1.0;
    g.set_parameters(e);
    J.col(j) = simulate_observer(g, est.u);
  }
  p.tail(q) = J.colPivHouseholderQr().solve(est.y.col(0));
  f.set_parameters(p);
}

/// Step 3: output-error refinement with stability as the admissible set.
LmResult refine(ObserverForm& form, const Experiment<double>& est, const LmOptions& options) {
  const Vec<double> y = est.y.col(0);
  ObserverForm trial = form;
  const Residual residual = [&](const Vec<double>& p) {
    trial.set_parameters(p);
    return Vec<double>(simulate_observer(trial, est.u) - y);
  };
  const int n = form.order();
  const Admissible stable = [n](const Vec<double>& p) { return spectral_radius(p.head(n)) < kStableRadius; };
  const LmResult lm = levenberg_marquardt(residual, form.parameters(), options, stable);
  form.set_parameters(lm.p);
  return lm;
}

}  // namespace

LinearFit fit_linear(const Experiment<double>& est, const ColumnMap& columns, const LinearFitOptions& options) {
  check_inputs(est, options.order);
  LinearFit fit;
  fit.form = arx_initialisation(est, options.order, options.offset);
  refit_numerator(fit.form, est);
  const Vec<double> y = est.y.col(0);
  fit.rms_arx = rms(y - simulate_observer(fit.form, est.u));
  fit.iterations = refine(fit.form, est, options.lm).iterations;
  fit.rms_estimation = rms(y - simulate_observer(fit.form, est.u));
  if (options.nested_denominator.size() == options.order && options.nested_denominator.allFinite() &&
      spectral_radius(options.nested_denominator) < kStableRadius) {
    ObserverForm nested = zero_observer_form(options.order, static_cast<int>(est.nu()), options.offset);
    nested.a = options.nested_denominator;
    refit_numerator(nested, est);
    const int steps = refine(nested, est, options.lm).iterations;
    const double r = rms(y - simulate_observer(nested, est.u));
    if (r < fit.rms_estimation) {
      fit.form = nested;
      fit.rms_estimation = r;
      fit.iterations = steps;
    }
  }
  fit.spectral_radius = spectral_radius(fit.form.a);
  fit.model = to_lpv_model(fit.form, columns);
  return fit;
}

OrderChoice choose_order(const Experiment<double>& est, const Experiment<double>& val, const ColumnMap& columns,
                         int max_order, bool offset, int init_samples, const LmOptions& lm) {
  if (max_order < 1) throw InputError("fit-linear: the largest order must be >= 1, got " + std::to_string(max_order));
  OrderChoice choice;
  Vec<double> previous;
  std::vector<LinearFit> fits;
  for (int n = 1; n <= max_order; ++n) {
    LinearFitOptions o{n, offset, lm, {}};
    if (!choice.scores.empty()) {  // order n − 1's denominator times (1 − 0·q⁻¹)
      o.nested_denominator = Vec<double>::Zero(n);
      o.nested_denominator.head(n - 1) = previous;
    }
    try {
      LinearFit fit = fit_linear(est, columns, o);
      previous = fit.form.a;
      choice.scores.push_back({n, fit.rms_estimation, validation_rms(fit.model, val, init_samples)});
      fits.push_back(std::move(fit));
    } catch (const InputError&) {
      if (n == 1) throw;  // order 1 does not fit: the data is unusable
      break;              // too few samples for this and larger orders
    }
  }
  double best = choice.scores.front().rms_validation;
  for (const OrderScore& s : choice.scores) best = std::min(best, s.rms_validation);
  const double floor = kOrderFloor * rms(val.y);
  for (const OrderScore& s : choice.scores)
    if (s.rms_validation <= (1.0 + kOrderSlack) * best + floor) {
      choice.order = s.order;
      choice.fit = fits[static_cast<size_t>(&s - choice.scores.data())];
      break;
    }
  return choice;
}

}  // namespace lpvid
