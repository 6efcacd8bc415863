#pragma once
/// What a bound search minimises (docs/design.md §7.6): δ for a given d_max, d_max for a
/// given δ, the weighted λ·δ² + (1−λ)·d_max², or nothing (decide consistency
/// for given δ and d_max). d_max is the RMS bound ‖d‖₂ ≤ d_max·√(n·ny).

#include <string>

#include "core/exact_bound.h"

namespace lpvid {

struct BoundObjective {
  enum class Kind {
    kMinDelta,     ///< d_max fixed (= dmax), minimise δ
    kMinDmax,      ///< δ fixed (= delta), minimise d_max
    kWeighted,     ///< minimise λ·δ² + (1−λ)·d_max²
    kFeasibility,  ///< δ and d_max both fixed: is the model consistent?
  };
  Kind kind = Kind::kWeighted;
  ExactBound delta;     ///< the fixed δ (kMinDmax, kFeasibility): exact for certificates, approx for solvers
  ExactBound dmax;      ///< the fixed d_max (kMinDelta, kFeasibility)
  double lambda = 0.5;  ///< λ ∈ [0, 1] (kWeighted); the default is 0.5

  bool delta_fixed() const { return kind == Kind::kMinDmax || kind == Kind::kFeasibility; }
  bool dmax_fixed() const { return kind == Kind::kMinDelta || kind == Kind::kFeasibility; }
  /// The objective value λδ² + (1−λ)d² (kWeighted), δ² (kMinDelta), d² (kMinDmax), 0.
  double value(double delta2, double dmax2) const;
  /// Human-readable, e.g. "minimise delta for dmax = 0.3".
  std::string describe() const;
  /// Throws InputError for λ outside [0, 1] or a negative/non-finite bound.
  void validate() const;
};

}  // namespace lpvid
