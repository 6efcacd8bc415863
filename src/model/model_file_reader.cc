#include "model/model_file.h"
/// Reading lpvid-model/1 files (the writer is model_file_writer.cc).

#include <algorithm>
#include <cmath>
#include <fstream>
#include <gmp.h>
#include <initializer_list>
#include <stdexcept>

#include "core/file_io.h"
#include "core/input_error.h"
#include "core/limits.h"
#include "core/number_text.h"
#include "json/json_number.h"
#include "model/state_scheduling.h"

namespace lpvid {
namespace {

using Kind = JsonNode::Kind;
using ojson = nlohmann::ordered_json;

std::string member_path(const std::string& base, std::string_view key) {
  return base.empty() ? std::string(key) : base + "." + std::string(key);
}
std::string index_path(const std::string& base, size_t i) { return base + "[" + std::to_string(i) + "]"; }

bool is_name_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_name_char(char c) { return is_name_start(c) || (c >= '0' && c <= '9'); }

/// Reads the JSON tree of a model file, naming file, line and JSON path in
/// every error.
class ModelReader {
 public:
  explicit ModelReader(const std::string& file) : file_(file) {}

  [[noreturn]] void fail(const JsonNode& n, const std::string& path, const std::string& reason) const {
    throw_input_error(file_, n.line, path, reason);
  }

  void expect(const JsonNode& n, Kind kind, const std::string& path) const {
    if (n.kind != kind)
      fail(n, path, std::string("expected ") + article_kind(kind) + ", got " + article_kind(n.kind));
  }

  void check_keys(const JsonNode& obj, const std::string& path, std::initializer_list<const char*> allowed,
                  const std::string& hint = "") const {
    for (const auto& [key, value] : obj.members) {
      bool ok = false;
      for (const char* a : allowed) ok = ok || key == a;
      if (ok) continue;
      std::string list;
      for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      fail(value, member_path(path, key),
           "unknown key \"" + key + "\" (allowed here: " + list + ")" + (hint.empty() ? "" : "; " + hint));
    }
  }

  const JsonNode& required(const JsonNode& obj, const std::string& path, const char* key) const {
    const JsonNode* n = obj.find(key);
    if (!n) fail(obj, path, std::string("missing required key \"") + key + "\"");
    return *n;
  }

  std::string string_at(const JsonNode& n, const std::string& path) const {
    expect(n, Kind::kString, path);
    return n.text;
  }

