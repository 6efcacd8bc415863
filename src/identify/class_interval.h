#pragma once
/// The class interval of an identification (docs/class_lower_bound.md):
/// [L_class, U], U the certified upper end of the identified θ's objective,
/// L_class the certified lower end over every θ of the region
/// (identify/class_bound.h). In the convex case (every unknown free) the
/// class solve's parameters are the class optimum: they are fixed and
/// certified too, and offered to the caller when their certified upper end
/// is lower (adopt_class_optimum takes them).

#include <optional>

#include "identify/class_bound.h"
#include "identify/fix_and_certify.h"
#include "model/problem.h"

namespace lpvid {

/// The class optimum found by the class bound (convex case), fixed and
/// certified like an identified θ.
struct ClassOptimum {
  FixedParameters fixed;
  CertifiedBounds bounds;
};

struct ClassInterval {
  ClassBoundResult bound;
  /// The class optimum, when it was certified with a lower upper end than the
  /// identified θ's: the caller decides whether to take it (adopt_class_optimum).
  std::optional<ClassOptimum> better;
  bool adopted = false;     ///< adopt_class_optimum replaced the identified θ by `better`
  double relative_gap = 0;  ///< (U − L_class)/U, U the upper end of `better` when there is one
};

/// `id` must hold a verified certification of an optimised objective (not
/// fixed bounds); it is not changed. Several records: not certified, reason
/// "no class bound: several records (not implemented)".
ClassInterval class_interval(const IdentifiedModel& id, const Problem& problem, const CertifyOptions& certify,
                             ClassBoundOptions options, SdpSolver& solver);

/// Takes the better class optimum of `interval`, if any, as the identified
/// model: id.fixed and id.bounds become it, interval.adopted is set.
void adopt_class_optimum(IdentifiedModel& id, ClassInterval& interval);

}  // namespace lpvid
