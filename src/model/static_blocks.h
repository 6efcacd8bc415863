#pragma once
/// Static blocks around the LPV part (docs/design.md §5.5; effect kinds §11.5): an input
/// delay, a static input map before the LPV system and a static output map
/// after it. They are what `lpvid diagnose` adds when the residual points to
/// a saturation, dead-zone, |·|, polynomial or delay; the model
/// file keeps them under "static" (lpvid-model/1, an added field):
///
///   "static": {"input_delay": 2,
///              "input":  {"kind": "saturation", "lower": -1, "upper": 1},
///              "output": {"kind": "polynomial", "coefficients": [0, 1, 0.2]}}
///
/// Semantics (applied channel by channel, the same map on every channel):
///   u'_k = g_in(u_{k−d})            d = input_delay; u_{k−d} := u_0 for k < d
///                                   (the record's first sample held: a
///                                   record need not start at rest)
///   x_{k+1} = A(ρ_k) x_k + B(ρ_k) u'_k,  ŷ_k = C(ρ_k) x_k + D(ρ_k) u'_k,
///   z_k = C1(ρ_k) x_k + D1(ρ_k) u'_k   (uncertainty channel, before g_out)
///   y_k = g_out(ŷ_k + Φ(ρ_k)) + w_k + d_k.
/// So Theorem 2.1 (eq. 11–12) applies unchanged with u replaced by u' and
/// the residual r = y − g_out(ŷ + Φ): the uncertainty and the noise enter
/// after the output map.
///
/// Every map uses only +, −, ×, comparisons: exact on rationals, so the
/// verifier recomputes them from the data text with no rounding.
///
/// Maps (v one scalar channel):
///   saturation   g(v) = min(max(v, lower), upper)
///   dead_zone    g(v) = v − upper (v > upper), v − lower (v < lower), else 0
///   abs          g(v) = |v|
///   polynomial   g(v) = Σ_k c_k v^k  (Horner); with a "range" [lo, hi]
///                (the argument's range on the data the map was fitted on)
///                the polynomial holds inside it and the map continues
///                linearly beyond it, with the polynomial's value and slope
///                at the nearer end: g(v) = p(hi) + p'(hi)·(v − hi) above hi,
///                p(lo) + p'(lo)·(v − lo) below lo. A fitted polynomial is no
///                evidence outside the range it saw, and a cubic's own tail
///                there can run anywhere; the linear continuation keeps the
///                map's trend at its edge (continuous, with a continuous
///                slope) and stays exact on rationals
///   piecewise_linear  knots x_0 < … < x_m (m ≥ 1), values g_0 … g_m: linear
///                interpolation between knots, the first and last segments
///                extended beyond them (a √, a one-sided clip, any monotone
///                or non-monotone curve up to the knots' resolution); exact on
///                rationals (one division by x_{i+1} − x_i)

#include <stdexcept>
#include <string>
#include <vector>

#include "core/scalar.h"

namespace lpvid {

enum class StaticKind { kIdentity, kSaturation, kDeadZone, kAbs, kPolynomial, kPiecewiseLinear };

/// "identity", "saturation", "dead_zone", "abs", "polynomial", "piecewise_linear".
inline const char* to_string(StaticKind k) {
  switch (k) {
    case StaticKind::kIdentity: return "identity";
    case StaticKind::kSaturation: return "saturation";
    case StaticKind::kDeadZone: return "dead_zone";
    case StaticKind::kAbs: return "abs";
    case StaticKind::kPolynomial: return "polynomial";
    case StaticKind::kPiecewiseLinear: return "piecewise_linear";
  }
  return "?";
}

/// Parses a kind name; false for an unknown name.
inline bool static_kind_from_string(const std::string& s, StaticKind& k) {
  for (StaticKind c : {StaticKind::kIdentity, StaticKind::kSaturation, StaticKind::kDeadZone, StaticKind::kAbs,
                       StaticKind::kPolynomial, StaticKind::kPiecewiseLinear})
    if (s == to_string(c)) {
      k = c;
      return true;
    }
  return false;
}

template <typename T>
struct StaticMap {
  StaticKind kind = StaticKind::kIdentity;
  T lower = T(0), upper = T(0);   ///< saturation and dead_zone (lower ≤ upper)
  std::vector<T> coefficients;    ///< polynomial c_0, c_1, … (at least one); piecewise_linear: the values g_i
  std::vector<T> knots;           ///< piecewise_linear x_0 < x_1 < … (as many as values, at least two)
  std::vector<T> range;           ///< polynomial: empty (everywhere the polynomial) or {lo, hi}, lo ≤ hi (see above)

  bool is_identity() const { return kind == StaticKind::kIdentity; }

