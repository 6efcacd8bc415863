#include "fit/model_parameters.h"

#include <algorithm>
#include <stdexcept>

#include "core/number_text.h"
#include "model/simulate.h"
#include "model/state_scheduling.h"

namespace lpvid {

namespace {

using Where = ParameterSlot::Where;

double& at_checked(Mat<double>& m, int r, int c) {
  if (r < 0 || c < 0 || r >= m.rows() || c >= m.cols()) throw std::out_of_range("parameter slot outside its matrix");
  return m(r, c);
}

template <typename V>
V& index_checked(std::vector<V>& v, int i) {
  if (i < 0 || static_cast<size_t>(i) >= v.size()) throw std::out_of_range("parameter slot outside its list");
  return v[static_cast<size_t>(i)];
}

std::string entry(const std::string& what, const std::string& basis, int r, int c) {
  return what + "[" + basis + "](" + std::to_string(r + 1) + "," + std::to_string(c + 1) + ")";
}

void term_slots(const ParamMatrix<double>& pm, Where where, const char* name, const std::vector<std::string>& rho,
                std::vector<ParameterSlot>& out) {
  for (size_t t = 0; t < pm.terms.size(); ++t)
    for (int r = 0; r < pm.terms[t].value.rows(); ++r)
      for (int c = 0; c < pm.terms[t].value.cols(); ++c)
        out.push_back({where, static_cast<int>(t), r, c, entry(name, pm.terms[t].basis.text(rho), r, c)});
}

/// Adds f·0 to pm unless a term with basis f exists.
void ensure_term(ParamMatrix<double>& pm, const Monomial& f) {
  for (const auto& t : pm.terms)
    if (t.basis == f) return;
  pm.add(f, Mat<double>::Zero(pm.rows, pm.cols));
}

void map_slots(const StaticMap<double>& g, Where lower, Where upper, Where coef, const std::string& prefix,
               std::vector<ParameterSlot>& out) {
  switch (g.kind) {
    case StaticKind::kSaturation:
    case StaticKind::kDeadZone:
      out.push_back({lower, 0, 0, 0, prefix + ".lower"});
      out.push_back({upper, 0, 0, 0, prefix + ".upper"});
      break;
    case StaticKind::kPolynomial:
      for (size_t i = 0; i < g.coefficients.size(); ++i)
        if (i != 1) out.push_back({coef, static_cast<int>(i), 0, 0, prefix + ".c" + std::to_string(i)});
      break;
    case StaticKind::kPiecewiseLinear:  // every value (the knots stay where the start put them)
      for (size_t i = 0; i < g.coefficients.size(); ++i)
        out.push_back({coef, static_cast<int>(i), 0, 0, prefix + ".g" + std::to_string(i)});
      break;
    case StaticKind::kIdentity:
    case StaticKind::kAbs: break;
  }
}

}  // namespace

double& slot_value(LpvModel<double>& m, const ParameterSlot& s) {
  switch (s.where) {
    case Where::kA: return at_checked(index_checked(m.A.terms, s.term).value, s.row, s.col);
    case Where::kC: return at_checked(index_checked(m.C.terms, s.term).value, s.row, s.col);
    case Where::kD: return at_checked(index_checked(m.D.terms, s.term).value, s.row, s.col);
    case Where::kB: return at_checked(index_checked(m.B.terms, s.term).value, s.row, s.col);
    case Where::kOffset: {
      Vec<double>& v = index_checked(m.offset.values, s.term);
      if (s.row < 0 || s.row >= v.size()) throw std::out_of_range("offset slot outside its vector");
      return v(s.row);
    }
    case Where::kX0: {  // term 0: x0 (record 1); term k >= 1: record k+1's (later_x0)
      Vec<double>& v = s.term == 0 ? m.x0 : index_checked(m.later_x0, s.term - 1);
      if (s.row < 0 || s.row >= v.size()) throw std::out_of_range("x0 slot outside x0");
      return v(s.row);
    }
    case Where::kInputLower: return m.statics.input.lower;
    case Where::kInputUpper: return m.statics.input.upper;
    case Where::kInputCoef: return index_checked(m.statics.input.coefficients, s.term);
    case Where::kOutputLower: return m.statics.output.lower;
    case Where::kOutputUpper: return m.statics.output.upper;
    case Where::kOutputCoef: return index_checked(m.statics.output.coefficients, s.term);
    case Where::kStateOffset: {
      Vec<double>& v = index_checked(m.state_offset.values, s.term);
      if (s.row < 0 || s.row >= v.size()) throw std::out_of_range("state_offset slot outside its vector");
      return v(s.row);
    }
    case Where::kStateShift:
      throw std::invalid_argument("slot " + s.name + ": a state-function shift is column text, use slot_values/with_slot_values");
  }
  throw std::out_of_range("unknown parameter slot");
}

namespace {

/// The parsed state column of a kStateShift slot (checked).
StateColumn shift_column(const LpvModel<double>& m, const ParameterSlot& s) {
  if (s.term < 0 || static_cast<size_t>(s.term) >= m.columns.rho.size())
    throw std::out_of_range("state shift slot outside the scheduling columns");
  const StateColumn c = parse_state_column(m.columns.rho[static_cast<size_t>(s.term)]);
  if (c.state < 0 || c.function == StateFunction::kState)
    throw std::out_of_range("state shift slot on column '" + m.columns.rho[static_cast<size_t>(s.term)] +
                            "', which has no shift");
  return c;
}

double get_slot(LpvModel<double>& m, const ParameterSlot& s) {
  if (s.where == Where::kStateShift) return double_from_text(shift_column(m, s).shift);
  return slot_value(m, s);
}

void set_slot(LpvModel<double>& m, const ParameterSlot& s, double v) {
  if (s.where == Where::kStateShift) {
    const StateColumn c = shift_column(m, s);
    m.columns.rho[static_cast<size_t>(s.term)] = state_column_text(c.function, c.state, v);
    return;
  }
  slot_value(m, s) = v;
}

}  // namespace

Vec<double> slot_values(const LpvModel<double>& m, const std::vector<ParameterSlot>& slots) {
  LpvModel<double> copy = m;
  Vec<double> p(static_cast<Eigen::Index>(slots.size()));
  for (size_t i = 0; i < slots.size(); ++i) p(static_cast<Eigen::Index>(i)) = get_slot(copy, slots[i]);
  return p;
}

LpvModel<double> with_slot_values(const LpvModel<double>& m, const std::vector<ParameterSlot>& slots,
                                  const Vec<double>& p) {
  if (p.size() != static_cast<Eigen::Index>(slots.size()))
    throw std::invalid_argument("with_slot_values: " + std::to_string(p.size()) + " values for " +
                                std::to_string(slots.size()) + " slots");
  LpvModel<double> out = m;
  for (size_t i = 0; i < slots.size(); ++i) set_slot(out, slots[i], p(static_cast<Eigen::Index>(i)));
  // keep saturation/dead-zone limits ordered whatever the fit did
  for (StaticMap<double>* g : {&out.statics.input, &out.statics.output})
    if (g->lower > g->upper) std::swap(g->lower, g->upper);
  return out;
}

std::vector<ParameterSlot> output_map_slots(const LpvModel<double>& m) {
  std::vector<ParameterSlot> out;
  term_slots(m.C, Where::kC, "C", m.scheduling, out);
  term_slots(m.D, Where::kD, "D", m.scheduling, out);
  return out;
}

std::vector<ParameterSlot> input_term_slots(const LpvModel<double>& m, const Monomial& f) {
  std::vector<ParameterSlot> out;
  for (size_t t = 0; t < m.B.terms.size(); ++t)
    if (m.B.terms[t].basis == f)
      for (int r = 0; r < m.B.terms[t].value.rows(); ++r)
        for (int c = 0; c < m.B.terms[t].value.cols(); ++c)
          out.push_back({Where::kB, static_cast<int>(t), r, c, entry("B", f.text(m.scheduling), r, c)});
  return out;
}

bool observer_shaped(const Mat<double>& a, Eigen::Index min_order) {
  if (a.rows() != a.cols() || a.rows() < min_order) return false;
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 1; j < a.cols(); ++j)
      if (a(i, j) != (j == i + 1 ? 1.0 : 0.0)) return false;
  return true;
}

