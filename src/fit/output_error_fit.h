#pragma once
/// Least-squares fit of model slots (fit/model_parameters.h) to measured
/// data: minimise Σ_k ‖y_k − ŷ_k(p)‖² over the slots p, where ŷ(p) is the
/// model's prediction g_out(ŷ + Φ) of y (model/simulate.h). This is the
/// output-error criterion: the state is simulated from u (and x0), never
/// reset to the data, so the fitted model is judged the way it is used.
///
/// Method: Levenberg–Marquardt (fit/levenberg_marquardt.h) with a
/// forward-difference Jacobian. For a model without
/// a static output map every C, D, φ and x0 slot enters ŷ affinely (eq. 14–15),
/// so those directions converge in one step; the nonlinear ones (saturation
/// limits, polynomial coefficients) take a few more.

#include <vector>

#include "data/experiment.h"
#include "fit/model_parameters.h"
#include "fit/observer_form.h"

namespace lpvid {

struct FitOptions {
  int max_iterations = 200;    ///< LM steps tried (accepted + rejected)
  double rel_tol = 1e-10;      ///< stop when the cost falls by less (relative)
  Eigen::Index first_sample = 0;  ///< the cost starts here (earlier samples only run the state)
  Eigen::Index last_sample = -1;  ///< one past the last sample of the cost (-1: n)
  /// A held-out block [skip_first, skip_last) inside the cost window whose
  /// residuals are left out of the cost (the state still runs through it):
  /// the fit of one fold of a blocked cross-validation (diagnose/fold_plan.h).
  /// Empty (skip_first >= skip_last): nothing is left out.
  Eigen::Index skip_first = 0, skip_last = 0;
  /// Stability guard when A is a slot (the joint re-fit): a step to a constant
  /// A term with spectral radius >= this is rejected (observer_form.h).
  /// Not applied when the start is already beyond it and has a state offset
  /// on state functions (a store with A = I kept bounded by its outflow):
  /// such a fit is judged by the finiteness of its simulation.
  double max_radius = kStableRadius;
  /// The Jacobian's columns of slots that move only the output map (C, D,
  /// output offset, output block) from one state trajectory per Jacobian
  /// instead of a whole simulation each: the same numbers (false: every
  /// column simulated; the tests compare the two).
  bool reuse_state_trajectory = true;
};

struct FitResult {
  LpvModel<double> model;  ///< with the fitted slot values
  double rms = 0;          ///< RMS of y − ŷ over the cost samples and outputs
  int iterations = 0;
  bool finite = true;      ///< false if the simulation overflowed (the model is then the start)
};

/// RMS of y − g_out(ŷ + Φ) over samples [first, last) of the experiment
/// (last = -1: n); +inf when the simulation is not finite.
double prediction_rms(const LpvModel<double>& model, const Experiment<double>& exp, Eigen::Index first = 0,
                      Eigen::Index last = -1);

/// How many leading validation samples an x0 may be fitted on (the cascaded
/// tanks benchmark's rule); the default of every option that takes it.
inline constexpr Eigen::Index kValidationInitSamples = 5;

/// The starting points of the initial-state fit: zero, the model's own x0
/// (the state it was fitted with, a plausible state of the same plant), and
/// the equilibria the model settles in when u and ρ stay at the record's
/// first sample (reached from zero and from the model's x0: a plant at rest
/// before the record starts). Duplicates and non-finite states left out.
std::vector<Vec<double>> initial_state_starts(const LpvModel<double>& model, const Experiment<double>& exp);

/// x0 fitted on the first `samples` samples of `exp` (the rest only runs the
/// state) from every start of initial_state_starts; the fit with the lowest
/// RMS on those samples is kept. With a static map or a state nonlinearity
/// the x0 problem is not convex, and a single start from zero can stop in a
/// local minimum (on a Wiener model with |·| at the sensor it lands on the
/// mirror branch). FitResult::finite is false if no start stayed finite
/// (the model then has x0 = 0).
FitResult fit_initial_state(const LpvModel<double>& model, const Experiment<double>& exp, Eigen::Index samples);

/// Free-run RMS on `val` from an x0 fitted on its first `init_samples`
/// samples only (fit_initial_state) (the cascaded tanks benchmark's rule), RMS over all samples.
/// Also returns the simulated output in `yhat` if non-null.
double validation_rms(const LpvModel<double>& model, const Experiment<double>& val, Eigen::Index init_samples,
                      Mat<double>* yhat = nullptr);

/// A free-run score under the benchmark protocol of docs/design.md §9.5 (the
/// nonlinear_benchmarks loader since version 1.0.1): x0 fitted on the first
/// `warmup` samples only (fit_initial_state), the RMS and the fit % over the samples after them:
///   fit % = 100 · (1 − ‖y − ŷ‖ / ‖y − ȳ‖),  ȳ the mean of the scored y.
struct FreeRunScore {
  double rms = 0, fit_percent = 0;
  Eigen::Index warmup = 0, scored = 0;  ///< samples used for x0 / in the RMS
};

/// Throws std::invalid_argument unless 1 <= warmup < exp.n(). Non-finite
/// simulation: rms = +inf, fit_percent = -inf.
FreeRunScore warmup_score(const LpvModel<double>& model, const Experiment<double>& exp, Eigen::Index warmup,
                          Mat<double>* yhat = nullptr);

/// Fits the slots of `model` to `exp`.
FitResult fit_slots(const LpvModel<double>& model, const std::vector<ParameterSlot>& slots,
                    const Experiment<double>& exp, const FitOptions& options = {});

}  // namespace lpvid
