#include "diagnose/diagnose.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <cstdio>
#include <mutex>

#include "core/deadline.h"
#include "data/fitting_precision.h"
#include "core/input_error.h"
#include "core/parallel_for.h"
#include "diagnose/effect_reading.h"
#include "diagnose/record_windows.h"
#include "data/experiment_builder.h"
#include "fit/output_error_fit.h"
#include "fit/output_score.h"
#include "model/simulate.h"
#include "solvers/solver_factory.h"

namespace lpvid {

BoundsSummary DiagnoseResult::bounds_summary(DiagnoseSide side) const {
  const std::vector<WindowBounds>& ws = side == DiagnoseSide::kBefore ? before : after;
  BoundsSummary s;
  s.all_verified = !ws.empty();
  for (const WindowBounds& w : ws) {
    s.all_verified = s.all_verified && w.bounds.verified();
    s.delta = std::max(s.delta, w.bounds.delta);
    s.dmax = std::max(s.dmax, w.bounds.dmax);
    s.uninformative += w.bounds.verified() && !w.informative ? 1 : 0;
  }
  return s;
}

bool TestScore::after_worse() const {
  if (!std::isfinite(after.rms)) return std::isfinite(before.rms);
  return std::isfinite(before.rms) && after.rms > before.rms;
}

bool DiagnoseResult::verified() const {
  return before.size() == after.size() && bounds_summary(DiagnoseSide::kBefore).all_verified &&
         bounds_summary(DiagnoseSide::kAfter).all_verified;
}

namespace {

/// [min, max] of m padded by 10 % of its width.
MapRange padded_range(const Mat<double>& m) {
  const double lo = m.minCoeff(), hi = m.maxCoeff(), pad = 0.1 * std::max(hi - lo, 1e-12);
  return {lo - pad, hi + pad};
}

/// DiagnoseResult::input_map_range, output_map_range.
void set_map_ranges(DiagnoseResult& out, const Experiment<double>& est_d) {
  const StaticBlocks<double>& st = out.after_model.statics;
  if (!st.input.is_identity()) out.input_map_range = padded_range(est_d.u);
  if (st.has_output()) {
    const Simulation<double> sim = simulate(out.after_model, est_d);
    const Mat<double> v = sim.yhat + sim.offset;  // g_out's argument along the estimation record
    out.output_map_range = padded_range(v.allFinite() ? v : est_d.y);
  }
}

}  // namespace

FreeRunScore pooled_test_score(const std::vector<Experiment<double>>& tests, const std::vector<const Mat<double>*>& yhat,
                               Eigen::Index warmup) {
  FreeRunScore s;
  s.warmup = warmup;
  for (const Experiment<double>& t : tests) s.scored += t.n() - warmup;
  if (tests.empty()) return s;
  Mat<double> y(s.scored, tests[0].ny()), f(s.scored, tests[0].ny());
  Eigen::Index row = 0;
  for (size_t t = 0; t < tests.size(); ++t) {
    const Eigen::Index m = tests[t].n() - warmup;
    y.middleRows(row, m) = tests[t].y.bottomRows(m);
    const bool ok = yhat[t]->rows() == tests[t].n() && yhat[t]->cols() == y.cols();
    f.middleRows(row, m) = ok ? Mat<double>(yhat[t]->bottomRows(m)) : Mat<double>::Constant(m, y.cols(), std::nan(""));
    row += m;
  }
  const OutputScores sc = score_outputs(y, f);  // the one-set formulas over the pooled samples
  s.rms = sc.rms_all;
  s.fit_percent = sc.fit_percent_all;
  return s;
}

CertifyOptions diagnose_policy(CertifyOptions base) {
  base.lower_end = false;
  base.full_horizon_limit = 0;
  base.scale_signals = true;
  base.progress = nullptr;
  return base;
}

CertifyOutcome DiagnoseResult::outcome() const { return verified() ? CertifyOutcome::kVerified : CertifyOutcome::kNotVerified; }

namespace {

void check_options(const Experiment<double>& est_d, const Experiment<Rational>& est_q,
                   const Experiment<double>& selection, const std::vector<Experiment<double>>& tests,
                   const DiagnoseOptions& o, const std::vector<RowWindow>& windows) {
  if (windows.empty()) throw InputError("diagnose: the estimation record is empty");
  if (est_d.n() != est_q.n()) throw InputError("diagnose: the exact and double estimation records differ in length");
  const Eigen::Index need = o.ranking.init_samples + 5;
  if (selection.n() != 0 && selection.n() < need) throw InputError("the validation data has too few samples");
  if (o.test_warmup < 1) throw InputError("the test warm-up must be at least 1 sample");
  for (size_t t = 0; t < tests.size(); ++t)
    if (tests[t].n() < o.test_warmup + 5)
      throw InputError("test set " + std::to_string(t + 1) + " has " + std::to_string(tests[t].n()) +
                       " samples: too few for a warm-up of " + std::to_string(o.test_warmup) + " and a score");
  if (o.threads > 1 && !o.make_solver) throw InputError("diagnose: threads > 1 needs a solver factory");
  for (const auto& [b, e] : windows)
    if (b < 0 || e <= b || e > est_q.n())
      throw InputError("--window " + std::to_string(b) + ":" + std::to_string(e) + " is outside the " +
                       std::to_string(est_q.n()) + " estimation samples");
}

/// The residual the report shows, before and after (ShownRecord).
ShownRecord shown_record(const DiagnoseResult& out, const Experiment<double>& est_d, const Experiment<double>& selection,
                         const DiagnoseOptions& options) {
  ShownRecord s;
  s.last_fold = selection.n() == 0 && !out.rank.fold_blocks.empty();
  s.init_samples = s.last_fold ? options.ranking.fold_warmup : options.ranking.init_samples;
  if (s.last_fold) {
    s.first = out.rank.fold_blocks.back().first;
    s.data = select_rows(est_d, out.rank.fold_blocks.back().first, out.rank.fold_blocks.back().last);
  } else {
    s.data = selection;
  }
  validation_rms(out.before_model, s.data, s.init_samples, &s.y_before);
  validation_rms(out.after_model, s.data, s.init_samples, &s.y_after);
  s.finite = s.y_before.allFinite() && s.y_after.allFinite();
  if (s.finite) {
    s.before = analyse_residual(Mat<double>(s.data.y - s.y_before), s.data.u, {});
    s.after = analyse_residual(Mat<double>(s.data.y - s.y_after), s.data.u, {});
  }
  return s;
}

}  // namespace

namespace {

/// The threads that certify the windows (certify_windows).
unsigned bound_threads(const DiagnoseOptions& options) { return options.make_solver ? std::max(1u, options.threads) : 1u; }

/// What the certification at the end will cost, said before any work: the
/// sequential estimate shared by the threads that run the 2·W certifications.
void announce_bound_cost(const std::vector<RowWindow>& windows, const LpvModel<double>& declared, const DiagnoseOptions& options) {
  if (!options.ranking.progress) return;
  const BoundCost cost = estimate_bound_cost(windows, declared.ny, declared.nz(), options.certify.lower_end);
  const size_t parallel = std::min<size_t>(bound_threads(options), 2 * windows.size());
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "bounds at the end: %zu windows x (before, after), expected roughly %.0f s on %zu thread%s (at idle) and "
                "%.1f MB of certificates%s (--max-windows N caps the windows%s)",
                windows.size(), cost.seconds / static_cast<double>(parallel), parallel, parallel == 1 ? "" : "s",
                cost.megabytes,
                options.certify.lower_end ? " with the lower ends' dual certificates" : "",
                options.certify.lower_end ? "; without --lower-ends no dual certificates are written" : "");
  options.ranking.progress(buf);
}

/// The bound windows as joint windows (diagnose/record_windows.h): one
/// piece each for one record, the records' windows side by side for several.
std::vector<JointWindow> bound_windows(const Experiment<double>& est_d, const DiagnoseOptions& options) {
  if (est_d.record_count() == 1) {
    std::vector<JointWindow> out;
    for (const RowWindow& w :
         spread_windows(options.windows.empty() ? default_bound_windows(est_d.n()) : options.windows, options.max_windows))
      out.push_back({w});
    return out;
  }
  const std::vector<JointWindow> all = joint_windows(est_d.record_lengths(), options.windows);
  std::vector<RowWindow> index;  // spread_windows picks among the joint windows by their index
  for (size_t i = 0; i < all.size(); ++i) index.emplace_back(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i));
  std::vector<JointWindow> out;
  for (const RowWindow& i : spread_windows(index, options.max_windows)) out.push_back(all[static_cast<size_t>(i.first)]);
  return out;
}

