#include "lmi/bound_objective.h"

#include <cmath>
#include <sstream>

#include "core/input_error.h"

namespace lpvid {

double BoundObjective::value(double delta2, double dmax2) const {
  switch (kind) {
    case Kind::kMinDelta:
      return delta2;
    case Kind::kMinDmax:
      return dmax2;
    case Kind::kWeighted:
      return lambda * delta2 + (1.0 - lambda) * dmax2;
    case Kind::kFeasibility:
      return 0.0;
  }
  return 0.0;
}

std::string BoundObjective::describe() const {
  std::ostringstream o;
  switch (kind) {
    case Kind::kMinDelta:
      o << "minimise delta for dmax = " << dmax.approx;
      break;
    case Kind::kMinDmax:
      o << "minimise dmax for delta = " << delta.approx;
      break;
    case Kind::kWeighted:
      o << "minimise " << lambda << "*delta^2 + " << (1.0 - lambda) << "*dmax^2";
      break;
    case Kind::kFeasibility:
      o << "decide consistency for delta = " << delta.approx << ", dmax = " << dmax.approx;
      break;
  }
  return o.str();
}

void BoundObjective::validate() const {
  if (kind == Kind::kWeighted && !(lambda >= 0.0 && lambda <= 1.0))
    throw InputError("--lambda must lie in [0, 1], got " + std::to_string(lambda));
  if (delta_fixed() && !(std::isfinite(delta.approx) && delta.approx >= 0.0))
    throw InputError("--delta must be a finite number >= 0, got " + std::to_string(delta.approx));
  if (dmax_fixed() && !(std::isfinite(dmax.approx) && dmax.approx >= 0.0))
    throw InputError("--dmax must be a finite number >= 0, got " + std::to_string(dmax.approx));
}

}  // namespace lpvid
