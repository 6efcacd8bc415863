#include "model/model_file.h"
/// Writing lpvid-model/1 files (the exact number text is json/json_number.h's;
/// the reader is model_file_reader.cc).

#include <stdexcept>

#include "core/file_io.h"
#include "core/input_error.h"
#include "json/json_number.h"
#include "model/state_scheduling.h"

namespace lpvid {
namespace {

using ojson = nlohmann::ordered_json;

// ---------------------------------------------------------------- writing

[[noreturn]] void bad_model(const std::string& what) {
  throw std::invalid_argument("write_model_json: " + what);
}

template <typename T>
ojson matrix_json(const Mat<T>& m) {
  ojson rows = ojson::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    ojson row = ojson::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(number_to_json(m(i, j)));
    rows.push_back(std::move(row));
  }
  return rows;
}

template <typename T>
ojson vector_json(const Vec<T>& v) {
  ojson out = ojson::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(number_to_json(v(i)));
  return out;
}

std::string basis_text(const Monomial& f, const std::vector<std::string>& names, const std::string& where) {
  if (f.powers.size() != names.size())
    bad_model(where + ": basis function has " + std::to_string(f.powers.size()) + " powers, the model has " +
              std::to_string(names.size()) + " scheduling variables");
  for (int p : f.powers)
    if (p < 0 || p > kMaxMonomialPower) bad_model(where + ": basis power " + std::to_string(p) + " out of range");
  return f.text(names);
}

template <typename T>
ojson terms_json(const ParamMatrix<T>& pm, Eigen::Index rows, Eigen::Index cols, const std::vector<std::string>& names,
                 const std::string& where) {
  ojson out = ojson::array();
  for (size_t i = 0; i < pm.terms.size(); ++i) {
    const ParamTerm<T>& t = pm.terms[i];
    const std::string w = where + "[" + std::to_string(i) + "]";
    if (t.value.rows() != rows || t.value.cols() != cols)
      bad_model(w + ": value is " + shape_text(t.value.rows(), t.value.cols()) + ", expected " + shape_text(rows, cols));
    ojson term = ojson::object();
    term["basis"] = basis_text(t.basis, names, w);
    term["value"] = matrix_json(t.value);
    out.push_back(std::move(term));
  }
  return out;
}

template <typename T>
bool is_zero(const Mat<T>& m) {
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      if (m(i, j) != T(0)) return false;
  return true;
}

template <typename T>
ojson fixed_correction_json(const std::vector<Mat<T>>& mats, const std::vector<Monomial>& basis, Eigen::Index rows,
                            Eigen::Index cols, const std::vector<std::string>& names, const std::string& where) {
  if (!mats.empty() && mats.size() != basis.size())
    bad_model(where + ": " + std::to_string(mats.size()) + " matrices for " + std::to_string(basis.size()) +
              " basis functions");
  ojson out = ojson::array();
  for (size_t i = 0; i < mats.size(); ++i) {
    const std::string w = where + "[" + std::to_string(i) + "]";
    if (mats[i].rows() != rows || mats[i].cols() != cols)
      bad_model(w + ": is " + shape_text(mats[i].rows(), mats[i].cols()) + ", expected " + shape_text(rows, cols));
    if (is_zero(mats[i])) continue;
    ojson term = ojson::object();
    term["basis"] = basis_text(basis[i], names, w);
    term["value"] = matrix_json(mats[i]);
    out.push_back(std::move(term));
  }
  return out;
}

ojson model_basis_json(const std::vector<Monomial>& basis, const std::vector<std::string>& names, const std::string& where) {
  ojson out = ojson::array();
  for (size_t i = 0; i < basis.size(); ++i)
    out.push_back(basis_text(basis[i], names, where + ".basis[" + std::to_string(i) + "]"));
  return out;
}

template <typename T>
ojson model_columns_json(const LpvModel<T>& m) {
  if (m.columns.u.size() != static_cast<size_t>(m.nu) || m.columns.y.size() != static_cast<size_t>(m.ny) ||
      m.columns.rho.size() != m.scheduling.size())
    bad_model("columns: need " + std::to_string(m.nu) + " u, " + std::to_string(m.ny) + " y and " +
              std::to_string(m.scheduling.size()) + " rho names");
  try {
    state_functions<T>(m.columns.rho, m.nx);  // state columns parse and name a state (data/column_map.h)
  } catch (const std::invalid_argument& e) {
    bad_model(std::string("columns.rho: ") + e.what());
  }
  ojson columns = ojson::object();
  columns["u"] = m.columns.u;
  columns["y"] = m.columns.y;
  columns["rho"] = m.columns.rho;
  return columns;
}

template <typename T>
ojson model_correction_json(const LpvModel<T>& m) {
  const Correction<T>& c = m.correction;
  ojson corr = ojson::object();
  corr["basis"] = model_basis_json(c.basis, m.scheduling, "correction");
  ojson a = fixed_correction_json(c.A, c.basis, m.nx, m.nx, m.scheduling, "correction.A");
  ojson b = fixed_correction_json(c.B, c.basis, m.nx, m.nu, m.scheduling, "correction.B");
  if (!a.empty()) corr["A"] = std::move(a);
  if (!b.empty()) corr["B"] = std::move(b);
  return corr;
}

template <typename T>
ojson model_uncertainty_json(const LpvModel<T>& m) {
  const Uncertainty<T>& u = m.uncertainty;
  ojson unc = ojson::object();
  unc["structure"] = to_string(u.structure);
  if (u.structure == UncertaintyStructure::kGeneral) {
    if (u.weight != T(1)) bad_model("uncertainty: weight must be 1 with structure general (scale C1, D1 instead)");
    Eigen::Index nz = std::max(u.C1.rows, u.D1.rows);
    for (const auto& t : u.C1.terms) nz = std::max(nz, t.value.rows());
    for (const auto& t : u.D1.terms) nz = std::max(nz, t.value.rows());
    if (nz < 1) bad_model("uncertainty: structure general needs nz >= 1");
    unc["nz"] = nz;
    unc["C1"] = terms_json(u.C1, nz, m.nx, m.scheduling, "uncertainty.C1");
    unc["D1"] = terms_json(u.D1, nz, m.nu, m.scheduling, "uncertainty.D1");
  } else {
    if (!(u.weight > T(0))) bad_model("uncertainty: weight must be positive");
    unc["weight"] = number_to_json(u.weight);
  }
  return unc;
}

/// An offset's values: one vector of length `length` per basis function.
template <typename T>
ojson model_offset_values_json(const std::vector<Vec<T>>& values, Eigen::Index length, const std::string& where) {
  ojson out = ojson::array();
  for (const auto& v : values) {
    if (v.size() != length)
      bad_model(where + ".values: vector of length " + std::to_string(v.size()) + ", expected " + std::to_string(length));
    out.push_back(vector_json(v));
  }
  return out;
}

template <typename T>
ojson model_offset_json(const LpvModel<T>& m) {
  ojson off = ojson::object();
  off["basis"] = model_basis_json(m.offset.basis, m.scheduling, "offset");
  if (!m.offset.values.empty()) {
    if (m.offset.values.size() != m.offset.basis.size()) bad_model("offset: values and basis differ in length");
    off["values"] = model_offset_values_json(m.offset.values, m.ny, "offset");
  }
  return off;
}

template <typename T>
ojson model_state_offset_json(const LpvModel<T>& m) {
  const StateOffset<T>& so = m.state_offset;
  if (so.values.size() != so.basis.size()) bad_model("state_offset: values and basis differ in length");
  ojson off = ojson::object();
  off["basis"] = model_basis_json(so.basis, m.scheduling, "state_offset");
  off["values"] = model_offset_values_json(so.values, m.nx, "state_offset");
  return off;
}

template <typename T>
ojson model_static_map_json(const StaticMap<T>& g, const std::string& where) {
  g.check(where);
  ojson o = ojson::object();
  o["kind"] = to_string(g.kind);
  if (g.kind == StaticKind::kSaturation || g.kind == StaticKind::kDeadZone) {
    o["lower"] = number_to_json(g.lower);
    o["upper"] = number_to_json(g.upper);
  }
  if (g.kind == StaticKind::kPolynomial) {
    ojson c = ojson::array();
    for (const T& x : g.coefficients) c.push_back(number_to_json(x));
    o["coefficients"] = std::move(c);
    if (!g.range.empty()) o["range"] = ojson::array({number_to_json(g.range[0]), number_to_json(g.range[1])});
  }
  if (g.kind == StaticKind::kPiecewiseLinear) {
    ojson x = ojson::array(), v = ojson::array();
    for (const T& t : g.knots) x.push_back(number_to_json(t));
    for (const T& t : g.coefficients) v.push_back(number_to_json(t));
    o["knots"] = std::move(x);
    o["values"] = std::move(v);
  }
  return o;
}

template <typename T>
ojson model_statics_json(const LpvModel<T>& m) {
  if (m.statics.input_delay < 0) bad_model("static.input_delay must be >= 0");
  ojson st = ojson::object();
  if (m.statics.input_delay != 0) st["input_delay"] = m.statics.input_delay;
  if (!m.statics.input.is_identity()) st["input"] = model_static_map_json(m.statics.input, "static.input");
  if (m.statics.has_output()) st["output"] = model_static_map_json(m.statics.output, "static.output");
  return st;
}

template <typename T>
ojson to_json(const LpvModel<T>& m) {
  if (m.nx < 0 || m.nu < 0 || m.ny < 0) bad_model("negative dimension");
  const Eigen::Index nx = m.nx, nu = m.nu, ny = m.ny;
  const auto& names = m.scheduling;
  ojson j = ojson::object();
  j["format"] = kModelFormat;
  j["states"] = m.nx;
  j["inputs"] = m.nu;
  j["outputs"] = m.ny;
  j["scheduling"] = names;
  j["columns"] = model_columns_json(m);
  if (m.signal_info.sample_time > 0.0) j["sample_time"] = m.signal_info.sample_time;
  if (!m.signal_info.units.empty()) {
    ojson units = ojson::object();
    for (const auto& [name, unit] : m.signal_info.units) units[name] = unit;
    j["units"] = std::move(units);
  }
  ojson initial = ojson::object();
  initial["A"] = terms_json(m.A, nx, nx, names, "initial.A");
  initial["B"] = terms_json(m.B, nx, nu, names, "initial.B");
  initial["C"] = terms_json(m.C, ny, nx, names, "initial.C");
  initial["D"] = terms_json(m.D, ny, nu, names, "initial.D");
  j["initial"] = std::move(initial);
  const Correction<T>& c = m.correction;
  if (!c.basis.empty() || !c.A.empty() || !c.B.empty()) j["correction"] = model_correction_json(m);
  j["uncertainty"] = model_uncertainty_json(m);
  if (!m.offset.basis.empty() || !m.offset.values.empty()) j["offset"] = model_offset_json(m);
  if (!m.state_offset.empty()) j["state_offset"] = model_state_offset_json(m);
  if (m.x0.size() != 0 && m.x0.size() != nx)
    bad_model("x0 has length " + std::to_string(m.x0.size()) + ", expected " + std::to_string(nx));
  bool x0_nonzero = false;
  for (Eigen::Index i = 0; i < m.x0.size(); ++i) x0_nonzero = x0_nonzero || m.x0(i) != T(0);
  if (x0_nonzero) j["x0"] = vector_json(m.x0);
  if (!m.statics.empty()) j["static"] = model_statics_json(m);
  return j;
}

template <typename T>
void write_file(const std::string& path, const LpvModel<T>& model) {
  write_text_file(path, write_model_json(model), "model");
}

}  // namespace

nlohmann::ordered_json model_to_json(const LpvModel<Rational>& model) { return to_json(model); }
nlohmann::ordered_json model_to_json(const LpvModel<double>& model) { return to_json(model); }
std::string write_model_json(const LpvModel<Rational>& model) { return pretty_json(to_json(model)); }
std::string write_model_json(const LpvModel<double>& model) { return pretty_json(to_json(model)); }
void write_model_file(const std::string& path, const LpvModel<Rational>& model) { write_file(path, model); }
void write_model_file(const std::string& path, const LpvModel<double>& model) { write_file(path, model); }

}  // namespace lpvid