std::vector<ParameterSlot> dynamics_slots(const LpvModel<double>& m) {
  std::vector<ParameterSlot> out;
  // observer form: every A term (also f(ρ)·A_f) moves only in column 1
  bool observer = false;
  for (const auto& t : m.A.terms)
    if (t.basis.is_constant()) observer = observer_shaped(t.value);
  for (size_t t = 0; t < m.A.terms.size(); ++t) {
    const Mat<double>& a = m.A.terms[t].value;
    const std::string f = m.A.terms[t].basis.text(m.scheduling);
    const Eigen::Index cols = observer ? 1 : a.cols();
    for (Eigen::Index c = 0; c < cols; ++c)
      for (Eigen::Index r = 0; r < a.rows(); ++r)
        out.push_back({Where::kA, static_cast<int>(t), static_cast<int>(r), static_cast<int>(c),
                       entry("A", f, static_cast<int>(r), static_cast<int>(c))});
  }
  term_slots(m.B, Where::kB, "B", m.scheduling, out);
  const std::vector<ParameterSlot> e = state_offset_slots(m);
  out.insert(out.end(), e.begin(), e.end());
  return out;
}

std::vector<ParameterSlot> state_offset_slots(const LpvModel<double>& m) {
  std::vector<ParameterSlot> out;
  for (size_t j = 0; j < m.state_offset.values.size(); ++j)
    for (int r = 0; r < m.state_offset.values[j].size(); ++r)
      out.push_back({Where::kStateOffset, static_cast<int>(j), r, 0,
                     "E[" + m.state_offset.basis[j].text(m.scheduling) + "](" + std::to_string(r + 1) + ")"});
  return out;
}

