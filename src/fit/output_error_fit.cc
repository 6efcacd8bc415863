#include "fit/output_error_fit.h"

#include <cmath>
#include <algorithm>
#include <limits>

#include "core/rms.h"
#include "fit/levenberg_marquardt.h"
#include "model/simulate.h"
#include "toeplitz/signal_toeplitz.h"

namespace lpvid {

namespace {

struct Window {
  Eigen::Index first = 0, last = 0;
};

Window window_of(const Experiment<double>& exp, Eigen::Index first, Eigen::Index last) {
  Window w{first, last < 0 ? exp.n() : last};
  if (w.first < 0 || w.first >= w.last || w.last > exp.n())
    throw std::invalid_argument("fit window [" + std::to_string(first) + ", " + std::to_string(last) +
                                ") is empty or outside the " + std::to_string(exp.n()) + " samples");
  return w;
}

/// Stacked residual y − ŷ over the window; empty when not finite.
Vec<double> residual(const LpvModel<double>& m, const Experiment<double>& exp, const Window& w) {
  const Simulation<double> sim = simulate(m, exp);
  const Eigen::Index rows = w.last - w.first;
  const Mat<double> r = exp.y.middleRows(w.first, rows) - sim.output.middleRows(w.first, rows);
  if (!r.allFinite()) return {};
  return stack_rows(r);
}

}  // namespace

double prediction_rms(const LpvModel<double>& model, const Experiment<double>& exp, Eigen::Index first,
                      Eigen::Index last) {
  const Vec<double> r = residual(model, exp, window_of(exp, first, last));
  if (r.size() == 0) return std::numeric_limits<double>::infinity();
  return rms(r);
}

double validation_rms(const LpvModel<double>& model, const Experiment<double>& val, Eigen::Index init_samples,
                      Mat<double>* yhat) {
  LpvModel<double> m = model;
  m.x0 = Vec<double>::Zero(model.nx);
  const Eigen::Index k = std::clamp<Eigen::Index>(init_samples, 1, val.n());
  FitOptions x0fit;
  x0fit.last_sample = k;
  const FitResult f = fit_slots(m, x0_slots(m), val, x0fit);
  if (yhat) *yhat = simulate(f.model, val).output;
  return prediction_rms(f.model, val);
}

FitResult fit_slots(const LpvModel<double>& model, const std::vector<ParameterSlot>& slots,
                    const Experiment<double>& exp, const FitOptions& o) {
  const Window w = window_of(exp, o.first_sample, o.last_sample);
  FitResult res;
  res.model = model;
  const Vec<double> p0 = slot_values(model, slots);
  const Vec<double> r0 = residual(model, exp, w);
  if (r0.size() == 0) {
    res.finite = false;
    res.rms = std::numeric_limits<double>::infinity();
    return res;
  }
  // a trial point whose simulation overflows gets a huge residual: LM rejects it
  const Eigen::Index m = r0.size();
  const Residual r = [&](const Vec<double>& p) {
    const Vec<double> v = residual(with_slot_values(model, slots, p), exp, w);
    return v.size() == m ? v : Vec<double>(Vec<double>::Constant(m, 1e100));
  };
  Vec<double> p = p0;
  if (p0.size() > 0) {
    LmOptions lm;
    lm.max_iterations = o.max_iterations;
    lm.relative_tolerance = o.rel_tol;
    const bool moves_a = std::any_of(slots.begin(), slots.end(),
                                     [](const ParameterSlot& s) { return s.where == ParameterSlot::Where::kA; });
    Admissible stable = nullptr;
    if (moves_a)
      stable = [&](const Vec<double>& q) { return constant_a_radius(with_slot_values(model, slots, q)) < o.max_radius; };
    if (stable && !stable(p0)) {
      res.rms = std::sqrt(r0.squaredNorm() / static_cast<double>(m));
      return res;  // an unstable start is not moved (its free run is judged as it is)
    }
    const LmResult fit = levenberg_marquardt(r, p0, lm, stable);
    p = fit.p;
    res.iterations = fit.iterations;
  }
  res.model = with_slot_values(model, slots, p);
  const Vec<double> rf = residual(res.model, exp, w);
  res.finite = rf.size() == m;
  res.rms = res.finite ? std::sqrt(rf.squaredNorm() / static_cast<double>(m)) : std::numeric_limits<double>::infinity();
  return res;
}

}  // namespace lpvid
