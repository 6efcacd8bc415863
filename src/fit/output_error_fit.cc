#include "fit/output_error_fit.h"
#include "fit/output_score.h"

#include <cmath>
#include <algorithm>
#include <limits>
#include <optional>

#include "core/finite_range.h"
#include "core/rms.h"
#include "fit/levenberg_marquardt.h"
#include "fit/record_states.h"
#include "model/simulate.h"
#include "model/state_scheduling.h"
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

/// Whether the slots move the coefficients of the input (output) map.
bool moves_map_coefficients(const std::vector<ParameterSlot>& slots, ParameterSlot::Where where) {
  return std::any_of(slots.begin(), slots.end(), [where](const ParameterSlot& s) { return s.where == where; });
}

/// [min, max] of the entries of m in the window's cost rows (model/static_blocks.h:
/// a polynomial map's range); empty when none is finite.
std::vector<double> cost_rows_range(const Mat<double>& m, const Window& w) {
  FiniteRange r;
  for (Eigen::Index i = w.first; i < std::min(w.last, m.rows()); ++i)
    if (i < w.skip_first || i >= w.skip_last) {
      const FiniteRange row = finite_range(m.row(i));
      r.add(row.lo);
      r.add(row.hi);
    }
  return r.any() ? std::vector<double>{r.lo, r.hi} : std::vector<double>{};
}

/// Clears the range of the input (output) map; whether there was one.
bool clear_ranges(LpvModel<double>& m, bool input, bool output) {
  bool cleared = false;
  for (auto [map, moved] : {std::pair{&m.statics.input, input}, std::pair{&m.statics.output, output}})
    if (moved && !map->range.empty()) {
      map->range.clear();
      cleared = true;
    }
  return cleared;
}

/// A polynomial map whose coefficients the fit moved gets the range of its
/// argument on the rows whose error the fit minimised (model/static_blocks.h):
/// the input map's argument is the delayed measured input, the output map's
/// ŷ + Φ of the fitted model. On those rows the map is the polynomial, so
/// the fitted outputs are unchanged; beyond them it continues linearly.
void set_fitted_ranges(LpvModel<double>& m, const Experiment<double>& exp, const Window& w, bool input, bool output) {
  if (input && m.statics.input.kind == StaticKind::kPolynomial) {
    m.statics.input.range = cost_rows_range(m.statics.delayed_input(exp.u), w);
  }
  if (output && m.statics.output.kind == StaticKind::kPolynomial) {
    const Simulation<double> s = simulate(m, exp, SimulationParts::kOutput);
    m.statics.output.range = s.yhat.allFinite() ? cost_rows_range(Mat<double>(s.yhat + s.offset), w) : std::vector<double>{};
  }
}

/// Stacked residual y − output over the window; empty when not finite.
Vec<double> residual_of_output(const Mat<double>& output, const Experiment<double>& exp, const Window& w) {
  const Eigen::Index rows = w.last - w.first;
  Mat<double> r = exp.y.middleRows(w.first, rows) - output.middleRows(w.first, rows);
  if (w.skip_first < w.skip_last) {  // drop the held-out block's rows
    const Eigen::Index a = w.skip_first - w.first, b = w.skip_last - w.first;
    Mat<double> kept(rows - (b - a), r.cols());
    kept << r.topRows(a), r.bottomRows(rows - b);
    r = std::move(kept);
  }
  if (!r.allFinite()) return {};
  return stack_rows(r);
}

/// Stacked residual y − ŷ over the window; empty when not finite.
Vec<double> residual(const LpvModel<double>& m, const Experiment<double>& exp, const Window& w) {
  return residual_of_output(simulate_output(m, exp), exp, w);
}

/// What the fit minimises at a trial point: the residual, or when the
/// simulation overflowed (empty) a huge one of the same length m, which LM rejects.
Vec<double> residual_or_huge(const Vec<double>& v, Eigen::Index m) {
  return v.size() == m ? v : Vec<double>(Vec<double>::Constant(m, 1e100));
}