  /// An integer in [lo, hi], written as a JSON number or a numeric string.
  int integer_at(const JsonNode& n, const std::string& path, int lo, int hi) const {
    Rational q = number<Rational>(n, path);
    if (mpz_cmp_ui(mpq_denref(q.mpq()), 1) != 0) fail(n, path, "expected an integer, got " + n.text);
    if (q < Rational(lo) || q > Rational(hi))
      fail(n, path, "expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ", got " + n.text);
    return static_cast<int>(mpz_get_si(mpq_numref(q.mpq())));
  }

  template <typename T>
  T number(const JsonNode& n, const std::string& path) const {
    return number_from_json<T>(n, file_, path);
  }

  std::vector<std::string> string_list(const JsonNode& n, const std::string& path) const {
    expect(n, Kind::kArray, path);
    std::vector<std::string> out;
    for (size_t i = 0; i < n.items.size(); ++i) out.push_back(string_at(n.items[i], index_path(path, i)));
    return out;
  }

  /// A rows × cols matrix written as a list of rows. [] is accepted for any
  /// matrix without entries.
  template <typename T>
  Mat<T> matrix(const JsonNode& n, const std::string& path, Eigen::Index rows, Eigen::Index cols) const {
    expect(n, Kind::kArray, path);
    const auto got_rows = static_cast<Eigen::Index>(n.items.size());
    if (got_rows == 0 && rows * cols == 0) return Mat<T>(rows, cols);
    Eigen::Index got_cols = -1;
    for (size_t i = 0; i < n.items.size(); ++i) {
      const JsonNode& row = n.items[i];
      if (row.kind != Kind::kArray)
        fail(row, index_path(path, i),
             std::string("expected a matrix row (an array of numbers), got ") + article_kind(row.kind));
      const auto c = static_cast<Eigen::Index>(row.items.size());
      if (got_cols >= 0 && c != got_cols)
        fail(row, index_path(path, i),
             "ragged matrix: row " + std::to_string(i) + " has " + std::to_string(c) + " entries, row 0 has " +
                 std::to_string(got_cols));
      got_cols = c;
    }
    if (got_rows != rows || got_cols != cols)
      fail(n, path, "expected " + shape_text(rows, cols) + " matrix, got " + shape_text(got_rows, got_cols));
    Mat<T> m(rows, cols);
    for (Eigen::Index i = 0; i < rows; ++i)
      for (Eigen::Index j = 0; j < cols; ++j)
        m(i, j) = number<T>(n.items[static_cast<size_t>(i)].items[static_cast<size_t>(j)],
                            index_path(index_path(path, static_cast<size_t>(i)), static_cast<size_t>(j)));
    return m;
  }

  template <typename T>
  Vec<T> vector(const JsonNode& n, const std::string& path, Eigen::Index len) const {
    expect(n, Kind::kArray, path);
    if (static_cast<Eigen::Index>(n.items.size()) != len)
      fail(n, path, "expected a vector of " + std::to_string(len) + " numbers, got " +
                        std::to_string(n.items.size()) + " entries");
    Vec<T> v(len);
    for (Eigen::Index i = 0; i < len; ++i)
      v(i) = number<T>(n.items[static_cast<size_t>(i)], index_path(path, static_cast<size_t>(i)));
    return v;
  }

  Monomial monomial(const JsonNode& n, const std::string& path, const std::vector<std::string>& names) const {
    if (n.kind != Kind::kString)
      fail(n, path, std::string("expected a basis function as a string such as \"1\" or \"rho1*rho2\", got ") +
                        article_kind(n.kind));
    try {
      return parse_monomial(n.text, names);
    } catch (const InputError& e) {
      fail(n, path, e.what());
    }
  }

  /// A list of distinct basis functions.
  std::vector<Monomial> basis_list(const JsonNode& n, const std::string& path,
                                   const std::vector<std::string>& names) const {
    expect(n, Kind::kArray, path);
    std::vector<Monomial> out;
    for (size_t i = 0; i < n.items.size(); ++i) {
      Monomial m = monomial(n.items[i], index_path(path, i), names);
      for (size_t j = 0; j < out.size(); ++j)
        if (out[j] == m)
          fail(n.items[i], index_path(path, i),
               "basis function \"" + n.items[i].text + "\" is listed twice (also at index " + std::to_string(j) +
                   ")");
      out.push_back(std::move(m));
    }
    return out;
  }

  /// One term {"basis": text, "value": matrix}.
  template <typename T>
  ParamTerm<T> term(const JsonNode& n, const std::string& path, Eigen::Index rows, Eigen::Index cols,
                    const std::vector<std::string>& names) const {
    expect(n, Kind::kObject, path);
    check_keys(n, path, {"basis", "value"});
    ParamTerm<T> t;
    t.basis = monomial(required(n, path, "basis"), member_path(path, "basis"), names);
    t.value = matrix<T>(required(n, path, "value"), member_path(path, "value"), rows, cols);
    return t;
  }

  /// A list of terms (absent: zero).
  template <typename T>
  ParamMatrix<T> param_matrix(const JsonNode* n, const std::string& path, Eigen::Index rows, Eigen::Index cols,
                              const std::vector<std::string>& names) const {
    ParamMatrix<T> pm(rows, cols);
    if (!n) return pm;
    expect(*n, Kind::kArray, path);
    for (size_t i = 0; i < n->items.size(); ++i)
      pm.terms.push_back(term<T>(n->items[i], index_path(path, i), rows, cols, names));
    return pm;
  }

  /// Fixed correction matrices A_i or B_i: one per basis function, zero
  /// unless a term gives it.
  template <typename T>
  std::vector<Mat<T>> correction_matrices(const JsonNode* n, const std::string& path,
                                          const std::vector<Monomial>& basis, Eigen::Index rows, Eigen::Index cols,
                                          const std::vector<std::string>& names,
                                          const std::string& basis_path) const {
    std::vector<Mat<T>> out;
    std::vector<bool> given(basis.size(), false);
    std::vector<ParamTerm<T>> terms;
    std::vector<size_t> index;
    if (n) {
      expect(*n, Kind::kArray, path);
      for (size_t i = 0; i < n->items.size(); ++i) {
        const std::string p = index_path(path, i);
        ParamTerm<T> t = term<T>(n->items[i], p, rows, cols, names);
        size_t k = 0;
        while (k < basis.size() && !(basis[k] == t.basis)) ++k;
        const JsonNode& b = *n->items[i].find("basis");
        if (k == basis.size())
          fail(b, member_path(p, "basis"), "\"" + b.text + "\" is not in " + basis_path);
        if (given[k]) fail(b, member_path(p, "basis"), "a second term for \"" + b.text + "\"");
        given[k] = true;
        terms.push_back(std::move(t));
        index.push_back(k);
      }
    }
    for (size_t k = 0; k < basis.size(); ++k) out.push_back(Mat<T>::Zero(rows, cols));
    for (size_t i = 0; i < terms.size(); ++i) out[index[i]] = std::move(terms[i].value);
    return out;
  }

  template <typename T>
  LpvModel<T> model(const JsonNode& root, const std::string& path) const {
    LpvModel<T> m = dimensions<T>(root, path);
    read_scheduling(root, path, m);
    read_columns(root, path, m);
    read_signal_info(root, path, m);
    read_initial(root, path, m);
    read_correction(root, path, m);
    read_uncertainty(root, path, m);
    read_offset(root, path, m);
    read_state_offset(root, path, m);
    if (const JsonNode* x = root.find("x0"))
      m.x0 = vector<T>(*x, member_path(path, "x0"), m.nx);
    else
      m.x0 = Vec<T>::Zero(m.nx);
    read_statics(root, path, m);
    return m;
  }

  /// The format tag, the known keys and the dimensions nx, nu, ny.
  template <typename T>
  LpvModel<T> dimensions(const JsonNode& root, const std::string& path) const {
    expect(root, Kind::kObject, path.empty() ? std::string("model") : path);
    const std::string format = string_at(required(root, path, "format"), member_path(path, "format"));
    if (format != kModelFormat)
      fail(*root.find("format"), member_path(path, "format"),
           "expected \"" + std::string(kModelFormat) + "\", got \"" + format + "\"");
    check_keys(root, path,
               {"format", "description", "states", "inputs", "outputs", "scheduling", "columns", "initial",
                "correction", "uncertainty", "offset", "state_offset", "x0", "static", "sample_time", "units"});
    if (const JsonNode* d = root.find("description")) string_at(*d, member_path(path, "description"));

    LpvModel<T> m;
    m.nx = integer_at(required(root, path, "states"), member_path(path, "states"), 0, kMaxModelDimension);
    m.nu = integer_at(required(root, path, "inputs"), member_path(path, "inputs"), 1, kMaxModelDimension);
    m.ny = integer_at(required(root, path, "outputs"), member_path(path, "outputs"), 1, kMaxModelDimension);
    return m;
  }

  /// The scheduling names: distinct identifiers.
  template <typename T>
  void read_scheduling(const JsonNode& root, const std::string& path, LpvModel<T>& m) const {
    if (const JsonNode* s = root.find("scheduling")) {
      const std::string sp = member_path(path, "scheduling");
      m.scheduling = string_list(*s, sp);
      for (size_t i = 0; i < m.scheduling.size(); ++i) {
        const std::string& name = m.scheduling[i];
        bool ok = !name.empty() && is_name_start(name[0]);
        for (char c : name) ok = ok && is_name_char(c);
        if (!ok)
          fail(s->items[i], index_path(sp, i),
               "scheduling name \"" + name +
                   "\" must start with a letter or '_' and contain only letters, digits and '_'");
        for (size_t j = 0; j < i; ++j)
          if (m.scheduling[j] == name) fail(s->items[i], index_path(sp, i), "scheduling name \"" + name + "\" is listed twice");
      }
    }
  }

  /// The data columns of inputs, outputs and scheduling variables; state-scheduling
  /// columns (data/column_map.h) must parse and name a state 1..nx.
  template <typename T>
  void read_columns(const JsonNode& root, const std::string& path, LpvModel<T>& m) const {
    const std::vector<std::string>& names = m.scheduling;
    const std::string cp = member_path(path, "columns");
    const JsonNode& c = required(root, path, "columns");
    expect(c, Kind::kObject, cp);
    check_keys(c, cp, {"u", "y", "rho"});
    auto column_list = [&](const char* key, size_t expected, const char* what) {
      const std::string p = member_path(cp, key);
      const JsonNode& n = required(c, cp, key);
      std::vector<std::string> v = string_list(n, p);
      if (v.size() != expected)
        fail(n, p, "expected " + std::to_string(expected) + " column names (" + what + "), got " +
                       std::to_string(v.size()));
      for (size_t i = 0; i < v.size(); ++i)
        if (v[i].empty()) fail(n.items[i], index_path(p, i), "empty column name");
      return v;
    };
    m.columns.u = column_list("u", static_cast<size_t>(m.nu), "inputs");
    m.columns.y = column_list("y", static_cast<size_t>(m.ny), "outputs");
    if (c.find("rho"))
      m.columns.rho = column_list("rho", names.size(), "scheduling variables");
    else
      m.columns.rho = names;
    // state-scheduling columns (data/column_map.h): the text parses and names a state 1..nx
    for (size_t i = 0; i < m.columns.rho.size(); ++i) {
      const std::string rp = index_path(member_path(cp, "rho"), i);
      const JsonNode* rn = c.find("rho");
      const JsonNode& at = rn && rn->is_array() && i < rn->items.size() ? rn->items[i] : c;
      try {
        state_functions<T>({m.columns.rho[i]}, m.nx);
      } catch (const std::invalid_argument& e) {
        fail(at, rp, e.what());
      }
    }
  }

  /// Sample time and units (data/signal_info.h): descriptive only.
  template <typename T>
  void read_signal_info(const JsonNode& root, const std::string& path, LpvModel<T>& m) const {
    if (const JsonNode* t = root.find("sample_time")) {
      const std::string tp = member_path(path, "sample_time");
      const double ts = nearest_double(number<Rational>(*t, tp));
      if (!(ts > 0.0) || !std::isfinite(ts)) fail(*t, tp, "the sample time must be a positive number of seconds, got " + t->text);
      m.signal_info.sample_time = ts;
    }
    if (const JsonNode* un = root.find("units")) {
      const std::string up = member_path(path, "units");
      expect(*un, Kind::kObject, up);
      std::vector<std::string> known = m.columns.u;
      known.insert(known.end(), m.columns.y.begin(), m.columns.y.end());
      known.insert(known.end(), m.columns.rho.begin(), m.columns.rho.end());
      for (const auto& [name, node] : un->members) {
        const std::string np = member_path(up, name);
        if (std::find(known.begin(), known.end(), name) == known.end())
          fail(node, np, "\"" + name + "\" is not one of the model's columns (columns.u, columns.y, columns.rho)");
        m.signal_info.units.emplace_back(name, string_at(node, np));
      }
    }
  }

  /// The initial model S_I.
  template <typename T>
  void read_initial(const JsonNode& root, const std::string& path, LpvModel<T>& m) const {
    const std::vector<std::string>& names = m.scheduling;
    const Eigen::Index nx = m.nx, nu = m.nu, ny = m.ny;
    const std::string ip = member_path(path, "initial");
    const JsonNode& in = required(root, path, "initial");
    expect(in, Kind::kObject, ip);
    check_keys(in, ip, {"A", "B", "C", "D"});
    m.A = param_matrix<T>(in.find("A"), member_path(ip, "A"), nx, nx, names);
    m.B = param_matrix<T>(in.find("B"), member_path(ip, "B"), nx, nu, names);
    m.C = param_matrix<T>(in.find("C"), member_path(ip, "C"), ny, nx, names);
    m.D = param_matrix<T>(in.find("D"), member_path(ip, "D"), ny, nu, names);
  }

  /// The correction S_C.
  template <typename T>
  void read_correction(const JsonNode& root, const std::string& path, LpvModel<T>& m) const {
    const std::vector<std::string>& names = m.scheduling;
    const Eigen::Index nx = m.nx, nu = m.nu;
    if (const JsonNode* c = root.find("correction")) {
      const std::string cp = member_path(path, "correction");
      expect(*c, Kind::kObject, cp);
      check_keys(*c, cp, {"basis", "A", "B"}, "the C_i, D_i corrections are unknowns, not model data");
      const std::string bp = member_path(cp, "basis");
      m.correction.basis = basis_list(required(*c, cp, "basis"), bp, names);
      m.correction.A = correction_matrices<T>(c->find("A"), member_path(cp, "A"), m.correction.basis, nx, nx, names, bp);
      m.correction.B = correction_matrices<T>(c->find("B"), member_path(cp, "B"), m.correction.basis, nx, nu, names, bp);
    }
  }

  /// The uncertainty's structure and weight (or C1, D1).
  template <typename T>
  void read_uncertainty(const JsonNode& root, const std::string& path, LpvModel<T>& m) const {
    const std::vector<std::string>& names = m.scheduling;
    const Eigen::Index nx = m.nx, nu = m.nu;
    if (const JsonNode* u = root.find("uncertainty")) {
      const std::string up = member_path(path, "uncertainty");
      expect(*u, Kind::kObject, up);
      const std::string sp = member_path(up, "structure");
      std::string s = "multiplicative";
      if (const JsonNode* sn = u->find("structure")) s = string_at(*sn, sp);
      if (s == "multiplicative" || s == "additive") {
        m.uncertainty.structure =
            s == "additive" ? UncertaintyStructure::kAdditive : UncertaintyStructure::kMultiplicative;
        check_keys(*u, up, {"structure", "weight"}, "nz, C1 and D1 are only used with structure \"general\"");
        if (const JsonNode* w = u->find("weight")) {
          m.uncertainty.weight = number<T>(*w, member_path(up, "weight"));
          if (!(m.uncertainty.weight > T(0))) fail(*w, member_path(up, "weight"), "weight must be positive, got " + w->text);
        }
      } else if (s == "general") {
        m.uncertainty.structure = UncertaintyStructure::kGeneral;
        check_keys(*u, up, {"structure", "nz", "C1", "D1"}, "with structure \"general\" scale C1 and D1 instead of giving a weight");
        int nz = 0;
        if (const JsonNode* z = u->find("nz")) {
          nz = integer_at(*z, member_path(up, "nz"), 1, kMaxModelDimension);
        } else {
          // The rows of the first term's value fix nz.
          for (const char* key : {"C1", "D1"}) {
            const JsonNode* list = u->find(key);
            if (nz == 0 && list && list->is_array() && !list->items.empty()) {
              const JsonNode* value = list->items[0].find("value");
              if (value && value->is_array()) nz = static_cast<int>(value->items.size());
            }
          }
          if (nz < 1 || nz > kMaxModelDimension)
            fail(*u, up, "structure \"general\" needs \"nz\" (or a C1/D1 term with at least one row)");
        }
        m.uncertainty.C1 = param_matrix<T>(u->find("C1"), member_path(up, "C1"), nz, nx, names);
        m.uncertainty.D1 = param_matrix<T>(u->find("D1"), member_path(up, "D1"), nz, nu, names);
      } else {
        fail(*u->find("structure"), sp,
             "expected \"multiplicative\", \"additive\" or \"general\", got \"" + s + "\"");
      }
    }
  }

  /// The output offset Φ(ρ).
  template <typename T>
  void read_offset(const JsonNode& root, const std::string& path, LpvModel<T>& m) const {
    const std::vector<std::string>& names = m.scheduling;
    const Eigen::Index ny = m.ny;
    if (const JsonNode* o = root.find("offset")) {
      const std::string op = member_path(path, "offset");
      expect(*o, Kind::kObject, op);
      check_keys(*o, op, {"basis", "values"});
      m.offset.basis = basis_list(required(*o, op, "basis"), member_path(op, "basis"), names);
      if (const JsonNode* v = o->find("values")) {
        const std::string vp = member_path(op, "values");
        expect(*v, Kind::kArray, vp);
        if (v->items.size() != m.offset.basis.size())
          fail(*v, vp, "expected " + std::to_string(m.offset.basis.size()) +
                           " vectors (one per offset basis function), got " + std::to_string(v->items.size()));
        for (size_t i = 0; i < v->items.size(); ++i)
          m.offset.values.push_back(vector<T>(v->items[i], index_path(vp, i), ny));
      }
    }
  }

  /// The state offset E(ρ): values required, one nx-vector per basis function.
  template <typename T>
  void read_state_offset(const JsonNode& root, const std::string& path, LpvModel<T>& m) const {
    const std::vector<std::string>& names = m.scheduling;
    const Eigen::Index nx = m.nx;
    if (const JsonNode* o = root.find("state_offset")) {
      const std::string op = member_path(path, "state_offset");
      expect(*o, Kind::kObject, op);
      check_keys(*o, op, {"basis", "values"});
      m.state_offset.basis = basis_list(required(*o, op, "basis"), member_path(op, "basis"), names);
      const std::string vp = member_path(op, "values");
      const JsonNode& v = required(*o, op, "values");
      expect(v, Kind::kArray, vp);
      if (v.items.size() != m.state_offset.basis.size())
        fail(v, vp, "expected " + std::to_string(m.state_offset.basis.size()) +
                        " vectors (one per state_offset basis function), got " + std::to_string(v.items.size()));
      for (size_t i = 0; i < v.items.size(); ++i)
        m.state_offset.values.push_back(vector<T>(v.items[i], index_path(vp, i), nx));
    }
  }

  /// Static blocks (model/static_blocks.h): input delay, input and output maps.
  template <typename T>
  void read_statics(const JsonNode& root, const std::string& path, LpvModel<T>& m) const {
    if (const JsonNode* st = root.find("static")) {
      const std::string sp = member_path(path, "static");
      expect(*st, Kind::kObject, sp);
      check_keys(*st, sp, {"input_delay", "input", "output"});
      if (const JsonNode* d = st->find("input_delay"))
        m.statics.input_delay = integer_at(*d, member_path(sp, "input_delay"), 0, 100000);
      if (const JsonNode* in = st->find("input")) m.statics.input = static_map<T>(*in, member_path(sp, "input"));
      if (const JsonNode* out = st->find("output")) m.statics.output = static_map<T>(*out, member_path(sp, "output"));
    }
  }

  /// {"kind": ..., "lower"/"upper" | "coefficients"} (model/static_blocks.h).
  template <typename T>
  StaticMap<T> static_map(const JsonNode& n, const std::string& path) const {
    expect(n, Kind::kObject, path);
    StaticMap<T> g;
    const JsonNode& k = required(n, path, "kind");
    const std::string kind = string_at(k, member_path(path, "kind"));
    if (!static_kind_from_string(kind, g.kind))
      fail(k, member_path(path, "kind"),
           "unknown static map \"" + kind + "\" (expected identity, saturation, dead_zone, abs, polynomial or piecewise_linear)");
    switch (g.kind) {
      case StaticKind::kSaturation:
      case StaticKind::kDeadZone:
        check_keys(n, path, {"kind", "lower", "upper"});
        g.lower = number<T>(required(n, path, "lower"), member_path(path, "lower"));
        g.upper = number<T>(required(n, path, "upper"), member_path(path, "upper"));
        if (!(g.lower <= g.upper)) fail(n, path, "lower must not exceed upper");
        break;
      case StaticKind::kPolynomial: {
        check_keys(n, path, {"kind", "coefficients", "range"});
        if (const JsonNode* r = n.find("range")) {
          const std::string rp = member_path(path, "range");
          expect(*r, Kind::kArray, rp);
          if (r->items.size() != 2) fail(*r, rp, "a range is [lo, hi]: two numbers");
          for (size_t i = 0; i < 2; ++i) g.range.push_back(number<T>(r->items[i], index_path(rp, i)));
          if (!(g.range[0] <= g.range[1])) fail(*r, rp, "lo must not exceed hi");
        }
        const JsonNode& c = required(n, path, "coefficients");
        const std::string cp = member_path(path, "coefficients");
        expect(c, Kind::kArray, cp);
        if (c.items.empty()) fail(c, cp, "a polynomial needs at least one coefficient (c0, c1, ...)");
        if (static_cast<long>(c.items.size()) - 1 > input_limits().max_degree)
          fail(c, cp, "degree " + std::to_string(c.items.size() - 1) + " polynomial" +
                          limit_hint(input_limits().max_degree, "--max-degree"));
        for (size_t i = 0; i < c.items.size(); ++i) g.coefficients.push_back(number<T>(c.items[i], index_path(cp, i)));
        break;
      }
      case StaticKind::kPiecewiseLinear: {
        check_keys(n, path, {"kind", "knots", "values"});
        for (const char* key : {"knots", "values"}) {
          const JsonNode& c = required(n, path, key);
          const std::string cp = member_path(path, key);
          expect(c, Kind::kArray, cp);
          std::vector<T>& out = std::string(key) == "knots" ? g.knots : g.coefficients;
          for (size_t i = 0; i < c.items.size(); ++i) out.push_back(number<T>(c.items[i], index_path(cp, i)));
        }
        if (g.knots.size() < 2) fail(n, path, "a piecewise_linear map needs at least two knots");
        if (g.knots.size() != g.coefficients.size())
          fail(n, path, std::to_string(g.knots.size()) + " knots but " + std::to_string(g.coefficients.size()) +
                            " values (one value per knot)");
        for (size_t i = 0; i + 1 < g.knots.size(); ++i)
          if (!(g.knots[i] < g.knots[i + 1]))
            fail(n, member_path(path, "knots"), "knots must be strictly increasing (entry " + std::to_string(i + 1) + ")");
        break;
      }
      case StaticKind::kIdentity:
      case StaticKind::kAbs: check_keys(n, path, {"kind"}); break;
    }
    return g;
  }

 private:
  const std::string& file_;
};

}  // namespace

// ------------------------------------------------------------- models

template <typename T>
LpvModel<T> model_from_json(const JsonNode& node, const std::string& file, const std::string& path) {
  return ModelReader(file).model<T>(node, path);
}

template <typename T>
LpvModel<T> parse_model_json(std::string_view text, const std::string& name) {
  JsonNode root = parse_exact_json(text, name);
  return model_from_json<T>(root, name, "");
}

template <typename T>
LpvModel<T> read_model_file(const std::string& path) {
  return parse_model_json<T>(read_text_file(path), path);
}

template LpvModel<double> read_model_file<double>(const std::string&);
template LpvModel<Rational> read_model_file<Rational>(const std::string&);
template LpvModel<double> parse_model_json<double>(std::string_view, const std::string&);
template LpvModel<Rational> parse_model_json<Rational>(std::string_view, const std::string&);
template LpvModel<double> model_from_json<double>(const JsonNode&, const std::string&, const std::string&);
template LpvModel<Rational> model_from_json<Rational>(const JsonNode&, const std::string&, const std::string&);

}  // namespace lpvid
