#pragma once
/// What the LMI programs of Theorems 2.1 and 3.1 share: the scales the
/// programs are solved in, and constraint (C2) as an LMI block.

#include "core/scalar.h"
#include "solvers/lmi_program.h"

namespace lpvid {

/// Throws the InputError of solve_delta_form when z has no nonzero sample
/// (or nz = 0); returns the number of leading zero samples m. Shared by the
/// Δ-form programs (delta_form_lmi.h, delta_kyp_lmi.h).
Eigen::Index check_uncertainty_excited(const Mat<double>& z);

/// Sizes of Theorem 2.1's signals and the scales its programs are solved
/// in: z/σ_z with σ_z the RMS of z from its first non-zero sample (m leading
/// zero samples, horizon L = n − m), r/σ_r with σ_r the RMS of r (1 when
/// r = 0). Throws the InputError of check_uncertainty_excited when z ≡ 0.
struct SignalScaling {
  Eigen::Index n = 0, ny = 0, nz = 0, m = 0, L = 0;
  double sigma_z = 1.0, sigma_r = 1.0;
};
SignalScaling signal_scaling(const Mat<double>& z, const Mat<double>& r);

/// (C2) of docs/design.md §7.1 as the LMI block [N·s, dᵀ; d, I] ⪰ 0 (the Schur
/// complement of ‖d‖² ≤ N·s, N = n·ny rows of d): adds the block
/// "C2_noise", its corner N·s (s the variable `s_var`, or when s_var < 0
/// the constant `fixed_s`), the identity, and the constant part of d, the
/// scaled residual `r_scaled` (n × ny; d row k·ny + i is block row
/// 1 + k·ny + i). The caller adds d's variable part in column 0 of the
/// returned block.
int add_noise_block(LmiProgram& p, int s_var, double fixed_s, const Mat<double>& r_scaled);

}  // namespace lpvid
