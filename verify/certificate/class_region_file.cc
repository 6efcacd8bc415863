#include "verify/certificate/class_region_file.h"

#include <algorithm>

#include "core/input_error.h"
#include "json/json_members.h"
#include "json/json_number.h"
#include "verify/certificate/dual_point_file.h"

namespace lpvid {
namespace {

bool bool_member(const JsonNode& obj, const char* key, const std::string& file, const std::string& where) {
  const JsonNode& n = member(obj, key, file, where);
  if (n.kind != JsonNode::Kind::kBool) throw_input_error(file, n.line, where + "." + key, "expected true or false");
  return n.boolean;
}

Vec<Rational> vector_member(const JsonNode& obj, const char* key, const std::string& file, long size) {
  const JsonNode& n = member(obj, key, file, "class");
  const std::string where = std::string("class.") + key;
  if (!n.is_array() || static_cast<long>(n.items.size()) != size)
    throw_input_error(file, n.line, where, "expected " + std::to_string(size) + " numbers (one per parameter)");
  Vec<Rational> v(size);
  for (long i = 0; i < size; ++i)
    v(i) = number_from_json<Rational>(n.items[static_cast<size_t>(i)], file, where + "[" + std::to_string(i) + "]");
  return v;
}

void parse_names_and_free(const JsonNode& node, const std::string& file, ClassRegion& r) {
  const JsonNode& names = member(node, "parameters", file, "class");
  if (!names.is_array()) throw_input_error(file, names.line, "class.parameters", "expected a list of names");
  for (const JsonNode& n : names.items) {
    if (!n.is_string()) throw_input_error(file, n.line, "class.parameters", "expected strings");
    r.parameters.push_back(n.text);
  }
  const long P = static_cast<long>(r.parameters.size());
  const JsonNode& free = member(node, "free", file, "class");
  if (!free.is_array()) throw_input_error(file, free.line, "class.free", "expected a list of parameter indices");
  for (const JsonNode& n : free.items) {
    const long i = integer_member(n, file, "class.free");
    if (i >= P) throw_input_error(file, n.line, "class.free", "index " + std::to_string(i) + " is not a parameter");
    if (std::find(r.free.begin(), r.free.end(), i) != r.free.end())
      throw_input_error(file, n.line, "class.free", "index " + std::to_string(i) + " is listed twice");
    r.free.push_back(i);
  }
}

/// The preorder tree: reads node `at` and its subtrees; returns the next index.
size_t parse_tree(const JsonNode& nodes, size_t at, long depth, const std::string& file, Eigen::Index ny, Eigen::Index nz,
                  CertificateForm form, ClassRegion& r) {
  if (at >= nodes.items.size()) throw_input_error(file, nodes.line, "class.nodes", "the tree is incomplete (a split lacks a subtree)");
  if (depth > kMaxClassDepth) throw_input_error(file, nodes.line, "class.nodes", "splits nested deeper than " + std::to_string(kMaxClassDepth));
  const JsonNode& n = nodes.items[at];
  const std::string where = "class.nodes[" + std::to_string(at) + "]";
  if (!n.is_object() || n.members.size() != 1) throw_input_error(file, n.line, where, "expected {\"split\": i} or {\"leaf\": {...}}");
  ClassNode node;
  if (const JsonNode* s = n.find("split")) {
    node.split = integer_member(*s, file, where + ".split");
    if (node.split >= static_cast<long>(r.parameters.size()))
      throw_input_error(file, s->line, where + ".split", "not a parameter index");
    r.nodes.push_back(node);
    const size_t next = parse_tree(nodes, at + 1, depth + 1, file, ny, nz, form, r);
    return parse_tree(nodes, next, depth + 1, file, ny, nz, form, r);
  }
  const JsonNode& leaf = member(n, "leaf", file, where);
  node.dual = parse_dual_point_object(leaf, file, where + ".leaf", ny, nz, form, {"epsilon", "expansion"});
  node.epsilon = number_from_json<Rational>(member(leaf, "epsilon", file, where + ".leaf"), file, where + ".leaf.epsilon");
  if (!(node.epsilon > 0)) throw_input_error(file, leaf.line, where + ".leaf.epsilon", "must be > 0");
  if (const JsonNode* e = leaf.find("expansion")) {
    const long P = static_cast<long>(r.parameters.size());
    if (!e->is_array() || static_cast<long>(e->items.size()) != P)
      throw_input_error(file, e->line, where + ".leaf.expansion", "expected " + std::to_string(P) + " numbers (one per parameter)");
    node.expansion.resize(P);
    for (long i = 0; i < P; ++i)
      node.expansion(i) = number_from_json<Rational>(e->items[static_cast<size_t>(i)], file, where + ".leaf.expansion");
  }
  r.nodes.push_back(std::move(node));
  return at + 1;
}

}  // namespace

ClassRegion parse_class_region(const JsonNode& node, const std::string& file, Eigen::Index ny, Eigen::Index nz,
                               CertificateForm form) {
  if (!node.is_object()) throw_input_error(file, node.line, "class", "expected an object");
  for (const auto& [key, value] : node.members)
    if (key != "unknowns" && key != "parameters" && key != "free" && key != "center" && key != "radius" &&
        key != "horizon" && key != "nodes")
      throw_input_error(file, value.line, "class." + key, "unknown key");
  ClassRegion r;
  const JsonNode& u = member(node, "unknowns", file, "class");
  r.unknowns.correction = bool_member(u, "correction", file, "class.unknowns");
  r.unknowns.offset = bool_member(u, "offset", file, "class.unknowns");
  r.unknowns.x0 = bool_member(u, "x0", file, "class.unknowns");
  parse_names_and_free(node, file, r);
  const long P = static_cast<long>(r.parameters.size());
  r.center = vector_member(node, "center", file, P);
  r.radius = vector_member(node, "radius", file, P);
  for (long i = 0; i < P; ++i)
    if (r.radius(i) < 0) throw_input_error(file, member(node, "radius", file, "class").line, "class.radius", "must be >= 0");
  const JsonNode& h = member(node, "horizon", file, "class");
  r.horizon = integer_member(h, file, "class.horizon");
  if (r.horizon < 1) throw_input_error(file, h.line, "class.horizon", "must be at least 1");
  const JsonNode& nodes = member(node, "nodes", file, "class");
  if (!nodes.is_array() || nodes.items.empty() || static_cast<long>(nodes.items.size()) > kMaxClassNodes)
    throw_input_error(file, nodes.line, "class.nodes", "expected 1 to " + std::to_string(kMaxClassNodes) + " nodes");
  if (parse_tree(nodes, 0, 0, file, ny, nz, form, r) != nodes.items.size())
    throw_input_error(file, nodes.line, "class.nodes", "nodes after the end of the tree");
  return r;
}

nlohmann::ordered_json class_region_json(const ClassRegion& r, CertificateForm form) {
  nlohmann::ordered_json j;
  j["unknowns"] = {{"correction", r.unknowns.correction}, {"offset", r.unknowns.offset}, {"x0", r.unknowns.x0}};
  j["parameters"] = r.parameters;
  j["free"] = r.free;
  nlohmann::ordered_json center = nlohmann::ordered_json::array(), radius = nlohmann::ordered_json::array();
  for (Eigen::Index i = 0; i < r.center.size(); ++i) center.push_back(rational_to_json(r.center(i)));
  for (Eigen::Index i = 0; i < r.radius.size(); ++i) radius.push_back(rational_to_json(r.radius(i)));
  j["center"] = center;
  j["radius"] = radius;
  j["horizon"] = r.horizon;
  nlohmann::ordered_json nodes = nlohmann::ordered_json::array();
  for (const ClassNode& n : r.nodes) {
    if (n.split >= 0) {
      nodes.push_back({{"split", n.split}});
      continue;
    }
    nlohmann::ordered_json leaf = dual_point_json(n.dual, form);
    leaf["epsilon"] = rational_to_json(n.epsilon);
    if (n.expansion.size() > 0) {
      nlohmann::ordered_json e = nlohmann::ordered_json::array();
      for (Eigen::Index i = 0; i < n.expansion.size(); ++i) e.push_back(rational_to_json(n.expansion(i)));
      leaf["expansion"] = e;
    }
    nodes.push_back({{"leaf", leaf}});
  }
  j["nodes"] = nodes;
  return j;
}

}  // namespace lpvid
