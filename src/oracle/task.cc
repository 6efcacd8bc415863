#include "oracle/task.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/input_error.h"
#include "core/number_text.h"
#include "json/json_members.h"
#include "json/json_number.h"
#include "json/json_tree.h"

namespace lpvid {

const char* to_string(TaskKind kind) {
  switch (kind) {
    case TaskKind::kMinDmax: return "min_dmax";
    case TaskKind::kMinDelta: return "min_delta";
    case TaskKind::kWeighted: return "weighted";
    case TaskKind::kDecide: return "decide";
    case TaskKind::kIdentify: return "identify";
  }
  return "?";
}

TaskKind task_kind_from_string(const std::string& text, const std::string& where) {
  for (TaskKind k : {TaskKind::kMinDmax, TaskKind::kMinDelta, TaskKind::kWeighted, TaskKind::kDecide, TaskKind::kIdentify})
    if (text == to_string(k)) return k;
  throw InputError(where + ": unknown task kind '" + text + "' (known: min_dmax, min_delta, weighted, decide, identify)");
}

BoundObjective objective_of(const OracleTask& task) {
  BoundObjective o;
  switch (task.kind) {
    case TaskKind::kMinDmax:
    case TaskKind::kIdentify: o.kind = BoundObjective::Kind::kMinDmax; break;
    case TaskKind::kMinDelta: o.kind = BoundObjective::Kind::kMinDelta; break;
    case TaskKind::kWeighted: o.kind = BoundObjective::Kind::kWeighted; break;
    case TaskKind::kDecide: o.kind = BoundObjective::Kind::kFeasibility; break;
  }
  if (!task.delta.empty()) o.delta = ExactBound::from_text(task.delta);
  if (!task.dmax.empty()) o.dmax = ExactBound::from_text(task.dmax);
  if (!task.lambda.empty()) o.lambda = double_from_text(task.lambda);
  return o;
}

std::string task_json(const OracleTask& task) {
  nlohmann::ordered_json j;
  j["format"] = kOracleTaskFormat;
  j["kind"] = to_string(task.kind);
  j["data"] = task.data;
  j["model"] = task.model;
  j["toeplitz_mode"] = "signal";
  j["noise_normalisation"] = "rms";
  if (!task.delta.empty()) j["delta"] = task.delta;
  if (!task.dmax.empty()) j["dmax"] = task.dmax;
  if (!task.lambda.empty()) j["lambda"] = task.lambda;
  j["tolerance"] = task.tolerance;
  j["info"] = task.info;
  return pretty_json(j);
}

namespace {

/// The exact text of a fixed bound: a non-negative number, kept as written.
std::string bound_text(const JsonNode& root, const char* key, const std::string& file) {
  const JsonNode& n = member(root, key, file, "");
  const Rational q = number_from_json<Rational>(n, file, key);
  if (q < 0) throw_input_error(file, n.line, key, "must be >= 0");
  return n.text;
}

void refuse(const JsonNode& root, const char* key, const std::string& file, const std::string& why) {
  if (const JsonNode* n = root.find(key)) throw_input_error(file, n->line, key, why);
}

}  // namespace

OracleTask parse_task(std::string_view text, const std::string& file) {
  const JsonNode root = parse_exact_json(text, file);
  if (!root.is_object()) throw_input_error(file, root.line, "", "a task is a JSON object");
  if (string_member(root, "format", file, "") != kOracleTaskFormat)
    throw_input_error(file, root.line, "format", std::string("expected \"") + kOracleTaskFormat + "\"");
  static const std::vector<std::string> allowed = {"format", "kind", "data", "model", "toeplitz_mode", "noise_normalisation",
                                                   "delta", "dmax", "lambda", "tolerance", "info"};
  for (const auto& [key, value] : root.members)
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      throw_input_error(file, value.line, key, "unknown key in a task");
  OracleTask t;
  t.kind = task_kind_from_string(string_member(root, "kind", file, ""), file + ": kind");
  t.data = string_member(root, "data", file, "");
  t.model = string_member(root, "model", file, "");
  if (const JsonNode* m = root.find("toeplitz_mode"); m && !(m->is_string() && m->text == "signal"))
    throw_input_error(file, m->line, "toeplitz_mode", "the oracle judges the signal mode only");
  if (const JsonNode* m = root.find("noise_normalisation"); m && !(m->is_string() && m->text == "rms"))
    throw_input_error(file, m->line, "noise_normalisation", "expected \"rms\"");
  const bool fixed_delta = t.kind == TaskKind::kMinDmax || t.kind == TaskKind::kDecide || t.kind == TaskKind::kIdentify;
  const bool fixed_dmax = t.kind == TaskKind::kMinDelta || t.kind == TaskKind::kDecide;
  const std::string kind = to_string(t.kind);
  if (fixed_delta) t.delta = bound_text(root, "delta", file);
  else refuse(root, "delta", file, "a " + kind + " task does not fix delta");
  if (fixed_dmax) t.dmax = bound_text(root, "dmax", file);
  else refuse(root, "dmax", file, "a " + kind + " task does not fix dmax");
  if (t.kind == TaskKind::kWeighted) {
    t.lambda = bound_text(root, "lambda", file);
    if (rational_from_text(t.lambda) > 1) throw_input_error(file, root.find("lambda")->line, "lambda", "must be in [0, 1]");
  } else {
    refuse(root, "lambda", file, "only a weighted task has lambda");
  }
  if (const JsonNode* tol = root.find("tolerance")) {
    t.tolerance = number_from_json<double>(*tol, file, "tolerance");
    if (!(t.tolerance >= 0) || !std::isfinite(t.tolerance)) throw_input_error(file, tol->line, "tolerance", "must be >= 0");
  }
  if (root.find("info")) t.info = nlohmann::ordered_json::parse(std::string(text), nullptr, true, true).at("info");
  return t;
}

}  // namespace lpvid
