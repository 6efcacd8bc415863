#pragma once
/// The continuous parameters that `lpvid diagnose` fits by least squares
/// (docs/design.md §9): named slots pointing into an LpvModel<double>.
///
/// A slot is one scalar of the model: an entry of a C or D term (the output
/// map C(ρ) = Σ_i f_i(ρ) C_i of eq. 8–10, including correction terms that
/// were folded in as explicit terms), an offset value φ_j (eq. 20), an entry
/// of x0, or a parameter of a static input/output map (model/static_blocks.h).
/// A and B are slots only in the joint re-fit of the dynamics with an effect
/// (dynamics_slots): Wiener / Hammerstein models need the
/// linear part re-estimated together with the static map. Without A, B slots
/// and without a static output map the output is affine in every C, D, φ
/// and x0 slot.
///
/// For state nonlinearities: an entry of a state offset value e_j (kStateOffset,
/// E(ρ) = Σ_j h_j(ρ) e_j in the state equation) and the shift c of a
/// state-function scheduling column "@sqrt(x<i>-c)" (kStateShift, the
/// fitted level). The shift lives in the column text: slot_values reads it
/// from the text, with_slot_values re-renders the text from the double
/// (model/state_scheduling.h: the shortest text that reads back exactly).

#include <string>
#include <vector>

#include "core/scalar.h"
#include "model/lpv_model.h"

namespace lpvid {

struct ParameterSlot {
  enum class Where { kA, kC, kD, kB, kOffset, kX0, kInputLower, kInputUpper, kInputCoef, kOutputLower, kOutputUpper, kOutputCoef,
                     kStateOffset, kStateShift };
  Where where = Where::kC;
  int term = 0;  ///< term index (C, D), (state) offset basis index, coefficient index, scheduling index (kStateShift)
  int row = 0, col = 0;
  std::string name;  ///< e.g. "C[rho1](1,2)", "input.upper", "x0(1)"
};

/// The scalar a slot names (throws std::out_of_range for a stale slot, and
/// std::invalid_argument for kStateShift, whose value is column text: use
/// slot_values / with_slot_values).
double& slot_value(LpvModel<double>& m, const ParameterSlot& s);

/// Current values of the slots.
Vec<double> slot_values(const LpvModel<double>& m, const std::vector<ParameterSlot>& slots);
/// A copy of m with the slots set to p.
LpvModel<double> with_slot_values(const LpvModel<double>& m, const std::vector<ParameterSlot>& slots, const Vec<double>& p);

/// Slots of every entry of every C and D term.
std::vector<ParameterSlot> output_map_slots(const LpvModel<double>& m);
/// Slots of the B terms with basis f (entries of f(ρ)·B_f).
std::vector<ParameterSlot> input_term_slots(const LpvModel<double>& m, const Monomial& f);
/// Slots of the state equation for the joint re-fit: every
/// entry of every B term, and of every A term, except that when the constant
/// A term is in observer canonical form (fit/observer_form.h: ones on
/// the superdiagonal, zeros elsewhere outside column 1) every A term moves
/// only in its first column: -a, the minimal parametrisation of the
/// denominator, and for a term f(ρ)·A_f a feedback f(ρ)·A_f(:,1)·x_1.
/// With a state offset, also every entry of its values (state_offset_slots).
std::vector<ParameterSlot> dynamics_slots(const LpvModel<double>& m);

/// Slots of every entry of every state offset value e_j.
std::vector<ParameterSlot> state_offset_slots(const LpvModel<double>& m);
/// Slot of the shift c of scheduling column j, which must be
/// "@abs/@sqrt/@hinge(x<i>-c)" (throws std::invalid_argument otherwise).
ParameterSlot state_shift_slot(const LpvModel<double>& m, int j);

/// Ones on the superdiagonal, zeros elsewhere outside the first column, and
/// at least `min_order` rows: the observer canonical form (fit/observer_form.h)
/// whose A terms move only in their first column.
bool observer_shaped(const Mat<double>& a, Eigen::Index min_order = 2);

/// Spectral radius of the constant A term (0 without one). The stability
/// guard of the joint re-fit; ρ-dependent A terms are judged by whether the
/// simulation stays finite.
double constant_a_radius(const LpvModel<double>& m);

/// Slots of every offset value (the offset must have values).
std::vector<ParameterSlot> offset_slots(const LpvModel<double>& m);
/// Slots of x0 (x0 is sized to nx) and of every later record's initial
/// state (LpvModel::later_x0): kX0 with term 0 for x0, term k for the
/// initial state of record k+1.
std::vector<ParameterSlot> x0_slots(const LpvModel<double>& m);
/// Slots of one record's initial state (0: x0; k >= 1: later_x0[k-1]).
std::vector<ParameterSlot> record_x0_slots(const LpvModel<double>& m, int record);
/// Slots of the effect parameters of the static maps (saturation/dead-zone
/// limits, polynomial coefficients except c_1, which the output map's scale
/// already carries).
std::vector<ParameterSlot> static_map_slots(const LpvModel<double>& m);

/// A model whose declared unknowns are explicit: the correction basis
/// folded into C and D as zero terms (its fixed A_i, B_i stay in the state
/// equation), unknown offset values set to zero, x0 sized to nx. The result
/// has no unknowns left: every parameter is a slot.
LpvModel<double> explicit_model(const LpvModel<double>& m);

/// The slots that are re-fitted with every candidate effect: C, D terms,
/// offset, x0 and the static maps' parameters.
std::vector<ParameterSlot> refit_slots(const LpvModel<double>& m);

/// `slots` plus the model's dynamics slots (A, B: dynamics_slots) that are
/// not already among them: the joint re-fit of the linear part with an effect
/// (a Wiener or Hammerstein map changes the best A, B too).
std::vector<ParameterSlot> with_dynamics_slots(std::vector<ParameterSlot> slots, const LpvModel<double>& m);

}  // namespace lpvid
