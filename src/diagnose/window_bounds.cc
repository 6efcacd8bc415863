#include "diagnose/window_bounds.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/deadline.h"
#include "core/rms.h"
#include "core/input_error.h"
#include "data/experiment_builder.h"
#include "diagnose/effect_candidates.h"
#include "diagnose/record_windows.h"
#include "model/model_file.h"
#include "model/simulate.h"

namespace lpvid {

namespace {

double round_digits(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return std::stod(buf);
}

}  // namespace

LpvModel<double> round_fitted_model(const LpvModel<double>& m, int digits) {
  const std::vector<ParameterSlot> slots = with_dynamics_slots(refit_slots(m), m);
  Vec<double> p = slot_values(m, slots);
  for (Eigen::Index i = 0; i < p.size(); ++i) p(i) = round_digits(p(i), digits);
  return with_slot_values(m, slots, p);
}

LpvModel<Rational> exact_model(const LpvModel<double>& m, const Vec<double>& x0) {
  LpvModel<double> c = m;
  c.x0 = x0;
  for (Eigen::Index i = 0; i < c.x0.size(); ++i) c.x0(i) = round_digits(c.x0(i), 12);
  // the JSON text of a double is its shortest round-trip decimal: read exactly
  return parse_model_json<Rational>(write_model_json(c), "fitted model");
}

WindowBounds certify_window(const LpvModel<double>& model, const ExperimentViews& est, Eigen::Index begin,
                            Eigen::Index end, CertifyOptions options, SdpSolver& solver) {
  const auto& [est_q, est_d] = est;
  if (begin < 0 || end <= begin || end > est_q.n())
    throw InputError("bound window " + std::to_string(begin) + ":" + std::to_string(end) + " is outside the " +
                     std::to_string(est_q.n()) + " estimation samples");
  WindowBounds w;
  w.begin = begin;
  w.end = end;
  const DataReference rows = piece_reference(options.records, est_q.record_lengths(), {begin, end});
  w.file_begin = rows.row_begin;
  w.file_end = rows.row_end;
  if (!options.records.empty()) options.records = {rows};  // the certificate names the window's file rows
  try {
    const Simulation<double> sim = simulate(model, est_d);
    const Vec<double> xb = model.nx > 0 ? Vec<double>(sim.x.row(begin).transpose()) : Vec<double>();
    w.model = exact_model(model, xb);
    w.bounds = certify_fixed_model(w.model, select_rows(est_q, begin, end), options, solver);
  } catch (const RunStopped&) {
    throw;  // the user's --timeout or a requested stop ends the run, not a window or a stage
  } catch (const std::exception& e) {
    // this window's failure (a diverging free run, z = 0 on its rows, a solver
    // error): not verified, with the reason; the other windows and every
    // result before this stage stand
    w.bounds = CertifiedBounds{};
    w.bounds.reason = std::string("certification failed on this window: ") + e.what();
  }
  judge_informative(w, est_d.y.middleRows(begin, end - begin));
  return w;
}

namespace {

/// The pieces stacked as records, each from the model's exact state at its first row.
Experiment<Rational> joint_data(const LpvModel<double>& model, const Experiment<double>& est_d,
                                const Experiment<Rational>& est_q, const std::vector<RowWindow>& pieces,
                                LpvModel<Rational>& exact) {
  const Simulation<double> sim = simulate(model, est_d);
  std::vector<Experiment<Rational>> parts;
  std::vector<Vec<Rational>> x0;
  for (const auto& [b, e] : pieces) {
    const Vec<double> xb = model.nx > 0 ? Vec<double>(sim.x.row(b).transpose()) : Vec<double>();
    LpvModel<Rational> m = exact_model(model, xb);
    x0.push_back(m.x0);
    if (parts.empty()) exact = std::move(m);
    Experiment<Rational> part = select_rows(est_q, b, e);
    part.records.clear();
    part.record_x0.clear();
    parts.push_back(std::move(part));
  }
  Experiment<Rational> out = stack_records(parts);
  out.record_x0 = x0;
  return out;
}

}  // namespace

WindowBounds certify_joint_window(const LpvModel<double>& model, const ExperimentViews& est,
                                  const std::vector<RowWindow>& pieces, CertifyOptions options, SdpSolver& solver) {
  const auto& [est_q, est_d] = est;
  if (pieces.size() == 1) return certify_window(model, est, pieces[0].first, pieces[0].second, options, solver);
  for (const auto& [b, e] : pieces)
    if (b < 0 || e <= b || e > est_q.n())
      throw InputError("bound window " + std::to_string(b) + ":" + std::to_string(e) + " is outside the " +
                       std::to_string(est_q.n()) + " estimation samples");
  WindowBounds w;
  w.pieces = pieces;
  Mat<double> y(0, est_d.ny());
  for (const auto& [b, e] : pieces) {
    w.records.push_back(piece_reference(options.records, est_d.record_lengths(), {b, e}));
    y.conservativeResize(y.rows() + (e - b), Eigen::NoChange);
    y.bottomRows(e - b) = est_d.y.middleRows(b, e - b);
  }
  w.begin = pieces[0].first;
  w.end = pieces[0].second;
  w.file_begin = w.records[0].row_begin;
  w.file_end = w.records[0].row_end;
  options.records = w.records;
  try {
    const Experiment<Rational> data = joint_data(model, est_d, est_q, pieces, w.model);
    w.bounds = certify_fixed_model(w.model, data, options, solver);
  } catch (const RunStopped&) {
    throw;
  } catch (const std::exception& e) {
    w.bounds = CertifiedBounds{};
    w.bounds.reason = std::string("certification failed on this joint window: ") + e.what();
  }
  judge_informative(w, y);
  return w;
}

void judge_informative(WindowBounds& w, const Mat<double>& y) {
  w.rms_output = rms(y);
  w.rms_variation = y.size() == 0 ? 0.0 : rms(Mat<double>(y.rowwise() - y.colwise().mean()));
  if (!w.bounds.verified()) {
    w.informative = false;
    w.note = "not verified";
    return;
  }
  w.informative = w.bounds.dmax < w.rms_variation;
  char buf[260];
  std::snprintf(buf, sizeof buf,
                "dmax %.4g %s the RMS %.4g of the measured output's deviation from its mean on these rows%s",
                w.bounds.dmax, w.informative ? "is below" : ">=", w.rms_variation,
                w.informative ? "" : ": uninformative (the constant model y = mean meets dmax = that RMS)");
  w.note = buf;
}

}  // namespace lpvid
