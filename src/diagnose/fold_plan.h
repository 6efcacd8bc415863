#pragma once
/// Blocked cross-validation of the estimation record (docs/design.md §9.3 "held-out
/// folds"): the effects of `lpvid diagnose` are ranked and
/// accepted by free-run error on blocks of the estimation record that the
/// fit did not see, so that one lucky block of held-out rows cannot decide.
///
///   folds      K contiguous blocks B_1 … B_K of the n estimation samples
///              (sizes differ by at most one sample, in record order).
///   fit        fold j fits on the longer of the two contiguous stretches
///              of the record beside B_j (all of it for the first and the
///              last block, at least half of it otherwise), with its own x0.
///              Not on both sides at once: an output-error fit across the gap
///              (FitOptions::skip_first/skip_last) let a near-integrator mode
///              (spectral radius 0.995–0.999) bridge it on the dryer record
///              and the held-out error of that fold tripled.
///   score      the fold-j model on B_j alone, by the benchmark protocol
///              (warmup_score): x0 fitted on B_j's first `warmup` samples,
///              squared error summed over the rest of B_j.
///   total      held-out RMS = √(Σ_j SSE_j / Σ_j count_j).
///
/// Acceptance (accepts): a candidate beats the reference if it lowers the
/// held-out error on a clear majority of folds (more than half: 3 of 4,
/// 3 of 5) AND its total held-out RMS is at least `min_gain` below the
/// reference's total. Blocked rather than shuffled folds: the samples of a
/// dynamic system are not exchangeable, and a free run needs contiguous rows.

#include <string>
#include <vector>

#include "core/scalar.h"

namespace lpvid {

struct FoldBlock {
  Eigen::Index first = 0, last = 0;  ///< rows [first, last) of the estimation record
};

/// The one-split role plan (no folds): rows [0, cut) fit, rows [cut, n)
/// select the effects (the last `holdout` share of the record, 0 < holdout
/// < 1). Throws InputError when either side has fewer than 10 samples.
Eigen::Index holdout_cut(Eigen::Index n, double holdout);

/// K blocked folds of n samples. Throws InputError unless K >= 2 and every
/// block has more than 2·warmup samples (a warm-up and as many scored).
std::vector<FoldBlock> blocked_folds(Eigen::Index n, int k, Eigen::Index warmup);

/// Over the records of the given lengths (Experiment::record_lengths(), at
/// least one): the blocks are made WITHIN the records, never across
/// a seam. With k <= R records each record is one block (folds = records);
/// with k > R every record gets at least one block and the k blocks are
/// shared out in proportion to the records' lengths (largest remainders,
/// ties to the earlier record); each record's blocks are blocked_folds of it.
/// Throws InputError like blocked_folds for a block of at most 2·warmup
/// samples. One record of n samples gives blocked_folds(n, k, warmup).
std::vector<FoldBlock> blocked_folds(const std::vector<Eigen::Index>& lengths, int k, Eigen::Index warmup);

/// The rows fold t is fitted on, as separate records in row order: the
/// longer of the two stretches of block t's own record beside it (all of
/// that record's other rows when the block is at one end of it; nothing when
/// the block is the whole record) and every other record whole. One record:
/// the single stretch of the one-record rule above.
std::vector<FoldBlock> training_pieces(const std::vector<Eigen::Index>& lengths, const std::vector<FoldBlock>& blocks,
                                       size_t t);

/// Held-out figures of one model family over the folds (+inf when a fold's
/// fit or free run was not finite).
struct FoldFigures {
  std::vector<double> sse;           ///< Σ of squared errors on the scored rows of each block
  std::vector<Eigen::Index> count;   ///< scored entries (rows × outputs) of each block

  bool empty() const { return sse.empty(); }
  double rms(size_t j) const;   ///< held-out RMS of fold j
  double total_rms() const;     ///< √(Σ SSE / Σ count)
};

/// An effect must explain at least this share of the round's estimation
/// residual (ScoredCandidate::estimation_share) to be accepted, whatever its
/// held-out figures: a candidate whose added output is numerically absent on
/// the estimation record (a |.| of a state that never crosses its kink fitted
/// with a vanishing gain, measured at 1e-13 of the residual) cannot be the
/// effect the residual shows, and a held-out gain it brings comes from the
/// re-fit beside it. 0.1 %: far below any effect a report should name, far
/// above rounding.
inline constexpr double kMinEstimationShare = 0.001;

/// Folds on which `candidate` has a strictly lower SSE than `reference`.
int folds_won(const FoldFigures& candidate, const FoldFigures& reference);

/// The acceptance rule above (min_gain in [0, 1)).
bool accepts(const FoldFigures& candidate, const FoldFigures& reference, double min_gain);

/// "3 of 4 folds and at least 5 % on the total" and the share floor — the
/// rule in words.
std::string acceptance_rule_text(size_t folds, double min_gain);

}  // namespace lpvid
