#include "diagnose/fold_plan.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/input_error.h"

namespace lpvid {

Eigen::Index holdout_cut(Eigen::Index n, double holdout) {
  if (!(holdout > 0 && holdout < 1)) throw InputError("--holdout must be in (0, 1)");
  const auto cut = static_cast<Eigen::Index>(std::floor(static_cast<double>(n) * (1.0 - holdout)));
  if (cut < 10 || n - cut < 10)
    throw InputError("--holdout " + std::to_string(holdout) + " leaves fewer than 10 samples on one side of " +
                     std::to_string(n));
  return cut;
}

std::vector<FoldBlock> blocked_folds(Eigen::Index n, int k, Eigen::Index warmup) {
  if (k < 2) throw InputError("--folds must be at least 2 (got " + std::to_string(k) + ")");
  std::vector<FoldBlock> out;
  for (int j = 0; j < k; ++j) {
    const Eigen::Index first = n * j / k, last = n * (j + 1) / k;
    if (last - first <= 2 * warmup)
      throw InputError(std::to_string(k) + " folds of " + std::to_string(n) + " estimation samples are " +
                       std::to_string(last - first) + " samples long: each needs more than twice the warm-up of " +
                       std::to_string(warmup) + " samples (use fewer folds or a shorter warm-up)");
    out.push_back({first, last});
  }
  return out;
}

double FoldFigures::rms(size_t j) const {
  if (!std::isfinite(sse[j]) || count[j] == 0) return std::numeric_limits<double>::infinity();
  return std::sqrt(sse[j] / static_cast<double>(count[j]));
}

double FoldFigures::total_rms() const {
  double s = 0;
  Eigen::Index c = 0;
  for (size_t j = 0; j < sse.size(); ++j) {
    s += sse[j];
    c += count[j];
  }
  if (sse.empty() || !std::isfinite(s) || c == 0) return std::numeric_limits<double>::infinity();
  return std::sqrt(s / static_cast<double>(c));
}

int folds_won(const FoldFigures& candidate, const FoldFigures& reference) {
  int won = 0;
  for (size_t j = 0; j < candidate.sse.size() && j < reference.sse.size(); ++j)
    if (candidate.sse[j] < reference.sse[j]) ++won;
  return won;
}

bool accepts(const FoldFigures& candidate, const FoldFigures& reference, double min_gain) {
  if (candidate.sse.size() != reference.sse.size() || candidate.empty()) return false;
  const int need = static_cast<int>(candidate.sse.size()) / 2 + 1;
  const double c = candidate.total_rms(), r = reference.total_rms();
  return folds_won(candidate, reference) >= need && std::isfinite(c) && c <= (1.0 - min_gain) * r;
}

std::string acceptance_rule_text(size_t folds, double min_gain) {
  const size_t need = folds / 2 + 1;
  char gain[32];
  std::snprintf(gain, sizeof gain, "%g", 100.0 * min_gain);
  return "an effect is accepted if it lowers the held-out free-run error on at least " + std::to_string(need) + " of " +
         std::to_string(folds) + " folds and the held-out RMS over all folds by at least " + gain + " %";
}

}  // namespace lpvid
