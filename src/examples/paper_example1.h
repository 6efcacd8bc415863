#pragma once
/// Example 1 of the paper (Section 4.1, eq. 17): a 2×2 LPV system with
/// scheduling ρ1, ρ2 and an output factor ρ2² that the initial model lacks.
///
///   x_{k+1} = [0 1; −(0.3 + 0.01ρ1) −(0.6 + 0.6ρ2)] x_k + I u_k
///   y_k     = [ρ2² 0; 0 1] x_k (+ noise)
///
/// The paper's Figure 2 shows a decreasing trajectory; docs/design.md §12 warns that ρ1
/// and ρ2 must not be functions of each other, so here ρ1 decreases linearly
/// from 1 to 0 while ρ2 = 0.5 + 0.45 sin(2πk/17) oscillates. The input is a
/// random ±1 pulse train (hold times 1–5 samples) in each channel.
/// All u, ρ are short exact decimals; y is the EXACT rational simulation
/// rounded to 10 decimals, plus noise N(0, σ²) rounded to 6 decimals.

#include <cstdint>

#include "core/scalar.h"
#include "data/experiment.h"
#include "model/lpv_model.h"

namespace lpvid {

struct Example1Options {
  int n = 100;                  ///< samples
  double noise_variance = 0.0;  ///< the paper's Table II uses 0.1
  uint64_t seed = 1;
};

/// The true system, eq. (17), columns u1,u2,y1,y2,rho1,rho2.
LpvModel<Rational> example1_true_model();

/// The initial model S_I: eq. (17) with C = I (lacks the ρ2² factor), the
/// multiplicative uncertainty weight W = 0.01 of the paper, and the full
/// correction basis {1, ρ1, ρ2, ρ1ρ2, ρ1², ρ2²}.
LpvModel<Rational> example1_initial_model();

/// Generated experiment (deterministic for given options).
Experiment<Rational> example1_experiment(const Example1Options& options);

}  // namespace lpvid