ParameterSlot state_shift_slot(const LpvModel<double>& m, int j) {
  if (j < 0 || static_cast<size_t>(j) >= m.columns.rho.size())
    throw std::invalid_argument("state_shift_slot: no scheduling column " + std::to_string(j + 1));
  const StateColumn c = parse_state_column(m.columns.rho[static_cast<size_t>(j)]);
  if (c.state < 0 || c.function == StateFunction::kState)
    throw std::invalid_argument("state_shift_slot: column '" + m.columns.rho[static_cast<size_t>(j)] +
                                "' is not a state function with a shift");
  return {Where::kStateShift, j, 0, 0, "shift[" + m.scheduling[static_cast<size_t>(j)] + "]"};
}

double constant_a_radius(const LpvModel<double>& m) {
  for (const auto& t : m.A.terms)
    if (t.basis.degree() == 0 && t.value.rows() > 0)
      return t.value.eigenvalues().cwiseAbs().maxCoeff();
  return 0;
}

std::vector<ParameterSlot> offset_slots(const LpvModel<double>& m) {
  std::vector<ParameterSlot> out;
  for (size_t j = 0; j < m.offset.values.size(); ++j)
    for (int r = 0; r < m.offset.values[j].size(); ++r)
      out.push_back({Where::kOffset, static_cast<int>(j), r, 0,
                     "phi[" + m.offset.basis[j].text(m.scheduling) + "](" + std::to_string(r + 1) + ")"});
  return out;
}

std::vector<ParameterSlot> record_x0_slots(const LpvModel<double>& m, int record) {
  std::vector<ParameterSlot> out;
  const Vec<double>& v = record == 0 ? m.x0 : m.later_x0.at(static_cast<size_t>(record - 1));
  const std::string prefix = record == 0 ? "x0(" : "x0[record " + std::to_string(record + 1) + "](";
  for (int i = 0; i < v.size(); ++i) out.push_back({Where::kX0, record, i, 0, prefix + std::to_string(i + 1) + ")"});
  return out;
}

std::vector<ParameterSlot> x0_slots(const LpvModel<double>& m) {
  std::vector<ParameterSlot> out = record_x0_slots(m, 0);
  for (size_t k = 0; k < m.later_x0.size(); ++k) {
    const std::vector<ParameterSlot> more = record_x0_slots(m, static_cast<int>(k + 1));
    out.insert(out.end(), more.begin(), more.end());
  }
  return out;
}

std::vector<ParameterSlot> static_map_slots(const LpvModel<double>& m) {
  std::vector<ParameterSlot> out;
  map_slots(m.statics.input, Where::kInputLower, Where::kInputUpper, Where::kInputCoef, "input", out);
  map_slots(m.statics.output, Where::kOutputLower, Where::kOutputUpper, Where::kOutputCoef, "output", out);
  return out;
}

LpvModel<double> explicit_model(const LpvModel<double>& m) {
  const SystemMatrices<double> s = system_matrices(m);  // validates, sizes C and D
  LpvModel<double> out = m;
  out.C = s.C;
  out.D = s.D;
  for (const Monomial& f : m.correction.basis) {
    ensure_term(out.C, f);
    ensure_term(out.D, f);
  }
  // keep the basis for its fixed A_i, B_i; its C_i, D_i are now explicit terms
  bool fixed_state_terms = false;
  for (const auto& a : m.correction.A) fixed_state_terms = fixed_state_terms || !a.isZero();
  for (const auto& b : m.correction.B) fixed_state_terms = fixed_state_terms || !b.isZero();
  if (!fixed_state_terms) out.correction = Correction<double>{};
  if (out.offset.values.empty())
    for (size_t j = 0; j < out.offset.basis.size(); ++j) out.offset.values.push_back(Vec<double>::Zero(m.ny));
  if (out.x0.size() != m.nx) out.x0 = Vec<double>::Zero(m.nx);
  return out;
}

std::vector<ParameterSlot> refit_slots(const LpvModel<double>& m) {
  std::vector<ParameterSlot> s = output_map_slots(m);
  for (auto v : {offset_slots(m), x0_slots(m), static_map_slots(m)}) s.insert(s.end(), v.begin(), v.end());
  return s;
}

std::vector<ParameterSlot> with_dynamics_slots(std::vector<ParameterSlot> slots, const LpvModel<double>& m) {
  for (const ParameterSlot& d : dynamics_slots(m)) {
    const bool known = std::any_of(slots.begin(), slots.end(), [&](const ParameterSlot& s) {
      return s.where == d.where && s.term == d.term && s.row == d.row && s.col == d.col;
    });
    if (!known) slots.push_back(d);
  }
  return slots;
}

}  // namespace lpvid
