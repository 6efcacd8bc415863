#pragma once
/// Selection of the correction basis F^N: the algorithm of the paper's
/// Appendix ("Practical implementation issues"), docs/design.md §8.5.
///
///  0. Test S_I alone with Theorem 2.1 at the given δ, d_max (certified with
///     BoundObjective kFeasibility: verified ⇒ consistent; otherwise see
///     "cannot explain" below). If the model declares an offset basis
///     without values, φ is identified in this step too (Theorem 3.1 without
///     correction is an LMI), so "S_I" means S_I with its best offset.
///  1. Otherwise grow the correction basis ONE monomial at a time in the
///     order of basis_growth_order() (the Appendix's F^1 ⊂ F^2 ⊂ …),
///     identify with Theorem 3.1 at the given bounds, certify the identified
///     (rounded) model at the same bounds, and stop at the first basis whose
///     model is certified consistent.
///  2. Then try removing terms one at a time ("gradually eliminate
///     parameters", end of the Appendix), keeping a removal when the smaller
///     basis is still certified consistent.
///
/// Choices where the paper is silent (documented here, the contract):
///
///  - Growth order (basis_growth_order): the constant 1 (LTI); then ρ1 … ρnρ
///    (affine); then the multilinear products of distinct ρ's by increasing
///    degree 2 … min(nρ, max_degree), lexicographic within a degree
///    (ρ1ρ2, ρ1ρ3, …, ρ2ρ3, …; the Appendix lists F^{nρ+2} = {…, ρ1ρ2},
///    ending with ρ1⋯ρnρ); then, degree by degree d = 2 … max_degree, the
///    remaining monomials of degree d: first the pure powers ρ1^d … ρnρ^d,
///    then the mixed ones (ρ1²ρ2, …) in descending lexicographic order of the
///    exponents. Nothing above max_degree (total degree) is tried. For
///    nρ = 2, max_degree = 2 this is 1, ρ1, ρ2, ρ1ρ2, ρ1², ρ2²: the bases of
///    the paper's Tables I/II in order.
///  - The fixed A_i, B_i of a candidate term are the ones the model file
///    declares for that monomial in its correction section, zero otherwise
///    (as in both of the paper's examples). The file's correction basis
///    itself is ignored: the algorithm builds its own.
///  - Identification per step. Without `iterate`: one solve of the paper's
///    relaxation (linearised at S_I) with kFeasibility at the given δ, d_max;
///    an infeasible relaxation is only the solver's verdict on the
///    relaxation, which is conservative (it proves nothing about the class).
///    With `iterate` (beyond the paper): kMinDmax at the given δ with
///    re-linearisation until d_max stalls, then the best model is certified
///    at the given bounds. The kFeasibility relaxation at S_I is usually
///    infeasible when the missing term is large and the bounds tight
///    (Example 1: even the full basis is rejected at δ = 0.05, d_max = 0.01),
///    so `iterate` is the useful mode there.
///  - "Cannot explain" is certified both ways or not said. A step whose
///    model is not certified consistent asks for a class certificate
///    (identify/class_bound.h, claim "class_invalidated", checked exactly
///    after its JSON round trip): no θ of the region, with any Δ of
///    ‖Δ‖∞ ≤ δ and noise of RMS ≤ d_max, explains the data. The region is
///    the whole class when no unknown moves z (additive structure, offsets:
///    Theorem 3.1 is convex there) → kCannotExplain; otherwise the
///    parameters that move z (multiplicative θ, x0) are confined to a box
///    centred at the step's identified parameters (zero when the step found
///    none), split by branch and bound up to `klass.max_leaves` →
///    kBoxInvalidated, which says nothing about θ outside that box. When the
///    class certificate fails (a point of the region is feasible, a leaf's
///    margin is not positive, the solver gave no answer) the step is
///    kNotDecided, its detail giving the solver's verdict and the reason;
///    solver trouble with no certificate either way stays kUnverified.
///  - How the verdicts drive the algorithm: only "consistent" stops the
///    growth or keeps a removal, exactly as before. A whole-class
///    "cannot explain" proves that no θ of that basis helps, so growing is
///    the only way on; a box invalidation refutes only θ near the found one
///    (another θ of the basis may still explain the data), so for the
///    algorithm it is treated exactly as "not decided" and only reported
///    with its box. The selection's overall result is "cannot explain" only
///    when the largest basis grown (it contains every smaller one, whose
///    classes are subsets) carries a whole-class certificate.
///  - Every "consistent" is backed by a certificate that the exact verifier
///    accepted (CertifiedBounds::verified; the front end writes it, the CLI
///    to <stem>.step<k>.cert.json). A model that was found but not
///    verified is "unverified" and never counts as consistent.
///  - Removal order: the most recently added term first (highest degree
///    first), one pass. One pass suffices if verdicts are monotone: if
///    removing t from B failed, removing it from any B' ⊂ B fails too.
///    A basis already evaluated (e.g. removing the last added term gives the
///    previous F^k) is not solved again: the step says "same as step j".

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/scalar.h"
#include "data/experiment.h"
#include "toeplitz/affine_residual.h"
#include "certify/certify.h"
#include "identify/class_bound.h"
#include "identify/identify.h"
#include "model/lpv_model.h"
#include "model/problem.h"
#include "model/monomial.h"
#include "solvers/sdp_solver.h"

