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
  Eigen::Index skip_first = 0, skip_last = 0;  ///< rows left out of the cost (empty if skip_first >= skip_last)
};

Window window_of(const Experiment<double>& exp, Eigen::Index first, Eigen::Index last, Eigen::Index skip_first = 0,
                 Eigen::Index skip_last = 0) {
  Window w{first, last < 0 ? exp.n() : last, std::max(skip_first, first), std::min(skip_last, last < 0 ? exp.n() : last)};
  if (w.first < 0 || w.first >= w.last || w.last > exp.n())
    throw std::invalid_argument("fit window [" + std::to_string(first) + ", " + std::to_string(last) +
                                ") is empty or outside the " + std::to_string(exp.n()) + " samples");
  if (w.skip_first < w.skip_last && w.skip_last - w.skip_first >= w.last - w.first)
    throw std::invalid_argument("the held-out block [" + std::to_string(skip_first) + ", " + std::to_string(skip_last) +
                                ") leaves no sample of the fit window [" + std::to_string(w.first) + ", " +
                                std::to_string(w.last) + ")");
  return w;
}

/// Stacked residual y − ŷ over the window; empty when not finite.
Vec<double> residual(const LpvModel<double>& m, const Experiment<double>& exp, const Window& w) {
  const Simulation<double> sim = simulate(m, exp);
  const Eigen::Index rows = w.last - w.first;
  Mat<double> r = exp.y.middleRows(w.first, rows) - sim.output.middleRows(w.first, rows);
  if (w.skip_first < w.skip_last) {  // drop the held-out block's rows
    const Eigen::Index a = w.skip_first - w.first, b = w.skip_last - w.first;
    Mat<double> kept(rows - (b - a), r.cols());
    kept << r.topRows(a), r.bottomRows(rows - b);
    r = std::move(kept);
  }
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

FreeRunScore warmup_score(const LpvModel<double>& model, const Experiment<double>& exp, Eigen::Index warmup,
                          Mat<double>* yhat) {
  if (warmup < 1 || warmup >= exp.n())
    throw std::invalid_argument("warm-up of " + std::to_string(warmup) + " samples leaves nothing to score in " +
                                std::to_string(exp.n()) + " samples");
  LpvModel<double> m = model;
  m.x0 = Vec<double>::Zero(model.nx);
  FitOptions x0fit;
  x0fit.last_sample = warmup;
  const FitResult f = fit_slots(m, x0_slots(m), exp, x0fit);
  const Mat<double> out = simulate(f.model, exp).output;
  if (yhat) *yhat = out;
  FreeRunScore s;
  s.warmup = warmup;
  s.scored = exp.n() - warmup;
  const Mat<double> y = exp.y.bottomRows(s.scored);
  const Mat<double> e = y - out.bottomRows(s.scored);
  if (!e.allFinite()) {
    s.rms = std::numeric_limits<double>::infinity();
    s.fit_percent = -std::numeric_limits<double>::infinity();
    return s;
  }
  s.rms = std::sqrt(e.squaredNorm() / static_cast<double>(e.size()));
  const Mat<double> centred = y.rowwise() - y.colwise().mean();
  const double spread = centred.norm();
  s.fit_percent = spread > 0 ? 100.0 * (1.0 - e.norm() / spread) : -std::numeric_limits<double>::infinity();
  return s;
}

FitResult fit_slots(const LpvModel<double>& model, const std::vector<ParameterSlot>& slots,
                    const Experiment<double>& exp, const FitOptions& o) {
  const Window w = window_of(exp, o.first_sample, o.last_sample, o.skip_first, o.skip_last);
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
