#pragma once
/// Generated analogues of the real records on which `lpvid diagnose` was
/// measured (the real records are not in the repository).
/// Each is a known plant simulated in double precision on an estimation
/// and a test record (different input realisations), so the right effect
/// family and the achievable error are known by construction:
///
///   abs_sensor     (coupled electric drives) a lightly damped 3rd-order
///                  linear part v = G(q)u — a resonant pair at radius 0.96,
///                  angle 0.35 rad, and a real pole at 0.85 — measured
///                  through |·| and quantised to 0.005: y = round(|v|/0.005)·0.005.
///                  The input holds random levels for 8–24 samples; about
///                  30 % of its samples are negative (the belt reverses).
///                  Right family: abs_value.
///   tanks          (cascaded tanks) two tanks with √ outflow, Euler-discretised:
///                  h1+ = h1 − 0.2√h1 + 0.1u, h2+ = h2 + 0.2√h1 − 0.2√h2 (levels
///                  1 … 16 at rest, time constants 10–40 samples), the upper
///                  level clipped at 10 (overflow, active for u > 6.3), y = h2 +
///                  noise (std 0.01); u a random staircase in [2, 8] held 30–90 samples.
///                  Right family: state_nonlinearity (√ or the clip in the state).
///   duffing        a Duffing oscillator ẍ + 2ζω ẋ + ω² x + k3 x³ = u
///                  (cubic stiffness in the loop), RK4 at 0.1 s, excited by a
///                  random-phase multisine, y = x + noise (std 0.002).
///                  Right family: a state-scheduled A term (basis_term in A).
///   linear         (the control) the duffing plant with k3 = 0: nothing to find.

#include <cstdint>
#include <string>
#include <vector>

#include "data/experiment.h"

namespace lpvid {

struct PlantAnalogue {
  Experiment<double> estimation, test;  ///< columns u1, y1 (no scheduling)
  std::vector<std::string> right_kinds;  ///< diagnose's first chosen effect must be one of these ("none" for the control)
};

/// "abs_sensor", "tanks", "duffing", "linear".
const std::vector<std::string>& plant_analogue_names();

/// Throws InputError for an unknown name or n < 100.
PlantAnalogue make_plant_analogue(const std::string& name, int n, uint64_t seed);

/// Records of ONE abs_sensor plant (the coupled-drives analogue) with the
/// input staircase scaled by each amplitude (its own realisation per record,
/// the plant at rest at each record's start): experiments of one system at
/// several input amplitudes. Right family: abs_value. Throws like
/// make_plant_analogue for n < 100.
std::vector<Experiment<double>> abs_sensor_records(int n, const std::vector<double>& amplitudes, uint64_t seed);

}  // namespace lpvid
