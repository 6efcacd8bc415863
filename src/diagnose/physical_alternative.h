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

#include "diagnose/fold_plan.h"

namespace lpvid {

/// The kinds in the tie rule's order of physical form: a named mechanism
/// before a generic expansion (a delay, a saturation, a dead zone, a sensor's
/// |.|, a state nonlinearity, a polynomial map, a piecewise-linear map, a
/// basis term). Unknown kinds come last.
int physical_form_rank(const std::string& kind);

/// Kinds that describe a mechanism: everything before input_polynomial in
/// physical_form_rank's order, and the output offset.
bool is_physical_kind(const std::string& kind);

/// For a round whose choice `chosen` (index into `ranked`) is a black-box
/// kind: the best-ranked physical candidate with finite per-fold figures, if
/// it is indistinguishable from the choice (see above); `taken` when it is
/// among `accepted`. Empty otherwise (a physical choice, no physical
/// candidate, fewer than 2 folds, or a clear difference).
/// A physical candidate the folds do not tell apart from a black-box choice.
struct PhysicalAlternative {
  int black_box = -1;          ///< index into RankingRound::ranked: the chosen black-box map
  int physical = -1;           ///< index into ranked: the best-ranked physical candidate
  std::vector<double> differences;  ///< d_j per fold (physical minus black box)
  double mean = 0, standard_error = 0;
  bool taken = false;          ///< the physical form passed the rule and replaced the black box
};

/// What the comparison reads of a ranked candidate.
struct RankedFigures {
  std::string kind;
  FoldFigures folds;  ///< its held-out figures per fold
};

std::optional<PhysicalAlternative> physical_alternative(const std::vector<RankedFigures>& ranked,
                                                        const std::vector<int>& accepted, int chosen);

}  // namespace lpvid
