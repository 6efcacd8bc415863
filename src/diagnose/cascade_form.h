#pragma once
/// Physical coordinates for state nonlinearities: a √ outflow
/// or an overflow acts on a LEVEL, but the linear starting model
/// is in observer canonical form (fit/observer_form.h), whose second state
/// is no level at all. For a 2nd-order LTI model with real poles p_u, p_d
/// the same input–output map has the cascade realisation
///
///   z1+ = p_u z1 + β u              (the upstream store, e.g. the upper tank)
///   z2+ = p_d z2 + (1 − p_d) z1 + b u (the downstream store, fed by z1)
///   y   = z2 + D u + Φ
///
/// (z1 scaled so that both stores have the same level at rest). It is a
/// similarity z = T x of the observer form x1+ = −a1 x1 + x2 + b1 u,
/// x2+ = −a2 x1 + b2 u, y = x1 (+ D u):  z2 = x1,  z1 = (x2 + p_u x1)/(1 − p_d),
/// so every matrix maps exactly (A → T A T⁻¹, B → T B, C → C T⁻¹, x0 → T x0).
/// Both orderings of the poles are returned: which one is upstream is for
/// the data to decide.

#include <vector>

#include "model/lpv_model.h"

namespace lpvid {

/// The two cascade realisations, or none when the model is not a 2nd-order
/// observer-form LTI model (one constant A term, no ρ-dependent A or B term,
/// no state-scheduled column, no state offset, no explicit uncertainty C1)
/// with two real poles, neither at 1.
std::vector<LpvModel<double>> cascade_realisations(const LpvModel<double>& m);

/// The model with its state changed to z = T x (T invertible, nx × nx):
/// every A, B, C term, the correction's fixed A_i, B_i and x0.
LpvModel<double> similarity_transform(const LpvModel<double>& m, const Mat<double>& T);

}  // namespace lpvid
