#pragma once
/// The closed loop of docs/design.md §9 as one library call (`lpvid diagnose` is a
/// front end to it, other programs can call it directly):
///
///   1. rank effects: every candidate is fitted and scored on held-out folds
///      of the ESTIMATION record (selection empty), or fitted on it and
///      scored on the SELECTION data (diagnose/effect_ranking.h);
///   2. fix: the models before and after are rounded to 12 significant digits
///      (diagnose/window_bounds.h), the numbers the certificates state;
///   3. certify: Theorem 2.1 on each bound window of the estimation record,
///      before and after, each certificate re-checked exactly
///      (diagnose/window_bounds.h), then Theorem 3.1 on the first window
///      (diagnose/window_identification.h);
///   4. test: only now, and only if a test set is given, the two chosen
///      models are scored on it by the benchmark protocol of docs/design.md §9.5: x0
///      from the first `test_warmup` samples, RMS and fit % over the rest.
///      It is the last step and nothing above reads it.
///
/// `lpvid diagnose` parses its options into these types, calls `diagnose`
/// and renders the result (src/cli/diagnose_report.h).
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "data/experiment.h"
#include "data/experiment_views.h"
#include "diagnose/bound_windows.h"
#include "diagnose/signal_ranges.h"
#include "diagnose/effect_ranking.h"
#include "diagnose/record_scores.h"
#include "diagnose/residual_analysis.h"
#include "diagnose/window_bounds.h"
#include "diagnose/window_identification.h"
#include "certify/certify.h"
#include "solvers/sdp_solver.h"

