#pragma once
/// Scheduling on the model's own simulated state: a quasi-LPV embedding of
/// a state-dependent nonlinearity (cubic stiffness, √level outflow,
/// overflow) in the model of docs/design.md §5.
///
/// A scheduling variable whose data column is a state form of
/// data/column_map.h is not read from the data file: at sample k it is a
/// function of the model's own state,
///
///   "@x<i>"            ρ_k = grid(x_k(i))
///   "@abs(x<i>-c)"     ρ_k = grid(|x_k(i) − c|)
///   "@sqrt(x<i>-c)"    ρ_k = grid(√|x_k(i) − c|)
///   "@hinge(x<i>-c)"   ρ_k = grid(max(x_k(i) − c, 0))
///   "@sqrtpos(x<i>-c)" ρ_k = grid(√max(x_k(i) − c, 0))  (Torricelli: no outflow below c)
///
/// with x_{k+1} = A(ρ_k) x_k + B(ρ_k) u'_k + E(ρ_k), x_0 = model.x0, where
/// grid(v) is the nearest multiple of 2^-kSchedulingGridBits (ties upward:
/// floor(v·2^b + 1/2)/2^b). The grid keeps the exact-rational simulation's
/// numbers bounded (without it A(ρ_k) x_k would square the digits of x at
/// every step); x itself is not rounded. The rounded square root is exact in
/// Rational: grid(√v) = floor(√(v·4^b) + 1/2)/2^b, computed with an integer
/// square root and one exact comparison (scheduling_grid_sqrt).
///
/// The exact trajectory is the definition: the certifier and the verifier
/// both compute it in rational arithmetic from the certified model (its x0
/// is the state at the first row of the certified window) and the input
/// columns, so Theorem 2.1's LMIs are checked along exactly that ρ. The
/// double simulation (fitting only) follows the same rule and may differ by
/// one grid step where the value lies within round-off of a grid midpoint.

#include <string>
#include <vector>

#include "core/scalar.h"
#include "data/column_map.h"

namespace lpvid {

constexpr int kSchedulingGridBits = 32;

/// (scheduling index j, state index i) for every state column of `rho` (any
/// form of data/column_map.h; indices 0-based). Throws std::invalid_argument
/// naming the column if i >= nx or the text does not parse.
std::vector<std::pair<int, int>> state_scheduled(const std::vector<std::string>& rho_columns, int nx);

/// One state-scheduling column with its shift c read as T.
template <typename T>
struct StateScheduled {
  int j = 0;  ///< scheduling index (0-based)
  int i = 0;  ///< state index (0-based)
  StateFunction function = StateFunction::kState;
  T shift = T(0);
};

/// Every state column of `rho` with its function and shift (exact for
/// Rational). Throws std::invalid_argument like state_scheduled.
template <typename T>
std::vector<StateScheduled<T>> state_functions(const std::vector<std::string>& rho_columns, int nx);

/// The nearest multiple of 2^-kSchedulingGridBits (ties upward).
double scheduling_grid(double v);
Rational scheduling_grid(const Rational& v);

/// grid(√|v|): floor(√|v|·2^b + 1/2)/2^b. Exact for Rational; the double
/// version rounds √ once and may differ by one grid step at a midpoint.
double scheduling_grid_sqrt(double v);
Rational scheduling_grid_sqrt(const Rational& v);

/// ρ of one state column at state value x: grid(f(x − c)) (see above).
double state_function_value(StateFunction f, double x, double shift);
Rational state_function_value(StateFunction f, const Rational& x, const Rational& shift);

/// The column text of a state function with a double shift c, written with
/// the shortest decimal that reads back as the same double (so re-reading
/// the text gives c exactly): "@sqrt(x1-0.25)", "@abs(x2+1.5)", "@x1" (the
/// identity ignores c, which must then be 0).
std::string state_column_text(StateFunction f, int state, double shift);

extern template std::vector<StateScheduled<double>> state_functions<double>(const std::vector<std::string>&, int);
extern template std::vector<StateScheduled<Rational>> state_functions<Rational>(const std::vector<std::string>&, int);

}  // namespace lpvid