/// One record from the model's own x0 (no record list): what
/// simulate_one_record simulates as simulate() would.
bool single_record(const Experiment<double>& exp) { return exp.record_count() == 1 && exp.record_x0.empty(); }

/// Whether a slot moves only the output map (C, D, the output offset, the
/// output block): the states and the scheduling do not depend on it.
bool moves_output_only(const ParameterSlot& s) {
  using W = ParameterSlot::Where;
  return s.where == W::kC || s.where == W::kD || s.where == W::kOffset || s.where == W::kOutputLower ||
         s.where == W::kOutputUpper || s.where == W::kOutputCoef;
}

/// The forward-difference Jacobian's residuals of fit_slots, the same
/// numbers as `r` (the residual of with_slot_values): a column whose slot
/// moves only the output map is the output pass on the state trajectory
/// simulated once at p (model/simulate.h, output_on_trajectory), the other
/// columns a whole simulation. Single-record experiments only.
class TrajectoryColumns {
 public:
  TrajectoryColumns(const LpvModel<double>& model, const std::vector<ParameterSlot>& slots, const Experiment<double>& exp,
                    const Window& w, Eigen::Index m, const Residual& r)
      : model_(model), slots_(slots), exp_(exp), w_(w), m_(m), r_(r) {}
  JacobianColumns columns() {
    return {[this](const Vec<double>& p) { at(p); },
            [this](const Vec<double>& q, Eigen::Index j) { return column(q, j); }};
  }

 private:
  void at(const Vec<double>& p) {
    const LpvModel<double> m = with_slot_values(model_, slots_, p);
    trajectory_ = simulate_one_record(m, exp_, SimulationParts::kOutput);
    u_model_ = m.statics.model_input(exp_.u);
  }
  Vec<double> column(const Vec<double>& q, Eigen::Index j) const {
    if (!moves_output_only(slots_[static_cast<size_t>(j)])) return r_(q);
    const Vec<double> v = residual_of_output(output_on_trajectory(with_slot_values(model_, slots_, q), trajectory_, u_model_), exp_, w_);
    return residual_or_huge(v, m_);
  }
  const LpvModel<double>& model_;
  const std::vector<ParameterSlot>& slots_;
  const Experiment<double>& exp_;
  const Window& w_;
  Eigen::Index m_;  ///< the residual's length
  const Residual& r_;
  Simulation<double> trajectory_;
  Mat<double> u_model_;
};

/// The first `last` rows of a single-record experiment. A simulation is
/// causal, so the rows after a fit's cost window never change its residual:
/// the fit of x0 on the first samples of a long record simulates only
/// those (the same numbers from far fewer rows).
Experiment<double> leading_rows(const Experiment<double>& exp, Eigen::Index last) {
  Experiment<double> e;
  e.source = exp.source;
  e.u = exp.u.topRows(last);
  e.y = exp.y.rows() >= last ? Mat<double>(exp.y.topRows(last)) : exp.y;
  e.rho = exp.rho.rows() >= last ? Mat<double>(exp.rho.topRows(last)) : exp.rho;
  return e;
}

/// Whether fit_slots may simulate leading_rows(exp, w.last) instead of exp.
bool cost_ends_early(const Experiment<double>& exp, const Window& w) {
  return w.last < exp.n() && single_record(exp);
}

}  // namespace

double prediction_rms(const LpvModel<double>& model, const Experiment<double>& exp, Eigen::Index first,
                      Eigen::Index last) {
  const Vec<double> r = residual(model, exp, window_of(exp, first, last));
  if (r.size() == 0) return std::numeric_limits<double>::infinity();
  return rms(r);
}