namespace lpvid {

/// `base` with the certification policy of diagnose: no lower ends (a dual
/// certificate per window is about 60 MB at 200 SISO rows, and the report
/// states the upper ends); with many windows, no extra full-horizon solve
/// (full_horizon_limit 0: a lower end, when asked for, comes from the K-tap
/// solve's dual lifted to the full horizon); the weighted objective on
/// unit-RMS signals (scale_signals, certify/bound_scaling.h); no per-stage
/// progress (windows run in parallel; diagnose reports each window).
CertifyOptions diagnose_policy(CertifyOptions base);

struct DiagnoseOptions {
  RankingOptions ranking;
  /// Windows of the estimation record on which the bounds are certified;
  /// empty: default_bound_windows (diagnose/bound_windows.h).
  std::vector<RowWindow> windows;
  /// At most this many of those windows (spread_windows: evenly over the
  /// record, first and last kept); 0: all. A 10 000-sample record has 50
  /// default windows.
  size_t max_windows = 0;
  /// Options of every certificate, with diagnose's policy (diagnose_policy)
  /// by default. `certify.records` is where each estimation record's rows are
  /// in its file (its window as read), in stacking order: every certificate
  /// names the file rows of its window (several records: of each piece of a
  /// joint window, diagnose/record_windows.h). The certificates stay in the
  /// result (WindowBounds::bounds); the front end names and writes them.
  CertifyOptions certify = diagnose_policy(CertifyOptions{});
  /// Called from the certifying job's thread as soon as a window's bound is
  /// certified (`window` of `windows`, before or after): a front end writes
  /// its certificates then and names the file in w.certificate (which the
  /// progress line then shows), so that files appear as the run goes. Unset:
  /// nothing is written.
  std::function<void(WindowBounds& w, size_t window, size_t windows, bool after)> on_bound;
  /// Windows certified at once; > 1 needs `make_solver` (one backend per
  /// job). Results do not depend on it.
  unsigned threads = 1;
  std::function<std::unique_ptr<SdpSolver>()> make_solver;
  /// The test part's warm-up (docs/design.md §9.5: cascaded tanks 50, Silverbox 50,
  /// coupled electric drives 10): used for x0, left out of the RMS.
  Eigen::Index test_warmup = kValidationInitSamples;
};

/// The test role's score by the benchmark protocol (fit/output_error_fit.h
/// warmup_score), before and after.
struct TestScore {
  Eigen::Index samples = 0;
  FreeRunScore before, after;
  Mat<double> y_before, y_after;  ///< the two models' free runs on the test record (x0 from its warm-up)
  /// Each measured signal of the test record against its range on the
  /// estimation records (diagnose/signal_ranges.h).
  std::vector<SignalExcursion> excursions;
  /// The model after scores a larger test RMS than the model before (or
  /// only the model before has a finite one). Stated in the report, never
  /// used to choose: the test record is scored after every choice.
  bool after_worse() const;
};

/// An interval of a static map's argument: where the report draws the
/// fitted map (the estimation record's range, padded by 10 %).
struct MapRange {
  double lo = 0, hi = 0;
};

/// The record the report analyses the residual on: the selection record, or
/// in fold mode (no selection record) the estimation record's last fold
/// block (the final models saw those rows too). Free runs with x0 fitted on
/// the first `init_samples` samples (fit/output_error_fit.h validation_rms).
struct ShownRecord {
  Experiment<double> data;
  bool last_fold = false;
  Eigen::Index first = 0;         ///< last_fold: its first row in the estimation record
  Eigen::Index init_samples = 0;
  Mat<double> y_before, y_after;  ///< the models' free runs on `data`
  bool finite = false;            ///< both free runs finite; only then are the analyses filled
  ResidualAnalysis before, after; ///< of data.y − y_before and data.y − y_after (residual_analysis.h)
};

/// The bound windows of one model (before or after) summarised: what the
/// text report, the JSON report and the figures state about them.
struct BoundsSummary {
  bool all_verified = false;  ///< at least one window, and every one verified
  /// The largest δ and d_max over the windows (each window satisfies them on
  /// its own rows; nothing is claimed across windows). Meaningful when all_verified.
  double delta = 0, dmax = 0;
  int uninformative = 0;      ///< verified windows whose d_max does not beat the constant model (WindowBounds::informative)
};

/// Which model of a diagnosis: the declared one or the one with the effects.
enum class DiagnoseSide { kBefore, kAfter };

struct DiagnoseResult {
  RankingResult rank;
  LpvModel<double> before_model, after_model;  ///< as rounded for the certificates
  std::vector<WindowBounds> before, after;     ///< one per bound window, same windows
  WindowIdentification before_id, after_id;    ///< Theorem 3.1 on the first window
  std::vector<TestScore> tests;                ///< one per test set given, in their order
  /// Over every test set: RMS over all their scored samples (each set from
  /// its own warm-up) and fit % against the pooled scored outputs' deviation
  /// from their mean (pooled_test_score).
  FreeRunScore pooled_before, pooled_after;
  ShownRecord shown;
  /// The free-run scores of the models before and after on each estimation
  /// record (Experiment::records; one record: that record) and pooled.
  RecordScores estimation_records;
  /// The after model's free run on the estimation record (empty if not finite).
  Mat<double> estimation_after;
  /// The after model's static maps are drawn over these ranges (set when
  /// the map is not the identity): u on the estimation record; v = ŷ + Φ
  /// along it (the model's own x0; y's range when v is not finite).
  std::optional<MapRange> input_map_range, output_map_range;
  /// The windows of `side` summarised.
  BoundsSummary bounds_summary(DiagnoseSide side) const;
  /// Every window's bound, before and after, verified exactly.
  bool verified() const;
  /// kVerified when verified(), else kNotVerified (the report states each
  /// window's own outcome and reason).
  CertifyOutcome outcome() const;
};

/// The pooled score of several test sets' free runs: RMS over every scored
/// sample of every set, fit % = 100·(1 − ‖y − ŷ‖/‖y − ȳ‖) over them all (ȳ
/// per output over all scored samples); `yhat[t]` is set t's free run, its
/// first `warmup` rows not scored.
FreeRunScore pooled_test_score(const std::vector<Experiment<double>>& tests, const std::vector<const Mat<double>*>& yhat,
                               Eigen::Index warmup);

/// Runs steps 1–4. `est` is the estimation record in its exact and double
/// views (the same rows; the fits read the doubles at data/fitting_precision.h);
/// `tests` may be empty; each test set is scored once, separately (a
/// benchmark with a multisine and an "arrow" record). Throws InputError for
/// windows outside the estimation record or too short a selection/test set.
DiagnoseResult diagnose(const LpvModel<double>& declared, const ExperimentViews& est,
                        const Experiment<double>& selection, const std::vector<Experiment<double>>& tests,
                        const DiagnoseOptions& options, SdpSolver& solver);

}  // namespace lpvid
