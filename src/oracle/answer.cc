#include "oracle/answer.h"

#include <algorithm>
#include <vector>

#include "core/input_error.h"
#include "json/json_members.h"
#include "json/json_number.h"
#include "json/json_tree.h"
#include "model/simulate.h"

namespace lpvid {
namespace {

/// A claimed bound: an exact number ≥ 0.
Rational claimed_value(const JsonNode& root, const char* key, const std::string& file) {
  const JsonNode& n = member(root, key, file, "");
  const Rational q = number_from_json<Rational>(n, file, key);
  if (q < 0) throw_input_error(file, n.line, key, "a bound is >= 0");
  return q;
}

Witness parse_witness(const JsonNode& n, const std::string& file, Eigen::Index ny, Eigen::Index nz) {
  if (!n.is_object()) throw_input_error(file, n.line, "witness", "expected an object with delta_taps or w");
  Witness wit;
  const JsonNode* taps = n.find("delta_taps");
  const JsonNode* w = n.find("w");
  if ((taps != nullptr) == (w != nullptr))
    throw_input_error(file, n.line, "witness", "give either delta_taps (with delta_horizon) or w");
  if (taps) {
    wit.taps = matrix_member(*taps, file, "witness.delta_taps", ny * nz);
    wit.horizon = integer_member(member(n, "delta_horizon", file, "witness"), file, "witness.delta_horizon");
    if (wit.horizon < 1 || wit.horizon < wit.taps.rows())
      throw_input_error(file, n.line, "witness.delta_horizon", "must be at least 1 and at least the number of taps");
  } else {
    wit.taps_form = false;
    wit.w = matrix_member(*w, file, "witness.w", ny);
  }
  return wit;
}

/// θ of an identify answer: one object per correction basis function, keyed
/// by its text as the model writes it, each with C (ny × nx) and D (ny × nu).
Vec<Rational> parse_theta(const JsonNode& n, const std::string& file, const LpvModel<Rational>& model) {
  if (!n.is_object()) throw_input_error(file, n.line, "theta", "expected an object keyed by correction basis function");
  const CorrectionLayout L = output_correction_layout(model);
  Vec<Rational> theta(L.size());
  std::vector<std::string> names;
  for (const Monomial& f : model.correction.basis) names.push_back(f.text(model.scheduling));
  for (const auto& [key, value] : n.members)
    if (std::find(names.begin(), names.end(), key) == names.end())
      throw_input_error(file, value.line, "theta." + key, "not a correction basis function of the model");
  for (Eigen::Index i = 0; i < L.n_basis; ++i) {
    const std::string path = "theta." + names[static_cast<size_t>(i)];
    const JsonNode& t = member(n, names[static_cast<size_t>(i)].c_str(), file, "theta");
    const Mat<Rational> C = matrix_member(member(t, "C", file, path), file, path + ".C", L.nx);
    const Mat<Rational> D = matrix_member(member(t, "D", file, path), file, path + ".D", L.nu);
    if (C.rows() != L.n_out || D.rows() != L.n_out)
      throw_input_error(file, t.line, path, "C and D need " + std::to_string(L.n_out) + " rows");
    for (Eigen::Index r = 0; r < L.n_out; ++r) {
      for (Eigen::Index c = 0; c < L.nx; ++c) theta(L.index_C(i, r, c)) = C(r, c);
      for (Eigen::Index c = 0; c < L.nu; ++c) theta(L.index_D(i, r, c)) = D(r, c);
    }
  }
  return theta;
}

}  // namespace

OracleAnswer parse_answer(std::string_view text, const std::string& file, const OracleTask& task,
                          const LpvModel<Rational>& model) {
  const Eigen::Index ny = model.ny, nz = model.nz();
  const JsonNode root = parse_exact_json(text, file);
  if (!root.is_object()) throw_input_error(file, root.line, "", "an answer is a JSON object");
  if (string_member(root, "format", file, "") != kOracleAnswerFormat)
    throw_input_error(file, root.line, "format", std::string("expected \"") + kOracleAnswerFormat + "\"");
  static const std::vector<std::string> allowed = {"format", "status", "delta", "dmax", "verdict", "witness", "theta", "message"};
  for (const auto& [key, value] : root.members)
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      throw_input_error(file, value.line, key, "unknown key in an answer (known: format, status, delta, dmax, verdict, witness, theta, message)");
  OracleAnswer a;
  if (const JsonNode* m = root.find("message"); m && m->is_string()) a.message = m->text;
  if (const JsonNode* s = root.find("status")) {
    if (!s->is_string() || (s->text != "ok" && s->text != "failed"))
      throw_input_error(file, s->line, "status", "expected \"ok\" or \"failed\"");
    a.failed = s->text == "failed";
    if (a.failed) return a;
  }
  switch (task.kind) {
    case TaskKind::kMinDmax: a.dmax = claimed_value(root, "dmax", file); break;
    case TaskKind::kMinDelta: a.delta = claimed_value(root, "delta", file); break;
    case TaskKind::kWeighted:
      a.delta = claimed_value(root, "delta", file);
      a.dmax = claimed_value(root, "dmax", file);
      break;
    case TaskKind::kDecide: a.verdict = string_member(root, "verdict", file, ""); break;
    case TaskKind::kIdentify:
      a.dmax = claimed_value(root, "dmax", file);
      a.theta = parse_theta(member(root, "theta", file, ""), file, model);
      break;
  }
  if (const JsonNode* v = root.find("verdict"); v && !(v->is_string() && (v->text == "consistent" || v->text == "invalidated")))
    throw_input_error(file, v->line, "verdict", "expected \"consistent\" or \"invalidated\"");
  if (const JsonNode* w = root.find("witness")) {
    if (task.kind == TaskKind::kDecide && a.verdict == "invalidated")
      throw_input_error(file, w->line, "witness", "an \"invalidated\" verdict has no primal witness");
    a.witness = parse_witness(*w, file, ny, nz);
  }
  return a;
}

}  // namespace lpvid