namespace lpvid {

/// The candidate terms in the order they are added (see above).
/// Throws std::invalid_argument for n_rho < 0 or max_degree < 0.
std::vector<Monomial> basis_growth_order(int n_rho, int max_degree);

/// The model with its correction basis replaced by `basis`; A_i, B_i are
/// taken from the model's correction for the same monomial, zero otherwise.
template <typename T>
LpvModel<T> with_correction_basis(const LpvModel<T>& model, const std::vector<Monomial>& basis);

/// "1, rho1, rho2^2", or "(none)" for the empty basis.
std::string basis_text(const std::vector<Monomial>& basis, const std::vector<std::string>& names);

enum class BasisVerdict {
  kConsistent,      ///< a certificate at the given bounds passed the exact verifier
  kCannotExplain,   ///< a class certificate (exactly checked): no θ of the basis explains the data
  kBoxInvalidated,  ///< a class certificate for a box of θ only (see above): the algorithm treats it as kNotDecided
  kNotDecided,      ///< the solver found no consistent model, and no class certificate exists
  kUnverified,      ///< solver trouble, or a model whose certificate did not pass, and no class certificate
};
/// "consistent", "cannot_explain", "box_invalidated", "not_decided", "unverified".
const char* to_string(BasisVerdict v);

struct BasisStep {
  int index = 0;                     ///< 0 = S_I alone
  std::string phase;                 ///< "initial", "grow", "remove"
  std::vector<Monomial> basis;
  std::string basis_text;
  BasisVerdict verdict = BasisVerdict::kUnverified;
  std::string detail;                ///< why this verdict, in words
  CertifiedBounds bounds;            ///< verified ⇒ exactly the given δ, d_max hold
  std::string certificate;           ///< the file the front end wrote its certificate to (verified only)
  double dmax_relaxation = -1;       ///< iterate: smallest d_max at δ the relaxation reached (< 0: none)
  std::string relaxation;            ///< IdentifyResult::relaxation, or "none (fixed model)"
  int solves = 0;                    ///< SDP solves, certification included
  double seconds = 0;
  int same_as = -1;                  ///< ≥ 0: this basis was evaluated at that step; nothing solved
  bool kept = false;                 ///< remove phase: the removal was kept
  ParameterLayout layout;            ///< of the certified model's parameters
  Vec<double> p;                     ///< the rounded parameters (12 digits) that were certified
  /// The class certificate's attempt (not consistent steps only; `klass->certified()`
  /// ⇔ kCannotExplain or kBoxInvalidated); `class_centered_at_fit`: its box is
  /// centred at the step's identified parameters (else at zero).
  std::optional<ClassBoundResult> klass;
  bool class_centered_at_fit = false;
  std::string class_certificate;     ///< the file the front end wrote it to (certified only)
};

struct BasisSelectionOptions {
  ExactBound delta, dmax;            ///< the given bounds (d_max RMS, docs/design.md §7.4)
  int max_degree = 2;
  bool iterate = false;
  int max_iterations = IdentifyOptions{}.max_iterations;
  double rel_tol = IdentifyOptions{}.rel_tol;
  bool prune = true;                 ///< run the removal phase
  Unknowns unknowns;                 ///< offset / x0 (correction is always on)
  bool class_certificates = true;    ///< try a class certificate for every step not consistent
  ClassBoundOptions klass;           ///< its box and leaf budget (unknowns are set per step)
  SolverOptions solver;
  /// data reference, max_taps, digits; objective and solver options are set per step.
  CertifyOptions certify;
  std::function<void(const BasisStep&)> on_step;  ///< progress (called after each step)
};

/// How a selection ended: the one stored status, decided once by
/// select_basis in this order.
enum class SelectionOutcome {
  kFound,          ///< a consistent (verified) model was found
  kCannotExplain,  ///< none: the largest basis grown carries a whole-class "cannot explain" certificate
  kNotVerified,    ///< none, and some step's solver answer failed the exact check
  kNotDecided,     ///< none, and nothing certifies that none exists (the initial value)
};
/// "found", "cannot_explain", "not_verified", "not_decided" (the report's status).
const char* to_string(SelectionOutcome outcome);

struct BasisSelectionResult {
  std::vector<Monomial> order;       ///< the candidates, in growth order
  std::vector<BasisStep> steps;
  SelectionOutcome outcome = SelectionOutcome::kNotDecided;
  /// A consistent (verified) model was found.
  bool found() const { return outcome == SelectionOutcome::kFound; }
  int final_step = -1;               ///< index into steps of the answer (found only)
  std::vector<Monomial> basis;       ///< the final basis (found only)
};

/// Runs the algorithm on `problem`'s model and data (its exact and double
/// views, model/problem.h). Throws InputError for bad input.
BasisSelectionResult select_basis(const Problem& problem, const BasisSelectionOptions& options, SdpSolver& solver);

/// Monotonicity of the verdicts (adding terms can only help): returns a
/// description of the first pair of steps with basis_i ⊆ basis_j, step i
/// consistent and step j not (cannot_explain: a contradiction between two
/// exact certificates; box_invalidated, not_decided: the region or the
/// solver); "" if there is none. Unverified steps are not counted.
std::string monotonicity_violation(const std::vector<BasisStep>& steps);

}  // namespace lpvid
