#pragma once
/// The oracle's task file (JSON, "format": "lpvid-oracle-task/1",
/// docs/oracle_task.schema.json): what an outside implementation is asked
/// about one case, i.e. one data file and one fixed model (Theorem 2.1 of
/// "Robust identification and invalidation of LPV systems"):
///
///   {"format": "lpvid-oracle-task/1",
///    "kind": "min_dmax" | "min_delta" | "weighted" | "decide" | "identify",
///    "data": "data.csv", "model": "model.json",     // beside the task file
///    "toeplitz_mode": "signal",
///    "noise_normalisation": "rms",                  // ‖d‖₂² ≤ n·ny·d_max²
///    "delta": "0.25",      // min_dmax, decide, identify: the fixed δ (exact decimal text)
///    "dmax": "0.031",      // min_delta, decide: the fixed d_max
///    "lambda": "0.5",      // weighted: minimise λδ² + (1−λ)d_max²
///    "tolerance": 0.01,    // relative slack before an answer is "suboptimal"
///    "info": {…}}          // free (seed, sizes, the generating truth)
///
/// "identify" (Theorem 3.1): the model has a correction basis f_i(ρ) with
/// unknown C_i, D_i (docs/design.md §11.1 "correction"); the task is to find them and the
/// least d_max at the fixed δ. The answer expected back is described in
/// oracle/answer.h.

#include <string>

#include <nlohmann/json.hpp>

#include "core/scalar.h"
#include "lmi/bound_objective.h"

namespace lpvid {

inline constexpr const char* kOracleTaskFormat = "lpvid-oracle-task/1";

enum class TaskKind { kMinDmax, kMinDelta, kWeighted, kDecide, kIdentify };

/// "min_dmax", "min_delta", "weighted", "decide", "identify".
const char* to_string(TaskKind kind);
/// The inverse of to_string; throws InputError naming `where` otherwise.
TaskKind task_kind_from_string(const std::string& text, const std::string& where);

struct OracleTask {
  TaskKind kind = TaskKind::kMinDmax;
  std::string data = "data.csv", model = "model.json";  ///< relative to the task file's folder
  std::string delta, dmax, lambda;  ///< exact decimal text of the fixed values (empty when not fixed)
  double tolerance = 0.01;
  nlohmann::ordered_json info = nlohmann::ordered_json::object();
};

/// The objective lpvid certifies for the task (fixed values as doubles; the
/// exact text goes to the certificate separately). identify: min d_max at δ.
BoundObjective objective_of(const OracleTask& task);

std::string task_json(const OracleTask& task);
/// Reads and checks a task (throws InputError "file:line: field: reason").
OracleTask parse_task(std::string_view text, const std::string& file);

}  // namespace lpvid
