#pragma once
/// How far a test record leaves the estimation record's range, signal by
/// signal. A model fitted on the estimation record is only supported by
/// data inside the range each measured signal covered there; a static map
/// or a scheduled coefficient evaluated beyond it is an extrapolation. The
/// diagnosis report states the excursion of every test record so that a
/// test figure is read with it (it is reported, never used to choose).
#include <vector>

#include "data/experiment.h"

namespace lpvid {

/// Which measured signal of an experiment: an input u, an output y or a
/// scheduling column ρ (its column within that role).
enum class SignalRole { kInput, kOutput, kScheduling };

/// One signal of a test record against the same signal of the estimation record.
struct SignalExcursion {
  SignalRole role = SignalRole::kInput;
  Eigen::Index column = 0;
  double estimation_lo = 0, estimation_hi = 0;  ///< its range on the estimation record
  double test_lo = 0, test_hi = 0;              ///< its range on the test record
  Eigen::Index samples = 0;                     ///< test samples
  Eigen::Index below = 0, above = 0;            ///< test samples below estimation_lo / above estimation_hi

  Eigen::Index outside() const { return below + above; }
  /// The share of the test samples outside the estimation range, in [0, 1].
  double outside_share() const { return samples == 0 ? 0.0 : static_cast<double>(outside()) / static_cast<double>(samples); }
  /// The farthest test sample beyond the estimation range, as a multiple of
  /// that range's width (0: inside; a constant estimation signal: the
  /// distance itself).
  double beyond() const;
};

/// Every input, output and scheduling column of `test` against the same
/// column of `estimation` (same column counts; throws std::invalid_argument
/// otherwise), in the order u, y, ρ. Non-finite samples are not counted.
std::vector<SignalExcursion> signal_excursions(const Experiment<double>& estimation, const Experiment<double>& test);

}  // namespace lpvid
