#pragma once
/// An Example-2-flavoured data set (paper Section 4.2, eq. 20): a nonlinear
/// system linearised along an operating point u* that is itself the
/// scheduling parameter, with an output offset Φ(u*) that an LPV model
/// (eq. 1) does not have. The paper's helicopter simulator is not available;
/// this is a small SISO stand-in with a known answer.
///
///   x̂_{k+1} = [0 1; −(0.24 + 0.1ρ_k)  0.9 − 0.4ρ_k] x̂_k + [0; 1] û_k
///   y_k     = [1 + 0.5ρ_k  0] x̂_k + Φ(ρ_k)                      (+ noise)
///   Φ(ρ)    = 0.5 + 0.8ρ − 0.3ρ²
///
/// ρ = u* (column `rho1`) is a slowly varying operating point: one period
/// of ρ_k = 0.5 − 0.45 cos(2πk/(n−1)) over the record (so it sweeps
/// [0.05, 0.95] and back), rounded to 4 decimals. û (column `u1`) is a
/// random ±0.5 pulse train (hold times 1–5 samples). The frozen-ρ poles have
/// modulus √(0.24 + 0.1ρ) ≤ 0.59. All u, ρ are short exact decimals; y is
/// the EXACT rational simulation plus Φ, rounded to 10 decimals, plus noise
/// N(0, σ²) rounded to 6 decimals, from the same deterministic random
/// stream as Example 1 (examples/random_stream.h).
///
/// The initial model has the LPV part exactly and declares the offset basis
/// {1, rho1, rho1^2} WITHOUT values: `lpvid identify` identifies φ
/// (Unknowns::offset). With noise-free data φ = (0.5, 0.8, −0.3) is
/// recovered (tests/examples/example2_test.cc).

#include <cstdint>

#include "core/scalar.h"
#include "data/experiment.h"
#include "model/lpv_model.h"

namespace lpvid {

struct Example2Options {
  int n = 40;                   ///< samples
  double noise_variance = 0.0;  ///< the paper's Example 2 uses 0.5 (for its own system)
  uint64_t seed = 1;
};

/// The true offset coefficients φ_j for the basis {1, ρ, ρ²}.
inline constexpr double kExample2Phi[3] = {0.5, 0.8, -0.3};

/// The true system above, with the offset values given; columns u1, y1, rho1.
LpvModel<Rational> example2_true_model();

/// The initial model: the true LPV part, multiplicative uncertainty weight
/// 0.01 (as Example 1), no correction basis, and the offset basis
/// {1, rho1, rho1^2} with unknown values.
LpvModel<Rational> example2_initial_model();

/// Generated experiment (deterministic for given options).
Experiment<Rational> example2_experiment(const Example2Options& options);

}  // namespace lpvid
