#pragma once
/// One leaf of a class certificate (verify/certificate/class_terms.h,
/// docs/class_lower_bound.md): from the structured barrier's central-path
/// point at the leaf's centre (solved with the free parameters as free
/// regressors) to an exactly evaluated dual point whose bound holds for every
/// parameter of the leaf's box, for the verifier's rebuild too.

#include <string>
#include <vector>

#include "certify/path_dual_build.h"
#include "verify/certificate/class_terms.h"

namespace lpvid {

struct ClassLeafBuild {
  std::string problem;  ///< why no leaf (empty when built)
  ClassNode node;       ///< the leaf (dual point, ε)
  Rational bound;       ///< its certified value (portable: any rebuild within the stated tolerance reaches it)
  /// Per boxed parameter (ClassSignals::boxed order): what its half-width
  /// costs the bound, ρ_i(2|⟨Jr_i, g⟩| + 2‖g‖·√t·‖Jz_i‖)/(scale of the objective) — where a split helps most.
  std::vector<double> cost;
};

ClassLeafBuild build_class_leaf(const ClassSignals& s, const Vec<Rational>& center, const Vec<Rational>& radius,
                                const DeltaFormSolution& solution, DualClaim claim, const FixedValues& fixed);

}  // namespace lpvid
