#include "jobs/plan.h"

#include <filesystem>

#include "core/file_io.h"
#include "core/input_error.h"
#include "core/number_text.h"

namespace lpvid::jobs {

nlohmann::ordered_json plan_json(const JobPlan& p) {
  nlohmann::ordered_json j;
  j["format"] = kJobsFormat;
  j["data"] = {{"path", p.data_path}, {"sha256", p.data_sha256}, {"names", p.data_names}};
  j["model"] = {{"path", p.model_path}, {"sha256", p.model_sha256}};
  j["objective"] = {{"kind", p.objective}, {"delta", p.delta_text}, {"dmax", p.dmax_text}, {"lambda", p.lambda_text}};
  j["toeplitz"] = p.toeplitz;
  j["window"] = p.window;
  j["min_last"] = p.min_last;
  j["windows"] = nlohmann::ordered_json::array();
  for (const JobWindow& w : p.windows)
    j["windows"].push_back({{"index", w.index},
                            {"rows", {w.file_begin, w.file_end}},
                            {"model", w.model},
                            {"certificate", w.certificate},
                            {"report", w.report},
                            {"x0", w.x0},
                            {"command", w.command}});
  if (p.joint)
    j["joint"] = {{"command", p.joint->command}, {"certificate", p.joint->certificate}, {"report", p.joint->report}};
  return j;
}

namespace {

/// The fields of one plan.json, each read with its file and field name in
/// the error.
struct PlanFields {
  std::string path;
  /// For a plan of an older lpvid (no model hash, toeplitz mode or window x0),
  /// which cannot say what its jobs must certify.
  std::string again = " (a plan of an older lpvid: run 'lpvid jobs plan' again)";

  const nlohmann::json& field(const nlohmann::json& obj, const char* key, const std::string& where) const {
    if (!obj.is_object() || !obj.contains(key)) throw InputError(path + ": " + where + key + ": missing");
    return obj.at(key);
  }
  std::string text_of(const nlohmann::json& obj, const char* key, const std::string& where) const {
    const nlohmann::json& v = field(obj, key, where);
    if (!v.is_string()) throw InputError(path + ": " + where + key + ": expected a string");
    return v.get<std::string>();
  }

  /// format, data, model, toeplitz, objective, window, min_last.
  void read_header(const nlohmann::json& j, JobPlan& p) const {
    if (text_of(j, "format", "") != kJobsFormat)
      throw InputError(path + ": format: expected \"" + std::string(kJobsFormat) + "\"");
    const nlohmann::json& data = field(j, "data", "");
    p.data_path = text_of(data, "path", "data.");
    p.data_sha256 = text_of(data, "sha256", "data.");
    for (const auto& name : field(data, "names", "data.")) p.data_names.push_back(name.get<std::string>());
    const nlohmann::json& model = field(j, "model", "");
    if (!j.contains("toeplitz") || !model.is_object() || !model.contains("sha256"))
      throw InputError(path + ": toeplitz, model.sha256: missing" + again);
    p.model_path = text_of(model, "path", "model.");
    p.model_sha256 = text_of(model, "sha256", "model.");
    p.toeplitz = text_of(j, "toeplitz", "");
    if (p.toeplitz != "signal" && p.toeplitz != "paper")
      throw InputError(path + ": toeplitz: expected \"signal\" or \"paper\"");
    const nlohmann::json& obj = field(j, "objective", "");
    p.objective = text_of(obj, "kind", "objective.");
    p.delta_text = text_of(obj, "delta", "objective.");
    p.dmax_text = text_of(obj, "dmax", "objective.");
    p.lambda_text = text_of(obj, "lambda", "objective.");
    p.window = field(j, "window", "").get<long>();
    p.min_last = field(j, "min_last", "").get<long>();
  }

  /// windows[k].
  JobWindow read_window(const nlohmann::json& w, size_t k) const {
    const std::string where = "windows[" + std::to_string(k) + "].";
    JobWindow jw;
    jw.index = field(w, "index", where).get<int>();
    const nlohmann::json& rows = field(w, "rows", where);
    if (!rows.is_array() || rows.size() != 2 || !rows[0].is_number_integer() || !rows[1].is_number_integer())
      throw InputError(path + ": " + where + "rows: expected [begin, end]");
    jw.file_begin = rows[0].get<long>();
    jw.file_end = rows[1].get<long>();
    if (jw.file_begin < 0 || jw.file_end <= jw.file_begin) throw InputError(path + ": " + where + "rows: empty window");
    jw.model = text_of(w, "model", where);
    jw.certificate = text_of(w, "certificate", where);
    jw.report = text_of(w, "report", where);
    jw.command = text_of(w, "command", where);
    if (!w.contains("x0")) throw InputError(path + ": " + where + "x0: missing" + again);
    const nlohmann::json& x0 = w.at("x0");
    if (!x0.is_array()) throw InputError(path + ": " + where + "x0: expected an array of exact numbers as text");
    for (const auto& v : x0) {
      if (!v.is_string() || number_text_problem(v.get<std::string>()))
        throw InputError(path + ": " + where + "x0: expected exact numbers as text");
      jw.x0.push_back(v.get<std::string>());
    }
    return jw;
  }
};

}  // namespace

JobPlan read_plan(const std::string& dir) {
  const PlanFields f{(std::filesystem::path(dir) / "plan.json").string()};
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_text_file(f.path));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(f.path + ": not JSON: " + e.what());
  }
  JobPlan p;
  f.read_header(j, p);
  const nlohmann::json& windows = f.field(j, "windows", "");
  if (!windows.is_array() || windows.empty()) throw InputError(f.path + ": windows: expected a non-empty array");
  for (size_t k = 0; k < windows.size(); ++k) p.windows.push_back(f.read_window(windows[k], k));
  if (j.contains("joint")) {
    const nlohmann::json& joint = j.at("joint");
    p.joint = JointJob{f.text_of(joint, "command", "joint."), f.text_of(joint, "certificate", "joint."),
                       f.text_of(joint, "report", "joint.")};
  }
  return p;
}

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace lpvid::jobs
