#pragma once
/// The library of candidate effects that `lpvid diagnose` tries (docs/design.md §9,
/// effect kinds of docs/design.md §11.5). Each candidate is the current
/// model with ONE effect added at a starting guess, plus the slots the fit
/// may move (the effect's own parameters, the output map C, D, the offset
/// and x0: adding an effect re-fits the output map, A and B stay).
///
/// Kinds and where they enter:
///   basis_term         a new f(ρ) in S_C (eq. 10): terms f(ρ)·C_f x + f(ρ)·D_f u
///                      in the output, f a monomial of the model's scheduling
///                      variables (with_input_scheduling adds the measured
///                      inputs as scheduling variables: ρ = u); a state-function
///                      column (√, |·|, hinge of a state) enters a monomial at most
///                      once and linearly
///   output_offset      Φ(ρ) (eq. 20): a constant, and Φ(ρ_i) over {1, ρ_i, …,
///                      ρ_i^max_degree} for each measured scheduling variable
///   input_saturation   static input map (model/static_blocks.h)
///   output_saturation  static output map
///   dead_zone          static input map
///   abs_value          |·| at the sensor: static output map
///   input_polynomial   u' = c0 + u + c2 u² + c3 u³
///   output_polynomial  y  = c0 + v + c2 v² + c3 v³ (v = ŷ + Φ)
///   output_piecewise_linear  y = g(v), g piecewise linear with knots at the
///                      quantiles of v (√-like, clipping, monotone sensor curves)
///   input_delay        u'_k = u_{k−d}, d = 1 … max_delay
///   basis_term in A    A(ρ) = A_0 + ρ^j A_j with ρ = x_1, the model's own
///                      simulated state (model/state_scheduling.h), j = 1 …
///                      state_degree: a state-dependent nonlinearity as a
///                      quasi-LPV term, needs the joint re-fit (A moves)
///   state_nonlinearity e·f(x_i − c) added to the state equation: a
///                      scheduling column "@sqrt(x<i>-c)",
///                      "@abs(x<i>-c)" or "@hinge(x<i>-c)" (model/state_scheduling.h)
///                      and a state offset E(ρ) = ρ_new·e (model.state_offset),
///                      i = 1 … nx. √ is a tank's outflow (c started below the
///                      state's simulated range), hinge an overflow clip
///                      (c started at the 0.9 quantile of x_i, e → −1 clips).
///                      e (from 0), c and A, B move in the joint re-fit.
///                      Also the store cascade (diagnose/store_cascade.h):
///                      two stores with √ outflow and overflow levels that
///                      replace an LTI SISO linear part, from a grid of starts.
/// A candidate never depends on the data set's name: only on the model's
/// structure and the ranges of the estimation signals (starting guesses).

#include <functional>
#include <string>
#include <vector>

#include "data/experiment.h"
#include "fit/model_parameters.h"

namespace lpvid {

struct CandidateOptions {
  int max_degree = 2;               ///< monomials of ρ up to this degree for basis_term
  int max_delay = 5;                ///< input delays 1..max_delay
  int polynomial_degree = 3;        ///< input/output polynomials
  int state_degree = 3;             ///< x1^1..x1^d in A (scheduling on the model's own state); 0: none
  int pwl_knots = 6;                ///< knots of the piecewise-linear output map (at v's quantiles); < 2: none
  bool state_functions = true;      ///< state_nonlinearity candidates (sqrt, abs, hinge of x_i − c in the state equation)
};

struct EffectCandidate {
  std::string kind;     ///< effect kind (docs/design.md §11.5)
  std::string label;    ///< e.g. "basis_term rho1^2 (C, D)", "input_delay 2"
  int effect_parameters = 0;            ///< parameters the effect adds
  std::vector<LpvModel<double>> starts; ///< the model with the effect at each starting guess
  std::vector<ParameterSlot> slots;     ///< what the fit moves (same for every start)
  /// Starting guesses that depend on the data the family is fitted on (the
  /// store cascade's levels and overflow from the output's range): when set,
  /// a fit on some rows starts from starts_for(those rows) instead of
  /// `starts` (computed from the whole estimation record), so no fold's start
  /// has seen its held-out block. Same structure and slots as `starts`.
  std::function<std::vector<LpvModel<double>>(const Experiment<double>&)> starts_for;
};

/// The candidates for the current (explicit) model. Skips an effect that the
/// model already has (a static map already present, an existing basis term).
std::vector<EffectCandidate> candidate_effects(const LpvModel<double>& current, const Experiment<double>& est,
                                               const CandidateOptions& options);

/// The model with every input column that is not yet a scheduling variable
/// added as one (named after the column): lets basis_term try f(u)·x, f(u)·u.
LpvModel<double> with_input_scheduling(const LpvModel<double>& m);

/// The experiment for the model `augmented` = with_input_scheduling(declared):
/// ρ gets the input columns that became scheduling variables.
Experiment<double> with_input_scheduling(const Experiment<double>& e, const LpvModel<double>& declared,
                                         const LpvModel<double>& augmented);

/// The same input-output model with its state scaled, x' = x/s: B and the
/// correction's B_i divided by s, C and the uncertainty channel's C1 times
/// s, x0/s, the state offset's values e_j/s; A and the correction's A_i are
/// unchanged (a diagonal similarity by a scalar). For a model without
/// state-scheduling columns (their values would change with the scale).
LpvModel<double> scale_state(const LpvModel<double>& m, double s);

/// The model with one more scheduling variable `name` read from data column
/// `column` (every basis monomial, also of the state offset, padded with a
/// zero power).
LpvModel<double> add_scheduling_variable(const LpvModel<double>& m, const std::string& name, const std::string& column);

}  // namespace lpvid
