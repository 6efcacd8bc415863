#include "fit/record_states.h"

#include <algorithm>

namespace lpvid {

namespace {

using Where = ParameterSlot::Where;

bool same_slots(const std::vector<ParameterSlot>& a, const std::vector<ParameterSlot>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const ParameterSlot& s, const ParameterSlot& t) {
    return s.where == t.where && s.term == t.term && s.row == t.row && s.col == t.col;
  });
}

}  // namespace

bool later_record_state(const ParameterSlot& s) { return s.where == Where::kX0 && s.term >= 1; }

std::optional<RecordStateFit> with_record_states(const LpvModel<double>& model, const std::vector<ParameterSlot>& slots,
                                                 const std::vector<Eigen::Index>& record_lengths,
                                                 const std::function<bool(Eigen::Index, Eigen::Index)>& has_cost) {
  RecordStateFit out{model, {}};
  const size_t later = record_lengths.empty() ? 0 : record_lengths.size() - 1;
  const Vec<double> start = model.x0.size() == model.nx ? model.x0 : Vec<double>(Vec<double>::Zero(model.nx));
  bool changed = out.model.later_x0.size() != later;
  out.model.later_x0.resize(later);
  for (Vec<double>& x : out.model.later_x0)
    if (x.size() != model.nx) {
      x = start;
      changed = true;
    }
  std::copy_if(slots.begin(), slots.end(), std::back_inserter(out.slots), [](const ParameterSlot& s) { return !later_record_state(s); });
  const bool fits_x0 = std::any_of(slots.begin(), slots.end(), [](const ParameterSlot& s) { return s.where == Where::kX0; });
  if (fits_x0) {
    Eigen::Index begin = record_lengths.empty() ? 0 : record_lengths[0];
    for (size_t k = 1; k < record_lengths.size(); ++k) {
      if (has_cost(begin, begin + record_lengths[k]))
        for (const ParameterSlot& s : record_x0_slots(out.model, static_cast<int>(k))) out.slots.push_back(s);
      begin += record_lengths[k];
    }
  }
  if (!changed && same_slots(out.slots, slots)) return std::nullopt;
  return out;
}

}  // namespace lpvid
