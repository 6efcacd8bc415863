#pragma once
/// A 3-input, 3-output nonlinear stand-in for the paper's Example 2 (Section
/// 4.2, eq. 20): the paper excites a helicopter simulator, stabilised by an
/// LQR loop, with three reference angles and measures the three Euler
/// angles. That simulator is not available; this is an unstable rigid body
/// of the same shape, in discrete time (forward Euler, h = 0.05 s):
///
///   θ_{k+1} = θ_k + h ω_k
///   ω_{k+1} = ω_k + h ( g ⊙ sin θ_k − c ω_k + N(θ_k, ω_k) + diag(cos θ_k) M τ_k )
///   N(θ, ω) = ( 5 θ2 θ3,  0.8 ω1 ω3,  4 θ1 θ2 )
///   g = (6, 4, 3) (destabilising, "gravity"),  c = 0.4,
///   M = [1 0.2 0; 0 1 0.2; 0.2 0 1] (torque mixing)
///
/// and the FIXED controller τ_k = −K_θ (θ_k − r_k) − K_ω ω_k − M⁻¹ diag(g) r_k:
/// K = [K_θ K_ω] is the discrete LQR gain of the plant linearised at the
/// origin (Q = diag(10⁴,10⁴,10⁴,100,100,100), R = I), computed once by iterating the
/// Riccati difference equation in double; the feed-forward makes the
/// linearised DC gain at the origin the identity. The closed loop from the
/// reference angles r (the paper's u) to y = θ is stable over the operating
/// range |r_i| ≤ 0.4 with the nonlinear static gain θ* = Φ(r*) (sin θ, the
/// products in N and cos θ in the torque make it non-affine; the θ2θ3 term
/// plays the role of the paper's u2*u3* in Φ).
///
/// Because the plant is the Euler step of a second-order system and only the
/// angles are measured, its linearisation at an equilibrium is EXACTLY a
/// second-order MIMO ARX model in θ̂ = θ − θ* (eliminate ω_k = (θ_{k+1} − θ_k)/h):
///
///   θ̂_{k+2} = (2I + h J_ω) θ̂_{k+1} − (I + h J_ω − h² J_θ) θ̂_k + h² J_r r̂_k
///
/// with J_θ, J_ω, J_r the Jacobians of the bracket above (controller
/// included) at (θ*, 0, r*). rigid_body_linearisation gives them.

#include <cstdint>
#include <vector>

#include "core/scalar.h"
#include "data/experiment.h"

namespace lpvid {

/// Sample time h of the plant (seconds).
inline constexpr double kRigidBodyStep = 0.05;
/// Half-width of the operating range: |r*_i| ≤ this (radians).
inline constexpr double kRigidBodyRange = 0.4;

/// The fixed state-feedback gain K = [K_θ K_ω] (3 × 6), computed once.
const Mat<double>& rigid_body_lqr_gain();

/// One closed-loop step: state x = (θ, ω) (6-vector) and reference r (3) →
/// next state.
Vec<double> rigid_body_step(const Vec<double>& x, const Vec<double>& r);

/// Closed-loop simulation from state x0 (6) under the reference rows of r
/// (n × 3); returns θ_k for k = 0 … n−1 (n × 3, row 0 = θ of x0).
Mat<double> rigid_body_simulate(const Mat<double>& r, const Vec<double>& x0);

/// Jacobians of the bracket of the ω update (controller included) at
/// (θ, ω = 0, r): J_θ = ∂/∂θ, J_ω = ∂/∂ω, J_r = ∂/∂r (each 3 × 3).
struct RigidBodyJacobians {
  Mat<double> theta, omega, ref;
};
RigidBodyJacobians rigid_body_linearisation(const Vec<double>& theta, const Vec<double>& r);

struct RigidBodyOptions {
  int settle = 40;               ///< part 1: samples after each step of u* before the pulses
  int pulses_per_point = 400;    ///< part 1: pulse samples at each operating point
  double pulse_amplitude = 0.1;  ///< part 1: û = ±this (radians)
  int ramp = 300;                ///< part 2: samples per slow ramp of u* (û = 0)
  int hold = 30;                 ///< part 2: samples held at each ramp's end
  int ramps = 40;                ///< part 2: number of ramps (fewer leave the cube poorly covered)
  int n = 200;                   ///< part 3: samples (the identification/invalidation record)
  double random_amplitude = 0.05;  ///< part 3: û = ±this
  /// Output noise variance (rad²; σ ≈ 0.0032 rad ≈ 0.18°). The paper's 0.5
  /// is on its helicopter's scale; here, with h = 0.05 s (J_r enters as
  /// h²·J_r), σ² = 1.5e-4 (0.5 deg²) leaves the part-1 ARX coefficients with
  /// errors of ~0.6 (bench/README.md), 1e-5 with ~0.08.
  double noise_variance = 1e-5;
  uint64_t seed = 1;
};

/// The paper's three-part experiment (Section 4.2, Figure 4), simulated in
/// one run (each part starts where the previous one ended). Columns: û in u
/// (u1..u3, the LPV model's input), y = θ measured (y1..y3), ρ = u* (rho1..rho3);
/// the plant's reference is u* + û. u, ρ are 4-decimal exact values, y the
/// double simulation rounded to 10 decimals plus N(0, σ²) noise rounded to
/// 6 decimals (examples/random_stream.h).
struct RigidBodyParts {
  /// Part 1: u* a square wave through the 8 corners of [−0.4, 0.4]³ and the
  /// origin, û = 0 while settling then ±pulse_amplitude random pulses.
  Experiment<Rational> local;
  /// Part 2: u* slow ramps between pseudo-random points of the range, û = 0;
  /// the last ramp ends where part 3 starts.
  Experiment<Rational> gain;
  /// Part 3: u* slowly varying, u*_i = 0.36 sin(2πk/T_i + φ_i) with
  /// T = (720, 600, 840) samples, φ = (−π/2, 0, π/2) (so the rate stays
  /// below 0.004 rad per sample: the closed loop's lag behind u*, which eq. 20
  /// does not model, stays near 0.01 rad), û random ±random_amplitude pulses.
  Experiment<Rational> validation;
};
RigidBodyParts rigid_body_experiment(const RigidBodyOptions& options);

/// The operating points of part 1, in visiting order (9 × 3).
Mat<double> rigid_body_corner_points();

}  // namespace lpvid
