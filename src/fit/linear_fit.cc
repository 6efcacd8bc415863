#include "fit/linear_fit.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/QR>

#include "core/rms.h"
#include "core/input_error.h"
#include "data/experiment_builder.h"
#include "data/record_order.h"
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
  // rows k >= n of each record (the regressors never reach into another record)
  Eigen::Index rows = 0;
  for (const Eigen::Index len : est.record_lengths()) rows += std::max<Eigen::Index>(len - n, 0);
  if (rows < 2 * unknowns)
    throw InputError(est.source + ": fit-linear: " + std::to_string(N) + " samples are too few for order " +
                     std::to_string(n) + " (need at least " + std::to_string(n + 2 * unknowns) +
                     (est.record_count() > 1 ? ", counting n fewer in each record" : "") + ")");
  Mat<double> Phi(rows, unknowns);
  Vec<double> target(rows);
  Eigen::Index r = 0, first = 0;
  for (const Eigen::Index len : est.record_lengths()) {
    for (Eigen::Index k = first + n; k < first + len; ++k, ++r) {
      for (int i = 1; i <= n; ++i) Phi(r, i - 1) = -est.y(k - i, 0);
      for (int i = 0; i <= n; ++i) Phi.block(r, n + i * m, 1, m) = est.u.row(k - i);
      if (offset) Phi(r, unknowns - 1) = 1.0;
      target(r) = est.y(k, 0);
    }
    first += len;
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

/// The fit's unknowns over several records: the shared observer form (its
/// x0 is the first record's) and the initial state of every further record.
/// One record: `more` is empty and the vector is the form's parameters().
struct RecordsForm {
  ObserverForm form;
  std::vector<Vec<double>> more;  ///< x0 of records 2, 3, …

  Vec<double> parameters() const {
    const Vec<double> p = form.parameters();
    Vec<double> out(p.size() + static_cast<Eigen::Index>(more.size()) * form.order());
    out.head(p.size()) = p;
    for (size_t r = 0; r < more.size(); ++r)
      out.segment(p.size() + static_cast<Eigen::Index>(r) * form.order(), form.order()) = more[r];
    return out;
  }
  void set_parameters(const Vec<double>& p) {
    const Eigen::Index own = form.parameter_count();
    form.set_parameters(p.head(own));
    for (size_t r = 0; r < more.size(); ++r) more[r] = p.segment(own + static_cast<Eigen::Index>(r) * form.order(), form.order());
  }
  /// ŷ over every record, each from its own x0 (stacked like the records).
  Vec<double> simulate(const Experiment<double>& est) const {
    if (more.empty()) return simulate_observer(form, est.u);
    Vec<double> y(est.n());
    Eigen::Index first = 0;
    const std::vector<Eigen::Index> lengths = est.record_lengths();
    for (size_t r = 0; r < lengths.size(); ++r) {
      ObserverForm f = form;
      if (r > 0) f.x0 = more[r - 1];
      y.segment(first, lengths[r]) = simulate_observer(f, est.u.middleRows(first, lengths[r]));
      first += lengths[r];
    }
    return y;
  }
};

RecordsForm records_form(const ObserverForm& f, const Experiment<double>& est) {
  return {f, std::vector<Vec<double>>(est.record_count() - 1, Vec<double>::Zero(f.order()))};
}

/// Step 2: with a fixed, ŷ is linear in (B, D, x0 of every record, c) (zero
/// when they are): its Jacobian columns are the simulations with one unit
/// parameter.
void refit_numerator(RecordsForm& f, const Experiment<double>& est) {
  const int n = f.form.order();
  Vec<double> p = f.parameters();
  const Eigen::Index q = p.size() - n;  // all parameters after a
  Mat<double> J(est.n(), q);
  RecordsForm g = f;
  for (Eigen::Index j = 0; j < q; ++j) {
    Vec<double> e = Vec<double>::Zero(p.size());
    e.head(n) = f.form.a;
    e(n + j) = 1.0;
    g.set_parameters(e);
    J.col(j) = g.simulate(est);
  }
  p.tail(q) = J.colPivHouseholderQr().solve(est.y.col(0));
  f.set_parameters(p);
}

/// Step 3: output-error refinement with stability as the admissible set.
LmResult refine(RecordsForm& form, const Experiment<double>& est, const LmOptions& options) {
  const Vec<double> y = est.y.col(0);
  RecordsForm trial = form;
  const Residual residual = [&](const Vec<double>& p) {
    trial.set_parameters(p);
    return Vec<double>(trial.simulate(est) - y);
  };
  const int n = form.form.order();
  const Admissible stable = [n](const Vec<double>& p) { return spectral_radius(p.head(n)) < kStableRadius; };
  const LmResult lm = levenberg_marquardt(residual, form.parameters(), options, stable);
  form.set_parameters(lm.p);
  return lm;
}

/// The pooled free-run RMS over the records of `val`, each record from an x0
/// fitted on its own first `init_samples` samples (validation_rms per record).
double pooled_validation_rms(const LpvModel<double>& model, const Experiment<double>& val, int init_samples) {
  if (val.record_count() == 1) return validation_rms(model, val, init_samples);
  double sse = 0;
  Eigen::Index first = 0;
  for (const Eigen::Index len : val.record_lengths()) {
    const double r = validation_rms(model, select_rows(val, first, first + len), init_samples);
    sse += r * r * static_cast<double>(len);
    first += len;
  }
  return std::sqrt(sse / static_cast<double>(val.n()));
}


/// The records of `est` in the canonical order (data/record_order.h: by
/// length, then the input and output samples, lexicographically), so that
/// the order the user lists them in changes no bit of the fit: order[i] is
/// the record placed i-th.
std::vector<size_t> record_order(const Experiment<double>& est) {
  const std::vector<Eigen::Index> lengths = est.record_lengths();
  std::vector<std::pair<Eigen::Index, std::vector<double>>> keys;
  Eigen::Index first = 0;
  for (const Eigen::Index n : lengths) {
    std::vector<double> k;
    for (Eigen::Index i = first; i < first + n; ++i) {
      for (Eigen::Index j = 0; j < est.nu(); ++j) k.push_back(est.u(i, j));
      k.push_back(est.y(i, 0));
    }
    keys.emplace_back(n, std::move(k));
    first += n;
  }
  return canonical_record_order(keys);
}

LinearFit fit_in_given_order(const Experiment<double>& est, const ColumnMap& columns, const LinearFitOptions& options);

}  // namespace