namespace {

/// The state the model settles in when u and ρ stay at their values of the
/// first sample: `steps` steps from `from`; empty when not finite.
Vec<double> equilibrium_at_first_sample(const LpvModel<double>& model, const Experiment<double>& exp,
                                        const Vec<double>& from, Eigen::Index steps = 2000) {
  Experiment<double> still;
  still.u = exp.u.topRows(1).replicate(steps, 1);
  still.rho = exp.rho.cols() > 0 ? Mat<double>(exp.rho.topRows(1).replicate(steps, 1)) : Mat<double>(steps, 0);
  LpvModel<double> m = model;
  m.x0 = from;
  const Simulation<double> sim = simulate(m, still);
  if (sim.x.rows() == 0 || !sim.x.allFinite()) return {};
  return sim.x.bottomRows(1).transpose();
}

}  // namespace

std::vector<Vec<double>> initial_state_starts(const LpvModel<double>& model, const Experiment<double>& exp) {
  std::vector<Vec<double>> starts{Vec<double>::Zero(model.nx)};
  const auto add = [&](const Vec<double>& x) {
    if (x.size() != model.nx || !x.allFinite()) return;
    for (const Vec<double>& s : starts)  // the same point (to rounding) is tried once
      if ((s - x).norm() <= 1e-9 * (1.0 + x.norm())) return;
    starts.push_back(x);
  };
  add(model.x0);
  if (exp.n() > 0) {
    add(equilibrium_at_first_sample(model, exp, Vec<double>::Zero(model.nx)));
    if (model.x0.size() == model.nx) add(equilibrium_at_first_sample(model, exp, model.x0));
  }
  return starts;
}

FitResult fit_initial_state(const LpvModel<double>& model, const Experiment<double>& exp, Eigen::Index samples) {
  FitOptions x0fit;
  x0fit.last_sample = std::clamp<Eigen::Index>(samples, 1, exp.n());
  FitResult best;
  best.finite = false;
  best.rms = std::numeric_limits<double>::infinity();
  best.model = model;
  best.model.x0 = Vec<double>::Zero(model.nx);
  for (const Vec<double>& start : initial_state_starts(model, exp)) {
    LpvModel<double> m = model;
    m.x0 = start;
    const FitResult f = fit_slots(m, x0_slots(m), exp, x0fit);
    if (f.finite && f.rms < best.rms) best = f;
  }
  return best;
}

double validation_rms(const LpvModel<double>& model, const Experiment<double>& val, Eigen::Index init_samples,
                      Mat<double>* yhat) {
  const FitResult f = fit_initial_state(model, val, init_samples);
  if (yhat) *yhat = simulate_output(f.model, val);
  return prediction_rms(f.model, val);
}

FreeRunScore warmup_score(const LpvModel<double>& model, const Experiment<double>& exp, Eigen::Index warmup,
                          Mat<double>* yhat) {
  if (warmup < 1 || warmup >= exp.n())
    throw std::invalid_argument("warm-up of " + std::to_string(warmup) + " samples leaves nothing to score in " +
                                std::to_string(exp.n()) + " samples");
  const FitResult f = fit_initial_state(model, exp, warmup);
  const Mat<double> out = simulate_output(f.model, exp);
  if (yhat) *yhat = out;
  FreeRunScore s;
  s.warmup = warmup;
  s.scored = exp.n() - warmup;
  const OutputScores scores = score_outputs(exp.y.bottomRows(s.scored), out.bottomRows(s.scored));
  s.rms = scores.rms_all;
  s.fit_percent = scores.fit_percent_all;
  return s;
}

