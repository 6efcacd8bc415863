#pragma once
/// A certified lower end of Theorem 3.1's optimum over a whole region of the
/// correction class (docs/class_lower_bound.md): the least objective over
/// every θ (C_i, D_i of eq. 10, φ of eq. 20, x0 when free) of the region,
/// together with Δ and d.
///
/// The parameters that do not move z (the additive structure's θ, output-map
/// corrections of the general structure, the offsets φ) enter (C2) linearly
/// and range over all reals: they are the structured barrier's free
/// regressors, and the dual g is projected off their columns. When every
/// parameter is of that kind Theorem 3.1 is convex (T_z is fixed) and one
/// solve gives the class optimum, its parameters and its certified lower end.
/// The others (the multiplicative structure's θ and x0: a BMI) are confined to
/// a box around the found θ; a leaf's bound holds for its whole box, and the
/// box is split (branch and bound, the lowest leaf first, along the
/// coordinate whose half-width costs most) until the lowest leaf reaches the
/// stopping gap or the leaf budget, counted in leaves, never in time.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "certify/certify.h"
#include "data/experiment.h"
#include "model/lpv_model.h"
#include "model/problem.h"
#include "toeplitz/affine_residual.h"
#include "verify/certificate/certificate_file.h"

namespace lpvid {

struct ClassBoundOptions {
  Unknowns unknowns;
  /// Box of the parameters that move z: each may move z by at most this
  /// fraction of ‖z(θ̂)‖ on its own, ρ_i = fraction·‖z(θ̂)‖/‖Jz_i‖.
  double box_fraction = 0.01;
  int max_leaves = 31;          ///< leaves of the branch-and-bound tree
  /// A lower end (not an invalidation, which always splits to its budget)
  /// stops splitting after this many successive splits that did not raise the
  /// lowest leaf's bound (0: split to max_leaves). Many boxed coordinates
  /// need many splits before a child beats its parent's inherited point: on
  /// the generated 2-state systems (bench/README.md, class_bound_bench) the
  /// lowest leaf rose after at most 2 such splits and never after 3, while
  /// every further leaf cost one structured solve.
  int stall_splits = 4;
  double stop_rel_gap = 0.01;   ///< stop splitting when the lowest leaf is within this of `upper`
  double upper = 0;             ///< the certified upper end it is compared with (0: split to the budget)
};

/// How a class bound ended.
enum class ClassBoundOutcome {
  kNotTried,      ///< no class bound was attempted: the initial value
  kCertified,     ///< a class certificate was made and checked exactly
  kNotCertified,  ///< attempted, none passed: ClassBoundResult::reason says why
};

struct ClassBoundResult {
  /// The one stored status, decided by class_lower_bound (or by
  /// class_interval when the bound could not run).
  ClassBoundOutcome outcome = ClassBoundOutcome::kNotTried;
  /// A class certificate was made and checked exactly.
  bool certified() const { return outcome == ClassBoundOutcome::kCertified; }
  std::string reason;                ///< why not (empty when certified)
  Rational lower;                    ///< the certified lower end (the claim's lower_bound; 0 for an invalidation)
  std::optional<Certificate> certificate;
  bool whole_class = false;          ///< every parameter free: the bound holds for every θ of the basis
  std::vector<long> free;            ///< parameter indices ranging over all reals
  Vec<double> center, radius;        ///< the box of the others (free ones: 0)
  std::vector<std::string> names;
  int leaves = 0;
  double seconds = 0;
  /// The parameters of the lowest leaf's solve: its centre with the free
  /// parameters at the solver's least-squares values. In the convex case
  /// (whole_class) this is the class optimum.
  Vec<double> best_p;
  double best_objective = 0;         ///< the solver's objective there (not certified)
  /// whole_class: the solve at best_p (its central point is the fixed
  /// model's at best_p too: certify_fixed_model_from), so that the optimum
  /// is certified without a second solve.
  std::shared_ptr<const DeltaFormSolution> best_solution;
};

/// `found_p` is the identified θ (layout of the affine residual for
/// `options.unknowns`): the box's centre. `certify` gives the objective, its
/// fixed values' exact texts and the data reference.
ClassBoundResult class_lower_bound(const Problem& problem, const Vec<double>& found_p, const CertifyOptions& certify,
                                   const ClassBoundOptions& options);

}  // namespace lpvid