/// Every piece of every joint window (the checks), and one window of each
/// joint window's total length (the cost estimate).
std::vector<RowWindow> all_pieces(const std::vector<JointWindow>& joint, bool total) {
  std::vector<RowWindow> out;
  for (const JointWindow& w : joint) {
    Eigen::Index len = 0;
    for (const RowWindow& p : w) {
      if (!total) out.push_back(p);
      len += p.second - p.first;
    }
    if (total) out.emplace_back(0, len);
  }
  return out;
}

/// Step 3: Theorem 2.1 on every window, before and after: one independent
/// job each (core/parallel_for.h); SDP solves serialise inside
/// (solvers/sdp_solver.cc).
void certify_windows(DiagnoseResult& out, const std::vector<JointWindow>& windows, const ExperimentViews& est,
                     const DiagnoseOptions& options, SdpSolver& solver) {
  out.before.resize(windows.size());
  out.after.resize(windows.size());
  const unsigned threads = bound_threads(options);
  std::mutex report;
  size_t done = 0;
  const auto started = std::chrono::steady_clock::now();  // the progress lines' rate only
  parallel_for(2 * windows.size(), threads, [&](size_t job) {
    check_deadline("the bounds were certified");
    const size_t i = job / 2;
    const bool after = job % 2 == 1;
    auto own = threads > 1 ? options.make_solver() : nullptr;
    WindowBounds& w = (after ? out.after : out.before)[i];
    const LpvModel<double>& model = after ? out.after_model : out.before_model;
    w = certify_joint_window(model, est, windows[i], options.certify, own ? *own : solver);
    if (options.on_bound) options.on_bound(w, i, windows.size(), after);
    if (options.ranking.progress) {
      const std::lock_guard<std::mutex> lock(report);
      const size_t k = ++done;
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      const std::string fell = w.bounds.fallback.empty() ? "" : " (" + w.bounds.fallback + ")";
      options.ranking.progress("bounds (Theorem 2.1), " + std::to_string(k) + " of " +
                               std::to_string(2 * windows.size()) + ": window " + std::to_string(i + 1) + " " +
                               (after ? "after" : "before") + ": " +
                               (w.bounds.verified() ? "verified" + fell + (w.certificate.empty() ? std::string() : ", " + w.certificate)
                                                   : "NOT verified (" + w.bounds.reason + ")") +
                               "; " + observed_rate_text(k, 2 * windows.size(), elapsed));
    }
  });
}

