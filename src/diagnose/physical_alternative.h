#pragma once
/// Physics first: when a black-box map wins a round (a polynomial or
/// piecewise-linear static map, a basis term), the best-ranked candidate of
/// a physical form (a delay, a saturation, a dead zone, a sensor's |.|, a
/// state nonlinearity such as √, |.| or a hinge, an offset) may be just as
/// good on the held-out blocks. The blocked folds measure it: per fold j the
/// difference d_j = RMS_physical(j) − RMS_black-box(j); the two are
/// indistinguishable on these data when the mean of d is at most its
/// standard error s/√k (s the sample standard deviation over the k folds),
/// i.e. the black box is not better by more than one standard error of the
/// fold-to-fold spread. Then the physical form is taken if it passes the
/// acceptance rule itself, and the report states both with the per-fold
/// evidence either way (the black box staying when the physical form does
/// not pass). Fold mode only (one validation split has no spread).

#include <optional>
#include <string>
#include <vector>

#include "diagnose/effect_ranking.h"

namespace lpvid {

/// Kinds that describe a mechanism: everything before input_polynomial in
/// physical_form_rank's order, and the output offset.
bool is_physical_kind(const std::string& kind);

/// For a round whose choice `chosen` (index into `ranked`) is a black-box
/// kind: the best-ranked physical candidate with finite per-fold figures, if
/// it is indistinguishable from the choice (see above); `taken` when it is
/// among `accepted`. Empty otherwise (a physical choice, no physical
/// candidate, fewer than 2 folds, or a clear difference).
std::optional<PhysicalAlternative> physical_alternative(const std::vector<ScoredCandidate>& ranked,
                                                        const std::vector<int>& accepted, int chosen);

}  // namespace lpvid