  /// Throws std::invalid_argument when the parameters do not define a map.
  void check(const std::string& where) const {
    if ((kind == StaticKind::kSaturation || kind == StaticKind::kDeadZone) && !(lower <= upper))
      throw std::invalid_argument(where + ": lower must not exceed upper");
    if (kind == StaticKind::kPolynomial && coefficients.empty())
      throw std::invalid_argument(where + ": a polynomial needs at least one coefficient");
    if (!range.empty() && (kind != StaticKind::kPolynomial || range.size() != 2 || !(range[0] <= range[1])))
      throw std::invalid_argument(where + ": a range is [lo, hi] with lo <= hi, on a polynomial map only");
    if (kind == StaticKind::kPiecewiseLinear) {
      if (knots.size() < 2 || knots.size() != coefficients.size())
        throw std::invalid_argument(where + ": a piecewise_linear map needs at least two knots and one value per knot");
      for (size_t i = 0; i + 1 < knots.size(); ++i)
        if (!(knots[i] < knots[i + 1])) throw std::invalid_argument(where + ": knots must be strictly increasing");
    }
  }

  T operator()(const T& v) const {
    switch (kind) {
      case StaticKind::kIdentity: return v;
      case StaticKind::kSaturation: return v < lower ? lower : (v > upper ? upper : v);
      case StaticKind::kDeadZone: return v > upper ? T(v - upper) : (v < lower ? T(v - lower) : T(0));
      case StaticKind::kAbs: return v < T(0) ? T(-v) : v;
      case StaticKind::kPolynomial: {
        if (range.size() == 2 && (v < range[0] || v > range[1])) {
          const T& e = v < range[0] ? range[0] : range[1];  // the nearer end
          T p = coefficients.back(), slope = T(0);          // p(e) and p'(e) by Horner
          for (size_t i = coefficients.size() - 1; i-- > 0;) {
            slope = T(slope * e + p);
            p = T(p * e + coefficients[i]);
          }
          return T(p + slope * T(v - e));
        }
        T acc = coefficients.back();
        for (size_t i = coefficients.size() - 1; i-- > 0;) acc = T(acc * v + coefficients[i]);
        return acc;
      }
      case StaticKind::kPiecewiseLinear: {
        if (knots.size() < 2 || knots.size() != coefficients.size())
          throw std::invalid_argument("piecewise_linear map: needs at least two knots and one value per knot");
        size_t i = 0;  // segment [x_i, x_{i+1}]: the last knot not above v, clamped to the end segments
        while (i + 2 < knots.size() && !(v < knots[i + 1])) ++i;
        const T t = T(T(v - knots[i]) / T(knots[i + 1] - knots[i]));
        return T(coefficients[i] + t * T(coefficients[i + 1] - coefficients[i]));
      }
    }
    return v;
  }

  /// The map applied entry by entry.
  Mat<T> apply(const Mat<T>& m) const {
    if (is_identity()) return m;
    Mat<T> out(m.rows(), m.cols());
    for (Eigen::Index i = 0; i < m.rows(); ++i)
      for (Eigen::Index j = 0; j < m.cols(); ++j) out(i, j) = (*this)(m(i, j));
    return out;
  }

  /// Number of scalar parameters (for the diagnose parameter count).
  int parameter_count() const {
    switch (kind) {
      case StaticKind::kIdentity:
      case StaticKind::kAbs: return 0;
      case StaticKind::kSaturation:
      case StaticKind::kDeadZone: return 2;
      case StaticKind::kPolynomial:
      case StaticKind::kPiecewiseLinear: return static_cast<int>(coefficients.size());
    }
    return 0;
  }
};

template <typename T>
struct StaticBlocks {
  int input_delay = 0;  ///< d ≥ 0 samples
  StaticMap<T> input, output;

  bool has_input() const { return input_delay != 0 || !input.is_identity(); }
  bool has_output() const { return !output.is_identity(); }
  bool empty() const { return !has_input() && !has_output(); }

  /// u' of the header: the delayed input (first sample held) through g_in.
  /// `u` is n × nu.
  Mat<T> model_input(const Mat<T>& u) const {
    if (!has_input()) return u;
    return input.apply(delayed_input(u));
  }
  /// u_{k−d}, the first sample held for k < d: the argument of g_in.
  Mat<T> delayed_input(const Mat<T>& u) const {
    if (input_delay < 0) throw std::invalid_argument("static.input_delay must be >= 0");
    Mat<T> delayed(u.rows(), u.cols());
    for (Eigen::Index k = 0; k < u.rows(); ++k)
      delayed.row(k) = u.row(k >= input_delay ? k - input_delay : 0);
    return delayed;
  }
};

}  // namespace lpvid
