#include "diagnose/fold_plan.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

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

namespace {

/// [first, first + length) of every record.
std::vector<FoldBlock> record_spans(const std::vector<Eigen::Index>& lengths) {
  if (lengths.empty()) throw std::invalid_argument("folds: no record lengths");
  std::vector<FoldBlock> out;
  Eigen::Index first = 0;
  for (const Eigen::Index len : lengths) {
    out.push_back({first, first + len});
    first += len;
  }
  return out;
}

/// Blocks per record: at least one each, k in all, by length (largest remainders).
std::vector<int> blocks_per_record(const std::vector<FoldBlock>& spans, int k, Eigen::Index n) {
  const size_t r = spans.size();
  std::vector<int> share(r, 1);
  if (k <= static_cast<int>(r)) return share;
  std::vector<double> rest(r);
  int given = static_cast<int>(r);
  for (size_t i = 0; i < r; ++i) {
    const double exact = static_cast<double>(k - static_cast<int>(r)) * static_cast<double>(spans[i].last - spans[i].first) /
                         static_cast<double>(n);
    share[i] += static_cast<int>(std::floor(exact));
    rest[i] = exact - std::floor(exact);
    given += static_cast<int>(std::floor(exact));
  }
  for (; given < k; ++given) {
    size_t best = 0;
    for (size_t i = 1; i < r; ++i)
      if (rest[i] > rest[best]) best = i;
    ++share[best];
    rest[best] = -1;
  }
  return share;
}

}  // namespace

std::vector<FoldBlock> blocked_folds(const std::vector<Eigen::Index>& lengths, int k, Eigen::Index warmup) {
  const std::vector<FoldBlock> spans = record_spans(lengths);
  const Eigen::Index n = spans.back().last;
  if (k < 2) throw InputError("--folds must be at least 2 (got " + std::to_string(k) + ")");
  const std::vector<int> share = blocks_per_record(spans, k, n);
  std::vector<FoldBlock> out;
  for (size_t i = 0; i < spans.size(); ++i) {
    const Eigen::Index len = spans[i].last - spans[i].first;
    if (share[i] == 1) {
      if (len <= 2 * warmup)
        throw InputError("record " + std::to_string(i + 1) + " has " + std::to_string(len) +
                         " samples: a fold needs more than twice the warm-up of " + std::to_string(warmup) + " samples");
      out.push_back(spans[i]);
      continue;
    }
    for (const FoldBlock& b : blocked_folds(len, share[i], warmup)) out.push_back({spans[i].first + b.first, spans[i].first + b.last});
  }
  return out;
}

std::vector<FoldBlock> training_pieces(const std::vector<Eigen::Index>& lengths, const std::vector<FoldBlock>& blocks,
                                       size_t t) {
  const FoldBlock& b = blocks[t];
  std::vector<FoldBlock> out;
  for (const FoldBlock& s : record_spans(lengths)) {
    if (b.last <= s.first || b.first >= s.last) {
      out.push_back(s);
      continue;
    }
    const FoldBlock before{s.first, b.first}, after{b.last, s.last};
    const FoldBlock& longer = before.last - before.first >= after.last - after.first ? before : after;
    if (longer.last > longer.first) out.push_back(longer);
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
  char gain[32], floor[32];
  std::snprintf(gain, sizeof gain, "%g", 100.0 * min_gain);
  std::snprintf(floor, sizeof floor, "%g", 100.0 * kMinEstimationShare);
  return "an effect is accepted if it lowers the held-out free-run error on at least " + std::to_string(need) + " of " +
         std::to_string(folds) + " folds and the held-out RMS over all folds by at least " + gain +
         " %, and its added output explains at least " + floor + " % of the estimation residual";
}

}  // namespace lpvid