LinearFit fit_linear(const Experiment<double>& est, const ColumnMap& columns, const LinearFitOptions& options) {
  check_inputs(est, options.order);
  if (est.record_count() == 1) return fit_in_given_order(est, columns, options);
  const std::vector<size_t> order = record_order(est);
  const std::vector<Eigen::Index> lengths = est.record_lengths();
  std::vector<Experiment<double>> parts;
  for (size_t r : order) {
    Eigen::Index first = 0;
    for (size_t q = 0; q < r; ++q) first += lengths[q];
    parts.push_back(select_rows(est, first, first + lengths[r]));
  }
  LinearFit fit = fit_in_given_order(stack_records(parts), columns, options);
  std::vector<Vec<double>> x0(order.size());
  for (size_t i = 0; i < order.size(); ++i) x0[order[i]] = fit.record_x0[i];
  fit.record_x0 = x0;
  fit.form.x0 = x0.front();  // the model's x0 is the first record's as the user listed them
  fit.model.x0 = x0.front();
  return fit;
}

namespace {

LinearFit fit_in_given_order(const Experiment<double>& est, const ColumnMap& columns, const LinearFitOptions& options) {
  LinearFit fit;
  RecordsForm form = records_form(arx_initialisation(est, options.order, options.offset), est);
  refit_numerator(form, est);
  const Vec<double> y = est.y.col(0);
  fit.rms_arx = rms(y - form.simulate(est));
  fit.iterations = refine(form, est, options.lm).iterations;
  fit.rms_estimation = rms(y - form.simulate(est));
  if (options.nested_denominator.size() == options.order && options.nested_denominator.allFinite() &&
      spectral_radius(options.nested_denominator) < kStableRadius) {
    RecordsForm nested = records_form(zero_observer_form(options.order, static_cast<int>(est.nu()), options.offset), est);
    nested.form.a = options.nested_denominator;
    refit_numerator(nested, est);
    const int steps = refine(nested, est, options.lm).iterations;
    const double r = rms(y - nested.simulate(est));
    if (r < fit.rms_estimation) {
      form = nested;
      fit.rms_estimation = r;
      fit.iterations = steps;
    }
  }
  fit.form = form.form;
  fit.record_x0 = {form.form.x0};
  for (const Vec<double>& x : form.more) fit.record_x0.push_back(x);
  fit.spectral_radius = spectral_radius(fit.form.a);
  fit.model = to_lpv_model(fit.form, columns);
  return fit;
}

}  // namespace

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
      choice.scores.push_back({n, fit.rms_estimation, pooled_validation_rms(fit.model, val, init_samples)});
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
