#pragma once
/// A random oracle case: a random LPV case from the generators the property
/// tests use (examples/random_case.h), and a task on it, all reproducible
/// from one seed. The task's fixed values come from the generating truth:
///  - min_dmax at δ = δ_true, min_delta at d_max = d_true, weighted with λ = 1/2;
///  - identify at δ = δ_true, on a model with 1–2 correction basis functions
///    whose true θ made the data (truth.json);
///  - decide at (δ_true, d_true) (consistent by construction: the truth is a
///    witness) or at (δ_true/4, d_true/4) (often invalidated), by a coin.

#include <cstdint>
#include <vector>

#include "examples/random_case.h"
#include "oracle/task.h"

namespace lpvid {

struct RandomTaskOptions {
  RandomCaseOptions cases;
  std::vector<TaskKind> kinds = {TaskKind::kMinDmax, TaskKind::kMinDelta, TaskKind::kWeighted, TaskKind::kDecide};
  double tolerance = 0.01;
};

struct GeneratedCase {
  uint64_t seed = 0;
  RandomCase random;
  OracleTask task;
};

GeneratedCase random_oracle_case(uint64_t seed, const RandomTaskOptions& options);

}  // namespace lpvid