/// Step 4: the test role, scored once per test set, after everything else was chosen.
void score_tests(DiagnoseResult& out, const Experiment<double>& estimation, const std::vector<Experiment<double>>& tests,
                 const DiagnoseOptions& options) {
  for (const Experiment<double>& test : tests) {
    TestScore t;
    t.samples = test.n();
    t.excursions = signal_excursions(estimation, test);
    t.before = warmup_score(out.before_model, test, options.test_warmup, &t.y_before);
    t.after = warmup_score(out.after_model, test, options.test_warmup, &t.y_after);
    out.tests.push_back(t);
  }
  if (tests.size() < 2) return;
  std::vector<const Mat<double>*> before, after;
  for (const TestScore& t : out.tests) {
    before.push_back(&t.y_before);
    after.push_back(&t.y_after);
  }
  out.pooled_before = pooled_test_score(tests, before, options.test_warmup);
  out.pooled_after = pooled_test_score(tests, after, options.test_warmup);
}

}  // namespace

DiagnoseResult diagnose(const LpvModel<double>& declared, const ExperimentViews& est,
                        const Experiment<double>& selection_data, const std::vector<Experiment<double>>& test_data,
                        const DiagnoseOptions& options, SdpSolver& solver) {
  // every fit, score and choice reads the data at the fits' precision
  // (data/fitting_precision.h); the certificates read est_q, the data as written
  // (copied here beside its double view at that precision)
  const ExperimentViews views{est.exp_q, at_fitting_precision(est.exp_d)};
  const Experiment<double> selection = at_fitting_precision(selection_data);
  const auto& [est_q, est_d] = views;
  std::vector<Experiment<double>> tests;
  for (const Experiment<double>& t : test_data) tests.push_back(at_fitting_precision(t));
  const std::vector<JointWindow> windows = bound_windows(est_d, options);
  check_options(est_d, est_q, selection, tests, options, all_pieces(windows, false));
  announce_bound_cost(all_pieces(windows, true), declared, options);

  // 1. effects: fitted on the estimation data, chosen on the selection data
  DiagnoseResult out;
  out.rank = rank_effects(declared, est_d, selection, options.ranking);
  // 2. the numbers the certificates state
  out.before_model = round_fitted_model(out.rank.before);
  out.after_model = round_fitted_model(out.rank.after);
  restate_parameters(out.rank, out.after_model);  // the report's values are the certified model's
  read_effects(out.rank, est_d);                   // what the fitted parameters make each effect
  out.before_model.signal_info = out.after_model.signal_info = declared.signal_info;  // fits build new models

  // 3. Theorem 2.1 on every window; Theorem 3.1 on the first
  certify_windows(out, windows, views, options, solver);
  if (options.ranking.progress) options.ranking.progress("Theorem 3.1 on the first window, before and after");
  // optional: a failure here is this stage's (WindowIdentification::failed); every result above stands
  for (auto [model, id] : {std::pair{&out.before_model, &out.before_id}, std::pair{&out.after_model, &out.after_id}}) {
    *id = try_identify_on_window(*model, views, windows[0][0].first, windows[0][0].second, options.certify, solver);
    judge_against_window(*id, model == &out.before_model ? out.before.front() : out.after.front());
    if (!id->failed.empty() && options.ranking.progress) options.ranking.progress(id->failed + " (the diagnosis stands)");
  }
  // 4. the test role
  score_tests(out, est_d, tests, options);
  // 5. what the report shows beside the numbers above
  out.shown = shown_record(out, est_d, selection, options);
  validation_rms(out.after_model, est_d, out.shown.init_samples, &out.estimation_after);
  set_map_ranges(out, est_d);
  out.estimation_records = score_records(out.before_model, out.after_model, est.exp_d);  // the data as written
  if (!out.estimation_after.allFinite()) out.estimation_after.resize(0, 0);
  return out;
}

}  // namespace lpvid
