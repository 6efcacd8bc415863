#include "verify/certificate/certificate_file.h"
#include "verify/certificate/work_budget.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/file_io.h"
#include "core/input_error.h"
#include "data/csv_reader.h"
#include "json/json_members.h"
#include "json/json_number.h"
#include "json/json_tree.h"
#include "model/model_file.h"
#include "verify/certificate/class_region_file.h"
#include "verify/certificate/dual_point_file.h"
#include "verify/certificate/number_range.h"

namespace lpvid {
namespace {

/// A dual claim's form and objective (which bound it claims).
void parse_dual_form(const JsonNode& root, const std::string& file, Certificate& c) {
  for (const char* key : {"delta_taps", "delta_horizon", "w"})
    if (const JsonNode* n = root.find(key)) throw_input_error(file, n->line, key, "dual claims do not carry this key");
  const std::string form = string_member(root, "form", file, "");
  const bool class_claim = is_class_claim(c.claim);
  if (form == "dual_delta") c.form = CertificateForm::kDualDelta;
  else if (form == "dual_delta_path") c.form = CertificateForm::kDualDeltaPath;
  else if (form == "zero_delta" && !class_claim) c.form = CertificateForm::kZeroDelta;
  else if (form == "nonnegative" && !class_claim) c.form = CertificateForm::kNonnegative;
  else
    throw_input_error(file, member(root, "form", file, "").line, "form",
                      class_claim ? "a class claim has form \"dual_delta\" or \"dual_delta_path\""
                                  : "a dual claim has form \"dual_delta\", \"dual_delta_path\", \"zero_delta\" or \"nonnegative\"");
  const JsonNode& objective_node = member(root, "objective", file, "");
  const std::string objective = string_member(root, "objective", file, "");
  const bool invalidated = c.claim == CertificateClaim::kInvalidated || c.claim == CertificateClaim::kClassInvalidated;
  if (objective == "feasibility" && invalidated) c.objective = DualClaim::kInvalidated;
  else if (objective == "min_delta" && !invalidated) c.objective = DualClaim::kMinDelta2;
  else if (objective == "min_dmax" && !invalidated) c.objective = DualClaim::kMinDmax2;
  else if (objective == "weighted" && !invalidated) c.objective = DualClaim::kWeighted;
  else
    throw_input_error(file, objective_node.line, "objective",
                      invalidated ? "the claim \"invalidated\" needs objective \"feasibility\""
                                  : "a lower bound needs objective \"min_delta\", \"min_dmax\" or \"weighted\"");
}

/// The values the objective fixes (δ², d_max², λ) and the claimed lower end.
void parse_dual_values(const JsonNode& root, const std::string& file, Certificate& c) {
  const bool delta_fixed = c.objective == DualClaim::kInvalidated || c.objective == DualClaim::kMinDmax2;
  const bool dmax_fixed = c.objective == DualClaim::kInvalidated || c.objective == DualClaim::kMinDelta2;
  const auto fixed = [&](const char* key, bool wanted, Rational& out) {
    const JsonNode* n = root.find(key);
    if (wanted && !n) throw_input_error(file, root.line, key, "missing (this objective fixes it)");
    if (!wanted && n) throw_input_error(file, n->line, key, "this objective does not fix it");
    if (n) out = number_from_json<Rational>(*n, file, key);
    if (n && out < 0) throw_input_error(file, n->line, key, "must be >= 0");
  };
  fixed("delta2", delta_fixed, c.delta2);
  fixed("dmax2", dmax_fixed, c.dmax2);
  fixed("lambda", c.objective == DualClaim::kWeighted, c.lambda);
  if (c.objective == DualClaim::kWeighted && c.lambda > 1)
    throw_input_error(file, member(root, "lambda", file, "").line, "lambda", "must be in [0, 1]");
  if (c.claim == CertificateClaim::kInvalidated || c.claim == CertificateClaim::kClassInvalidated) {
    if (const JsonNode* n = root.find("lower_bound"))
      throw_input_error(file, n->line, "lower_bound", "the claim \"invalidated\" carries no lower_bound");
  } else {
    c.lower_bound = number_from_json<Rational>(member(root, "lower_bound", file, ""), file, "lower_bound");
  }
}

/// The dual point: horizon, σ, g, then the form's own fields. A closed form
/// (verify/certificate/closed_form_check.h) carries none.
void parse_dual_point(const JsonNode& root, const std::string& file, Certificate& c) {
  if (is_closed_form(c.form)) {
    if (const JsonNode* n = root.find("dual"))
      throw_input_error(file, n->line, "dual", std::string("form \"") + to_string(c.form) + "\" carries no dual point");
    return;
  }
  c.dual = parse_dual_point_object(member(root, "dual", file, ""), file, "dual", c.model.ny, c.model.nz(), c.form);
}

/// The dual claims' fields (certificate_file.h).
void parse_dual_claim(const JsonNode& root, const std::string& file, const std::string& claim, Certificate& c) {
  c.claim = claim == "invalidated" ? CertificateClaim::kInvalidated : CertificateClaim::kLowerBound;
  parse_dual_form(root, file, c);
  parse_dual_values(root, file, c);
  parse_dual_point(root, file, c);
  if (const JsonNode* n = root.find("class")) throw_input_error(file, n->line, "class", "only class claims carry this key");
}

/// The class claims' fields (certificate_file.h): the dual claims' objective
/// and values, then the region and its tree of dual points.
void parse_class_claim(const JsonNode& root, const std::string& file, const std::string& claim, Certificate& c) {
  c.claim = claim == "class_invalidated" ? CertificateClaim::kClassInvalidated : CertificateClaim::kClassLowerBound;
  if (const JsonNode* n = root.find("dual")) throw_input_error(file, n->line, "dual", "a class claim carries its dual points in class.nodes");
  parse_dual_form(root, file, c);
  parse_dual_values(root, file, c);
  c.region = parse_class_region(member(root, "class", file, ""), file, c.model.ny, c.model.nz(), c.form);
}

/// The top level: known keys only, the format, the claim (returned) and the noise normalisation.
std::string parse_header(const JsonNode& root, const std::string& file) {
  if (!root.is_object()) throw_input_error(file, root.line, "", "a certificate is a JSON object");
  static const std::vector<std::string> allowed = {"format", "claim", "data", "records", "model", "toeplitz_mode",
                                                   "noise_normalisation", "delta2", "dmax2", "form",
                                                   "delta_taps", "delta_horizon", "w", "info",
                                                   "objective", "lambda", "lower_bound", "dual", "class"};
  for (const auto& [key, value] : root.members)
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      throw_input_error(file, value.line, key, "unknown key in a certificate");
  if (string_member(root, "format", file, "") != kCertificateFormat)
    throw_input_error(file, root.line, "format", std::string("expected \"") + kCertificateFormat + "\"");
  const std::string claim = string_member(root, "claim", file, "");
  if (claim != "consistent" && claim != "invalidated" && claim != "lower_bound" && claim != "not_a_witness" &&
      claim != "class_lower_bound" && claim != "class_invalidated")
    throw_input_error(file, member(root, "claim", file, "").line, "claim",
                      "expected \"consistent\", \"invalidated\", \"lower_bound\", \"not_a_witness\", "
                      "\"class_lower_bound\" or \"class_invalidated\"");
  if (string_member(root, "noise_normalisation", file, "") != "rms")
    throw_input_error(file, root.line, "noise_normalisation", "expected \"rms\" (||d||^2 <= n*ny*dmax^2)");
  return claim;
}

/// One data reference object ("data", or an entry of "records" at `path`): file, sha256, names, rows.
DataReference parse_reference_object(const JsonNode& data, const std::string& file, const std::string& path) {
  if (!data.is_object()) throw_input_error(file, data.line, path, "expected an object");
  DataReference d;
  d.file = string_member(data, "file", file, path);
  d.sha256 = string_member(data, "sha256", file, path);
  if (const JsonNode* names = data.find("names")) {
    if (!names->is_array()) throw_input_error(file, names->line, path + ".names", "expected a list of names");
    for (const auto& n : names->items) {
      if (!n.is_string()) throw_input_error(file, n.line, path + ".names", "expected strings");
      d.names.push_back(n.text);
    }
  }
  if (const JsonNode* rows = data.find("rows")) {
    if (!rows->is_array() || rows->items.size() != 2)
      throw_input_error(file, rows->line, path + ".rows", "expected [begin, end]");
    d.row_begin = integer_member(rows->items[0], file, path + ".rows[0]");
    d.row_end = integer_member(rows->items[1], file, path + ".rows[1]");
    if (d.row_end <= d.row_begin) throw_input_error(file, rows->line, path + ".rows", "empty window");
  }
  return d;
}

/// "records": two or more {file, sha256, names, rows, x0} (several records under one Δ).
void parse_records(const JsonNode& list, const std::string& file, Certificate& c) {
  if (!list.is_array() || list.items.size() < 2)
    throw_input_error(file, list.line, "records", "expected a list of two or more records (one record: \"data\")");
  c.records.clear();
  for (size_t k = 0; k < list.items.size(); ++k) {
    const std::string path = "records[" + std::to_string(k) + "]";
    const JsonNode& item = list.items[k];
    CertificateRecord r;
    r.data = parse_reference_object(item, file, path);
    for (const auto& [key, value] : item.members)
      if (key != "file" && key != "sha256" && key != "names" && key != "rows" && key != "x0")
        throw_input_error(file, value.line, path + "." + key, "unknown key in a record");
    if (const JsonNode* x0 = item.find("x0")) {
      if (!x0->is_array()) throw_input_error(file, x0->line, path + ".x0", "expected a list of numbers");
      r.x0 = Vec<Rational>(static_cast<Eigen::Index>(x0->items.size()));
      for (size_t i = 0; i < x0->items.size(); ++i)
        r.x0(static_cast<Eigen::Index>(i)) = number_from_json<Rational>(x0->items[i], file, path + ".x0[" + std::to_string(i) + "]");
    }
    c.records.push_back(r);
  }
}

/// "data" (one record) or "records" (several), exactly one of them.
void parse_data_reference(const JsonNode& root, const std::string& file, Certificate& c) {
  const JsonNode* records = root.find("records");
  if (records != nullptr) {
    if (root.find("data") != nullptr) throw_input_error(file, records->line, "records", "give either \"data\" or \"records\", not both");
    parse_records(*records, file, c);
    return;
  }
  c.records = {{parse_reference_object(member(root, "data", file, ""), file, "data"), {}}};
}

/// A primal point ("consistent", "not_a_witness"): δ², d_max² and the Δ taps or w.
void parse_primal_point(const JsonNode& root, const std::string& file, Certificate& c) {
  for (const char* key : {"objective", "lambda", "lower_bound", "dual", "class"})
    if (const JsonNode* n = root.find(key)) throw_input_error(file, n->line, key, "only dual claims carry this key");
  c.delta2 = number_from_json<Rational>(member(root, "delta2", file, ""), file, "delta2");
  c.dmax2 = number_from_json<Rational>(member(root, "dmax2", file, ""), file, "dmax2");
  const std::string form = string_member(root, "form", file, "");
  const Eigen::Index ny = c.model.ny, nz = c.model.nz();
  if (form == "delta") {
    c.form = CertificateForm::kDelta;
    c.taps = matrix_member(member(root, "delta_taps", file, ""), file, "delta_taps", ny * nz);
    c.horizon = integer_member(member(root, "delta_horizon", file, ""), file, "delta_horizon");
    if (c.horizon < c.taps.rows() || c.horizon < 1)
      throw_input_error(file, member(root, "delta_horizon", file, "").line, "delta_horizon",
                        "must be at least the number of delta_taps and at least 1");
    if (root.find("w")) throw_input_error(file, root.find("w")->line, "w", "form \"delta\" carries delta_taps, not w");
  } else if (form == "w") {
    c.form = CertificateForm::kW;
    c.w = matrix_member(member(root, "w", file, ""), file, "w", ny);
    if (root.find("delta_taps"))
      throw_input_error(file, root.find("delta_taps")->line, "delta_taps", "form \"w\" carries w, not delta_taps");
  } else {
    throw_input_error(file, member(root, "form", file, "").line, "form", "expected \"delta\" or \"w\"");
  }
}

}  // namespace


Certificate parse_certificate(std::string_view text, const std::string& file) {
  const JsonNode root = parse_exact_json(text, file);
  require_double_range(root, file);
  const std::string claim = parse_header(root, file);
  Certificate c;
  parse_data_reference(root, file, c);
  c.model = model_from_json<Rational>(member(root, "model", file, ""), file, "model");
  c.mode = toeplitz_mode_from_string(string_member(root, "toeplitz_mode", file, ""));
  if (claim == "invalidated" || claim == "lower_bound") {
    parse_dual_claim(root, file, claim, c);
    return c;
  }
  if (claim == "class_lower_bound" || claim == "class_invalidated") {
    parse_class_claim(root, file, claim, c);
    return c;
  }
  if (claim == "not_a_witness") c.claim = CertificateClaim::kNotAWitness;
  parse_primal_point(root, file, c);
  return c;
}

Certificate read_certificate(const std::string& path) {
  const std::string text = read_text_file(path);
  refuse_declared_text(text, path);  // before the exact parse's memory (verify/certificate/work_budget.h)
  return parse_certificate(text, path);
}

namespace {

/// A data reference as JSON ("data" or an entry of "records").
nlohmann::ordered_json reference_json(const DataReference& d) {
  nlohmann::ordered_json data;
  data["file"] = d.file;
  data["sha256"] = d.sha256;
  if (!d.names.empty()) data["names"] = d.names;
  if (d.row_end >= 0) data["rows"] = {d.row_begin, d.row_end};
  return data;
}

/// The objective, its fixed values and the claimed lower end (dual and class claims).
void objective_json(const Certificate& c, nlohmann::ordered_json& j) {
  const char* objective = c.objective == DualClaim::kInvalidated ? "feasibility"
                          : c.objective == DualClaim::kMinDelta2 ? "min_delta"
                          : c.objective == DualClaim::kMinDmax2  ? "min_dmax"
                                                                 : "weighted";
  j["objective"] = objective;
  if (c.objective == DualClaim::kInvalidated || c.objective == DualClaim::kMinDmax2) j["delta2"] = rational_to_json(c.delta2);
  if (c.objective == DualClaim::kInvalidated || c.objective == DualClaim::kMinDelta2) j["dmax2"] = rational_to_json(c.dmax2);
  if (c.objective == DualClaim::kWeighted) j["lambda"] = rational_to_json(c.lambda);
  if (c.claim == CertificateClaim::kLowerBound || c.claim == CertificateClaim::kClassLowerBound)
    j["lower_bound"] = rational_to_json(c.lower_bound);
  j["form"] = to_string(c.form);
}

}  // namespace

std::string certificate_json(const Certificate& c) {
  nlohmann::ordered_json j;
  j["format"] = kCertificateFormat;
  j["claim"] = to_string(c.claim);
  if (c.records.empty()) throw std::invalid_argument("a certificate names at least one record");
  if (c.records.size() == 1) {
    if (c.records.front().x0.size() > 0)
      throw std::invalid_argument("one record has the model's x0 (an own x0 is for several records)");
    j["data"] = reference_json(c.records.front().data);
  } else {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const CertificateRecord& r : c.records) {
      nlohmann::ordered_json item = reference_json(r.data);
      if (r.x0.size() > 0) item["x0"] = matrix_json(Mat<Rational>(r.x0.transpose()))[0];
      list.push_back(item);
    }
    j["records"] = list;
  }
  j["model"] = model_to_json(c.model);
  j["toeplitz_mode"] = to_string(c.mode);
  j["noise_normalisation"] = "rms";
  if (is_dual_claim(c.claim) || is_class_claim(c.claim)) {
    objective_json(c, j);
    if (is_class_claim(c.claim)) j["class"] = class_region_json(c.region, c.form);
    else if (!is_closed_form(c.form)) j["dual"] = dual_point_json(c.dual, c.form);
    j["info"] = c.info;
    return pretty_json(j);
  }
  j["delta2"] = rational_to_json(c.delta2);
  j["dmax2"] = rational_to_json(c.dmax2);
  if (c.form == CertificateForm::kDelta) {
    j["form"] = "delta";
    j["delta_taps"] = matrix_json(c.taps);
    j["delta_horizon"] = c.horizon;
  } else {
    j["form"] = "w";
    j["w"] = matrix_json(c.w);
  }
  j["info"] = c.info;
  return pretty_json(j);
}

