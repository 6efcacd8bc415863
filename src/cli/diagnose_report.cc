#include "cli/diagnose_report.h"

#include <cstdio>

#include "diagnose/record_windows.h"

namespace lpvid::cli {

std::string test_rule_text(const FreeRunScore& score) {
  return "free run; x0 from the first " + std::to_string(score.warmup) +
         " samples (warm-up), RMS and fit % over the remaining " + std::to_string(score.scored);
}

std::string signal_column(const ColumnMap& names, SignalRole role, Eigen::Index column) {
  const std::vector<std::string>& list = role == SignalRole::kInput ? names.u : role == SignalRole::kOutput ? names.y : names.rho;
  const auto c = static_cast<size_t>(column);
  if (c < list.size() && !list[c].empty()) return list[c];
  return (role == SignalRole::kInput ? "u" : role == SignalRole::kOutput ? "y" : "rho") + std::to_string(column + 1);
}

const char* to_string(SignalRole role) {
  return role == SignalRole::kInput ? "input" : role == SignalRole::kOutput ? "output" : "scheduling";
}

std::string excursion_text(const SignalExcursion& e, const ColumnMap& test_names, const ColumnMap& estimation_names) {
  const auto g = [](double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", x);
    return std::string(buf);
  };
  const std::string name = signal_column(test_names, e.role, e.column);
  const std::string est = signal_column(estimation_names, e.role, e.column);
  std::string t = name + (e.role == SignalRole::kScheduling ? " (scheduling)" : "") + " " + g(e.test_lo) + " to " + g(e.test_hi) + " (estimation" + (est == name ? "" : " " + est) + " " +
                  g(e.estimation_lo) + " to " + g(e.estimation_hi) + "): ";
  if (e.outside() == 0) return t + "inside";
  t += std::to_string(e.outside()) + " of " + std::to_string(e.samples) + " samples outside (" +
       g(100.0 * e.outside_share()) + " %";
  if (e.below > 0) t += ", " + std::to_string(e.below) + " below";
  if (e.above > 0) t += ", " + std::to_string(e.above) + " above";
  return t + "), the farthest " + g(e.beyond()) + " of the estimation range's width beyond it";
}

std::vector<DataReference> fold_files(const DiagnoseReport& in) {
  if (in.records.size() < 2 || !in.est) return {};
  std::vector<DataReference> refs;
  for (const EstimationRecord& r : in.records) refs.push_back(r.data);
  std::vector<DataReference> out;
  for (const FoldBlock& b : in.result->rank.fold_blocks)
    out.push_back(piece_reference(refs, in.est->record_lengths(), {b.first, b.last}));
  return out;
}

}  // namespace lpvid::cli
