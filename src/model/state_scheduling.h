#pragma once
/// Scheduling on the model's own simulated state (issue 9 item 3): a
/// quasi-LPV embedding of a state-dependent nonlinearity (cubic stiffness,
/// √level outflow) in the model of SPEC §2.
///
/// A scheduling variable whose data column is "@x<i>" (i = 1 … nx) is not
/// read from the data file: at sample k it is the model's own state
///
///   ρ_k = grid(x_k(i)),   x_{k+1} = A(ρ_k) x_k + B(ρ_k) u'_k,   x_0 = model.x0,
///
/// where grid(v) is the nearest multiple of 2^-kSchedulingGridBits (ties
/// upward: floor(v·2^b + 1/2)/2^b). The grid keeps the exact-rational
/// simulation's numbers bounded (without it A(ρ_k) x_k would square the
/// digits of x at every step); x itself is not rounded.
///
/// The exact trajectory is the definition: the certifier and the verifier
/// both compute it in rational arithmetic from the certified model (its x0
/// is the state at the first row of the certified window) and the input
/// columns, so Theorem 2.1's LMIs are checked along exactly that ρ. The
/// double simulation (fitting only) follows the same rule and may differ by
/// one grid step where x_k(i) lies within round-off of a grid midpoint.

#include <string>
#include <vector>

#include "core/scalar.h"
#include "data/column_map.h"

namespace lpvid {

constexpr int kSchedulingGridBits = 32;

/// (scheduling index j, state index i) for every "@x<i>" column of `rho`
/// (indices 0-based). Throws std::invalid_argument if i >= nx.
std::vector<std::pair<int, int>> state_scheduled(const std::vector<std::string>& rho_columns, int nx);

/// The nearest multiple of 2^-kSchedulingGridBits (ties upward).
double scheduling_grid(double v);
Rational scheduling_grid(const Rational& v);

}  // namespace lpvid
