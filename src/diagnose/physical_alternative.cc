#include "diagnose/physical_alternative.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace lpvid {

int physical_form_rank(const std::string& kind) {
  static const char* const order[] = {"input_delay",       "input_saturation", "output_saturation",
                                      "dead_zone",         "abs_value",        "state_nonlinearity",
                                      "input_polynomial",  "output_polynomial", "output_piecewise_linear",
                                      "basis_term"};
  for (size_t i = 0; i < std::size(order); ++i)
    if (kind == order[i]) return static_cast<int>(i);
  return static_cast<int>(std::size(order));
}

bool is_physical_kind(const std::string& kind) {
  return kind == "output_offset" || physical_form_rank(kind) < physical_form_rank("input_polynomial");
}

std::optional<PhysicalAlternative> physical_alternative(const std::vector<RankedFigures>& ranked,
                                                        const std::vector<int>& accepted, int chosen) {
  if (chosen < 0 || static_cast<size_t>(chosen) >= ranked.size()) return std::nullopt;
  const RankedFigures& box = ranked[static_cast<size_t>(chosen)];
  if (is_physical_kind(box.kind) || physical_form_rank(box.kind) >= physical_form_rank("unknown kind"))
    return std::nullopt;
  const size_t k = box.folds.sse.size();
  if (k < 2) return std::nullopt;
  for (size_t i = 0; i < ranked.size(); ++i) {
    const RankedFigures& c = ranked[i];
    if (!is_physical_kind(c.kind) || c.folds.sse.size() != k) continue;
    PhysicalAlternative a;
    a.black_box = chosen;
    a.physical = static_cast<int>(i);
    for (size_t j = 0; j < k; ++j) a.differences.push_back(c.folds.rms(j) - box.folds.rms(j));
    if (!std::all_of(a.differences.begin(), a.differences.end(), [](double d) { return std::isfinite(d); })) continue;
    double sum = 0;
    for (double d : a.differences) sum += d;
    a.mean = sum / static_cast<double>(k);
    double ss = 0;
    for (double d : a.differences) ss += (d - a.mean) * (d - a.mean);
    a.standard_error = std::sqrt(ss / static_cast<double>(k - 1)) / std::sqrt(static_cast<double>(k));
    // the best-ranked physical candidate decides: a clear difference ends the search
    if (a.mean > a.standard_error) return std::nullopt;
    a.taken = std::find(accepted.begin(), accepted.end(), a.physical) != accepted.end();
    return a;
  }
  return std::nullopt;
}

}  // namespace lpvid
