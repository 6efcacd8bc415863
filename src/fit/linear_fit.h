#pragma once
/// The linear starting model of `lpvid diagnose` (docs/design.md §9):
/// an LTI state-space model of chosen order fitted to measured data.
///
///  1. ARX least squares (Ljung, System Identification, 2nd ed., 1999, §7.3,
///     eq. 4.7): y_k + Σ a_i y_{k−i} = Σ_{i=0..n} b_i u_{k−i} (+ e) over
///     k = n … N−1; unstable roots of the denominator are reflected into the
///     unit disc (observer_form.h).
///  2. Given the denominator a, the free-run output is affine in (B, D, x0, c),
///     which are re-fitted by linear least squares on the simulation error.
///  3. Output-error refinement (Ljung §4.2 eq. 4.25, §10.2): Levenberg–
///     Marquardt on ε_k = y_k − ŷ_k(θ), θ = (a, B, D, x0[, c]), ŷ the free-run
///     simulation; steps to a denominator with a root |λ| ≥ kStableRadius are
///     rejected, so the returned A is stable (spectral radius < 0.999).
///
/// Single output (ny = 1), any number of inputs; the state-space form is the
/// observer canonical form, ŷ = C x + D u with C = [1 0 … 0].
///
/// Several records (Experiment::records) of one system: one model (a, B, D,
/// c) fitted to all of them, each record with its own x0 (an unknown of
/// steps 2–3); the ARX rows of step 1 stay inside their record. The order
/// is chosen on all records (choose_order pools the held-out error of every
/// record, each from its own x0). One record gives the numbers of the
/// one-record fit exactly.

#include <vector>

#include "data/experiment.h"
#include "fit/levenberg_marquardt.h"
#include "fit/output_error_fit.h"
#include "fit/observer_form.h"
#include "model/lpv_model.h"

namespace lpvid {

/// Largest order accepted (a guard; real use is 1…10).
constexpr int kMaxLinearOrder = 30;

struct LinearFitOptions {
  int order = 2;        ///< n >= 1
  bool offset = false;  ///< fit a constant output offset c (Φ of eq. 20 with basis "1")
  LmOptions lm{};       ///< output-error refinement
  /// A second starting denominator (size `order`; empty: none): steps 2–3 run
  /// from it too and the fit with the lower estimation RMS is kept. choose_order
  /// passes the order n − 1 fit's denominator with a root at 0 appended, so
  /// order n contains the order n − 1 fit and never fits the rows worse.
  Vec<double> nested_denominator{};
};

struct LinearFit {
  ObserverForm form;        ///< the fitted parameters
  LpvModel<double> model;   ///< the same as an lpvid-model/1 model ("scheduling": []); x0 of the first record
  std::vector<Vec<double>> record_x0;  ///< each record's fitted x0 (the first is form.x0)
  double rms_estimation = 0;  ///< free-run RMS of y − ŷ on the estimation data
  double rms_arx = 0;         ///< free-run RMS after steps 1–2 (before refinement)
  double spectral_radius = 0; ///< of A (< 1)
  int iterations = 0;         ///< Levenberg–Marquardt steps tried
};

/// Fits the model to `est` (u: N × nu, y: N × 1). `columns` is copied into the
/// model (the data's names for u and y). Throws InputError for order < 1 or
/// > kMaxLinearOrder, ny != 1, a non-finite sample (naming the row), or too
/// few samples for the ARX regression (the message says how many are needed).
LinearFit fit_linear(const Experiment<double>& est, const ColumnMap& columns, const LinearFitOptions& options);

// The free-run RMS (prediction_rms) and the validation RMS with x0 fitted on
// the first samples (validation_rms) are in fit/output_error_fit.h.

struct OrderScore {
  int order = 0;
  double rms_estimation = 0, rms_validation = 0;
};

struct OrderChoice {
  int order = 0;                    ///< the chosen order
  std::vector<OrderScore> scores;   ///< one per candidate order
  LinearFit fit;                    ///< the chosen order's fit on `est` (the one scored)
};

/// Relative slack of the order rule: the smallest order whose validation RMS
/// is within this fraction of the best one is chosen (parsimony; a larger
/// order must pay for its parameters with a clear gain on held-out data).
constexpr double kOrderSlack = 0.05;

/// Differences of free-run RMS below this fraction of the held-out output's
/// RMS are rounding (noise-free data fit by several orders to ~1e-13).
constexpr double kOrderFloor = 1e-9;

/// Fits every order in [1, max_order] on `est` (order n also from order
/// n − 1's fit: nested_denominator), scores it on `val` (x0 from
/// the first init_samples samples of each record of val, the squared errors
/// pooled over the records) and chooses the smallest order with
/// rms_validation <= (1 + kOrderSlack) · best + kOrderFloor · rms(y_val). Orders too large for the data
/// are skipped (at least one must fit, else the InputError of fit_linear).
OrderChoice choose_order(const Experiment<double>& est, const Experiment<double>& val, const ColumnMap& columns,
                         int max_order, bool offset, int init_samples, const LmOptions& lm = {});

}  // namespace lpvid