namespace {

/// The model and slots of fit_slots with each record's own initial state
/// (fit/record_states.h); nullopt when they are so already or the data give
/// the records' states.
std::optional<RecordStateFit> record_states(const LpvModel<double>& model, const std::vector<ParameterSlot>& slots,
                                            const Experiment<double>& exp, const Window& w) {
  if (!exp.record_x0.empty()) return std::nullopt;
  const auto has_cost = [&w](Eigen::Index begin, Eigen::Index end) {
    const Eigen::Index a = std::max(begin, w.first), b = std::min(end, w.last);
    return a < b && !(w.skip_first <= a && b <= w.skip_last);
  };
  return with_record_states(model, slots, exp.record_lengths(), has_cost);
}

/// fit_slots' residual and its length.
struct FittedResidual {
  const Residual& r;
  Eigen::Index m;
};

/// Levenberg–Marquardt on fit_slots' residual from p0. With two or more
/// columns of the output map alone, their residuals come from one state
/// trajectory per Jacobian (the same numbers, fewer simulations).
LmResult minimise(const LpvModel<double>& model, const std::vector<ParameterSlot>& slots, const Experiment<double>& exp,
                  const Window& w, const FittedResidual& fr, const Vec<double>& p0, const Admissible& stable,
                  const FitOptions& o) {
  LmOptions lm;
  lm.max_iterations = o.max_iterations;
  lm.relative_tolerance = o.rel_tol;
  TrajectoryColumns trajectory(model, slots, exp, w, fr.m, fr.r);
  const JacobianColumns columns = trajectory.columns();
  const bool reuse = o.reuse_state_trajectory && single_record(exp) &&
                     std::count_if(slots.begin(), slots.end(), moves_output_only) >= 2;
  return levenberg_marquardt(fr.r, p0, lm, stable, reuse ? &columns : nullptr);
}

}  // namespace

FitResult fit_slots(const LpvModel<double>& model, const std::vector<ParameterSlot>& slots,
                    const Experiment<double>& exp, const FitOptions& o) {
  const Window w = window_of(exp, o.first_sample, o.last_sample, o.skip_first, o.skip_last);
  if (cost_ends_early(exp, w)) {
    FitOptions shorter = o;
    shorter.last_sample = w.last;
    return fit_slots(model, slots, leading_rows(exp, w.last), shorter);
  }
  // a polynomial map being fitted is the polynomial on every row while it is
  // fitted; its range is set from the fitted model below
  const bool input_map = moves_map_coefficients(slots, ParameterSlot::Where::kInputCoef);
  const bool output_map = moves_map_coefficients(slots, ParameterSlot::Where::kOutputCoef);
  if (LpvModel<double> open = model; clear_ranges(open, input_map, output_map)) return fit_slots(open, slots, exp, o);
  // several records: each its own initial state, fitted where the cost reaches it
  if (const std::optional<RecordStateFit> r = record_states(model, slots, exp, w)) return fit_slots(r->model, r->slots, exp, o);
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
    return residual_or_huge(v, m);
  };
  Vec<double> p = p0;
  if (p0.size() > 0) {
    const bool moves_a = std::any_of(slots.begin(), slots.end(),
                                     [](const ParameterSlot& s) { return s.where == ParameterSlot::Where::kA; });
    Admissible stable = nullptr;
    if (moves_a)
      stable = [&](const Vec<double>& q) { return constant_a_radius(with_slot_values(model, slots, q)) < o.max_radius; };
    if (stable && !stable(p0)) {
      // a start whose constant A is not stable on its own: a store (A = I)
      // kept bounded by a state nonlinearity (√ outflow, overflow) is fitted,
      // judged by whether its simulation stays finite, like ρ-dependent A
      // terms; any other unstable start is not moved (its free run is judged as it is)
      if (state_scheduled(model.columns.rho, model.nx).empty() || model.state_offset.empty()) {
        res.rms = std::sqrt(r0.squaredNorm() / static_cast<double>(m));
        set_fitted_ranges(res.model, exp, w, input_map, output_map);
        return res;
      }
      stable = nullptr;
    }
    const LmResult fit = minimise(model, slots, exp, w, FittedResidual{r, m}, p0, stable, o);
    p = fit.p;
    res.iterations = fit.iterations;
  }
  res.model = with_slot_values(model, slots, p);
  set_fitted_ranges(res.model, exp, w, input_map, output_map);
  const Vec<double> rf = residual(res.model, exp, w);
  res.finite = rf.size() == m;
  res.rms = res.finite ? std::sqrt(rf.squaredNorm() / static_cast<double>(m)) : std::numeric_limits<double>::infinity();
  return res;
}

}  // namespace lpvid
