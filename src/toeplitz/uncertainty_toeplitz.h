#pragma once
/// T_z, the Toeplitz matrix of the uncertainty channel z (paper eq. 4 and
/// Theorem 2.1, docs/design.md §6.3), in the two modes the project implements:
///
///  - `signal` (default): T_z = T_{z} (eq. 3) of the simulated z. This is the
///    exact condition for a causal LTI Δ mapping the recorded z to w; it is
///    the same for LTI and LPV models and includes the response to x_0.
///  - `paper`: T_z = T_G12 · T_u literally (eq. 4, Theorem 2.1), T_G12 the
///    system Toeplitz (eq. 2) of u → z along ρ and T_u the signal Toeplitz
///    of u. Column j is the z response (from x_0 = 0) to u delayed by j
///    samples along the *undelayed* ρ. For an LTI G12 (or ρ constant along
///    the trajectory) and x_0 = 0 both modes are equal; for an LPV model
///    along a varying ρ they differ in general and the paper-mode matrix is
///    not Toeplitz (docs/design.md §6.3: its last column is D1(ρ_{n−1}) u_0, not D1(ρ_0) u_0).
///
/// Both are (n·nz) × n. Templated on the scalar; no tolerance (docs/design.md §13.4).

#include <stdexcept>
#include <string>
#include <string_view>

#include "core/input_error.h"
#include "core/scalar.h"
#include "data/experiment.h"
#include "model/lpv_model.h"
#include "model/simulate.h"
#include "toeplitz/signal_toeplitz.h"
#include "toeplitz/system_toeplitz.h"

namespace lpvid {

enum class ToeplitzMode {
  kSignal,  ///< T_z = signal Toeplitz of the simulated z (docs/design.md §6.3, default)
  kPaper,   ///< T_z = T_G12 · T_u (paper eq. 4, Theorem 2.1)
};

/// The default mode (docs/design.md §6.3).
constexpr ToeplitzMode kDefaultToeplitzMode = ToeplitzMode::kSignal;

/// "signal" or "paper" (the CLI's --toeplitz values and the certificate field).
inline const char* to_string(ToeplitzMode mode) {
  switch (mode) {
    case ToeplitzMode::kSignal:
      return "signal";
    case ToeplitzMode::kPaper:
      return "paper";
  }
  return "unknown";
}

/// Inverse of to_string; throws InputError for anything else.
inline ToeplitzMode toeplitz_mode_from_string(std::string_view text) {
  if (text == "signal") return ToeplitzMode::kSignal;
  if (text == "paper") return ToeplitzMode::kPaper;
  throw InputError("unknown Toeplitz mode '" + std::string(text) + "' (expected 'signal' or 'paper')");
}

/// Signal mode from an existing simulation: T_z = T_{z} (eq. 3), (n·nz) × n.
template <typename T>
Mat<T> T_z_signal(const Simulation<T>& sim) {
  return signal_toeplitz(sim.z);
}

/// Paper mode: T_G12 · T_u (eq. 4, Theorem 2.1), (n·nz) × n. T_G12 maps u
/// to z from x_0 = 0, so a model with a non-zero x0 is rejected
/// (std::invalid_argument): the paper's formula has no term for x_0, and
/// silently dropping it would describe a different z than the simulation.
/// Likewise a model with a state offset E(ρ) (model.state_offset) is rejected.
template <typename T>
Mat<T> T_z_paper(const LpvModel<T>& model, const Experiment<T>& exp) {
  for (Eigen::Index i = 0; i < model.x0.size(); ++i)
    if (model.x0(i) != T(0))
      throw std::invalid_argument(
          "Toeplitz mode 'paper' (T_z = T_G12 T_u, eq. 4) assumes x_0 = 0, but the model has a non-zero x0; "
          "use mode 'signal'");
  if (has_state_offset(model))
    throw std::invalid_argument(
        "Toeplitz mode 'paper' (T_z = T_G12 T_u, eq. 4) does not support state_offset: the affine term E(rho) of "
        "the state equation is not a map of u; use mode 'signal'");
  const Mat<T> TG12 = system_toeplitz(model, exp, SystemChannel::kUncertainty);
  return TG12 * signal_toeplitz(Mat<T>(model.statics.model_input(exp.u)));  // u' (model/static_blocks.h)
}

/// T_z of Theorem 2.1 in the given mode (see the file comment), (n·nz) × n.
template <typename T>
Mat<T> T_z(const LpvModel<T>& model, const Experiment<T>& exp, ToeplitzMode mode = kDefaultToeplitzMode) {
  if (mode == ToeplitzMode::kPaper) return T_z_paper(model, exp);
  return T_z_signal(simulate(model, exp));
}

}  // namespace lpvid
