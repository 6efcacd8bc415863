#pragma once
/// Exact check of a class claim ("class_lower_bound", "class_invalidated";
/// verify/certificate/class_terms.h, docs/class_lower_bound.md). Called by
/// check_certificate after the data have been read exactly; then:
///  1. the exact affine signals z0, Jz, r0, Jr of the certificate's initial
///     model and unknowns are built (toeplitz/affine_residual.h) and their
///     parameter names must equal class.parameters;
///  2. every free parameter's column of Jz is zero; the horizon is n minus the
///     samples where z is zero for every parameter;
///  3. the tree is walked: a split halves the box in its coordinate (a boxed
///     one with a positive radius); at each leaf z(p_c), r(p_c) are formed at
///     the box's centre, g is projected onto the complement of the free
///     columns of Jr, the dual point is evaluated exactly (dual equality,
///     Y1 ⪰ 0 as for a dual claim), and the penalties of the box give the
///     leaf's bound;
///  4. "class_lower_bound": every leaf's bound ≥ the claimed lower_bound;
///     "class_invalidated": every leaf's margin > 0.

#include <string>

#include "data/experiment.h"
#include "verify/certificate/certificate.h"
#include "verify/certificate/certificate_verdict.h"

namespace lpvid {

CertificateVerdict check_class_claim(const Certificate& c, const Experiment<Rational>& exp, std::string details);

}  // namespace lpvid
