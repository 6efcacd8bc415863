#pragma once
/// The class interval of an identification (docs/class_lower_bound.md):
/// [L_class, U], U the certified upper end of the identified θ's objective,
/// L_class the certified lower end over every θ of the region
/// (identify/class_bound.h). In the convex case (every unknown free) the
/// class solve's parameters are the class optimum: they are fixed and
/// certified too, and adopted when their certified upper end is lower.

#include "identify/class_bound.h"
#include "identify/fix_and_certify.h"

namespace lpvid {

struct ClassInterval {
  ClassBoundResult bound;
  bool adopted = false;     ///< the class optimum replaced the identified θ (convex case)
  double relative_gap = 0;  ///< (U − L_class)/U, with U after adoption
};

/// `id` must hold a verified certification of an optimised objective (not
/// fixed bounds). May replace id.fixed and id.bounds (adopted). Several
/// records: not certified, reason "no class bound: several records (not
/// implemented)".
ClassInterval class_interval(IdentifiedModel& id, const LpvModel<Rational>& model_q, const LpvModel<double>& model_d,
                             const Experiment<Rational>& exp_q, const Experiment<double>& exp_d,
                             const CertifyOptions& certify, ClassBoundOptions options, SdpSolver& solver);

}  // namespace lpvid