void write_certificate(const std::string& path, const Certificate& c) {
  write_text_file(path, certificate_json(c), "certificate");
}

void set_data_reference(Certificate& c, const DataReference& data) { c.records = {{data, {}}}; }

void set_record_references(Certificate& c, const std::vector<DataReference>& records, const std::vector<Vec<Rational>>& x0) {
  if (records.empty()) throw std::invalid_argument("a certificate names at least one record");
  if (!x0.empty() && x0.size() != records.size())
    throw std::invalid_argument(std::to_string(x0.size()) + " initial states for " + std::to_string(records.size()) + " records");
  if (records.size() == 1) {
    set_data_reference(c, records.front());
    return;
  }
  c.records.clear();
  for (size_t k = 0; k < records.size(); ++k) c.records.push_back({records[k], x0.empty() ? Vec<Rational>() : x0[k]});
}

namespace {
/// `file` relative to `cert_dir` (absolute when there is no relative path).
std::string relative_to(const std::string& file, const std::filesystem::path& cert_dir) {
  namespace fs = std::filesystem;
  const fs::path data_abs = fs::absolute(fs::path(file));
  const std::string rel = fs::relative(data_abs, cert_dir).string();
  return rel.empty() ? data_abs.string() : rel;
}
}  // namespace

Certificate placed_at(Certificate c, const std::string& certificate_path) {
  namespace fs = std::filesystem;
  const fs::path cert_dir = fs::absolute(fs::path(certificate_path)).parent_path();
  for (CertificateRecord& r : c.records) r.data.file = relative_to(r.data.file, cert_dir);
  return c;
}

}  // namespace lpvid
