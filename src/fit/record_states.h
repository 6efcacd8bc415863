#pragma once
/// Each record its own initial state in a fit over several records
/// (`lpvid diagnose --data a.csv --data b.csv`): one model, record 1 from
/// x0, record k ≥ 2 from LpvModel::later_x0[k-2]. The records are separate
/// runs of the plant, so no one state fits them all; a common x0 would charge
/// every record but one with a start-up error the model does not have.

#include <functional>
#include <optional>
#include <vector>

#include "fit/model_parameters.h"

namespace lpvid {

/// A slot of a later record's initial state (kX0 with term k >= 1): fits
/// derive these from the data's records (with_record_states), so they are no
/// part of what a candidate is.
bool later_record_state(const ParameterSlot& s);

/// A fit's model and slots with the records' initial states in place.
struct RecordStateFit {
  LpvModel<double> model;
  std::vector<ParameterSlot> slots;
};

/// The model's later_x0 sized to `record_lengths` (a new entry, or one of
/// another length, starts at x0; one record: none), and, when `slots` fit x0,
/// the slots of every later record whose rows [begin, end) hold cost samples
/// (`has_cost(begin, end)`): a record the cost does not reach leaves its
/// state as it is, and the slots of records the data do not have are dropped.
/// nullopt when the model and the slots are already so.
std::optional<RecordStateFit> with_record_states(const LpvModel<double>& model, const std::vector<ParameterSlot>& slots,
                                                 const std::vector<Eigen::Index>& record_lengths,
                                                 const std::function<bool(Eigen::Index, Eigen::Index)>& has_cost);

}  // namespace lpvid
