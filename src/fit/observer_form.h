#pragma once
/// A single-output LTI model in observer canonical form (Kailath, Linear
/// Systems, 1980, §2.1.3), the parametrisation of fit/linear_fit.h:
///
///   A = [ -a_1  1  0 … 0 ]      B (n × nu) free,   C = [1 0 … 0],   D (1 × nu) free
///       [ -a_2  0  1 … 0 ]
///       [  …             ]      x_{k+1} = A x_k + B u_k,   ŷ_k = C x_k + D u_k + c
///       [ -a_n  0  0 … 0 ]
///
/// so that ŷ = (D + C (zI − A)⁻¹ B) u has denominator zⁿ + a_1 zⁿ⁻¹ + … + a_n
/// (its roots are the eigenvalues of A), and c is an optional constant output
/// offset (Φ of eq. 20 with basis "1"). Every (a, B, D) is a minimal-parameter
/// description of an order-n transfer function, which is what output-error
/// refinement needs (no redundant directions).

#include <vector>

#include "core/scalar.h"
#include "model/lpv_model.h"

namespace lpvid {

struct ObserverForm {
  Vec<double> a;      ///< n denominator coefficients a_1..a_n
  Mat<double> B;      ///< n × nu
  Mat<double> D;      ///< 1 × nu
  Vec<double> x0;     ///< n, initial state
  bool has_offset = false;
  double offset = 0;  ///< c (used only when has_offset)

  int order() const { return static_cast<int>(a.size()); }
  int inputs() const { return static_cast<int>(B.cols()); }
  /// The companion matrix A above (n × n).
  Mat<double> A() const;
  /// Number of entries of parameters(): n + n·nu + nu + n (+1 with offset).
  int parameter_count() const;
  /// (a, vec(B) column-major, D, x0[, c]) as one vector, the layout used by
  /// the output-error refinement.
  Vec<double> parameters() const;
  /// Inverse of parameters() (size must be parameter_count()).
  void set_parameters(const Vec<double>& p);
};

/// A zero model of order n with nu inputs.
ObserverForm zero_observer_form(int n, int nu, bool has_offset);

/// Free-run output ŷ_k = C x_k + D u_k (+ c), k = 0 … N−1, from x_0 = f.x0;
/// u is N × nu. Returns an N-vector.
Vec<double> simulate_observer(const ObserverForm& f, const Mat<double>& u);

/// The output-error fits accept A as stable when its spectral radius is below
/// this: a root closer to the unit circle is a drift mode (seen on the dryer
/// data at orders ≥ 5) that a free run from 5 samples cannot pin down.
constexpr double kStableRadius = 0.999;

/// Largest |root| of zⁿ + a_1 zⁿ⁻¹ + … + a_n (= spectral radius of A); 0 for n = 0.
double spectral_radius(const Vec<double>& a);

/// Returns a unchanged if all roots have |λ| ≤ max_radius; otherwise moves
/// every root with |λ| ≥ 1 inside the unit disc (λ → 1/λ̄, the reflection that
/// keeps the amplitude response's shape), clamps |λ| to max_radius and returns
/// the new real coefficients. The default is inside kStableRadius, so the
/// result is an admissible start for the output-error fit.
Vec<double> stabilise_denominator(const Vec<double>& a, double max_radius = 0.998);

/// The model as an LpvModel with "scheduling": [] (docs/design.md §11.1): one term "1" per
/// matrix, offset {"basis": ["1"], "values": [[c]]} when present, x0.
LpvModel<double> to_lpv_model(const ObserverForm& f, const ColumnMap& columns);

}  // namespace lpvid
