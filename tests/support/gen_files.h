#pragma once
/// Generators for input files (docs/design.md §4, §11): random well-formed model files
/// (with every number written as a JSON number, a decimal string or a `p/q`
/// string), random CSV tables written with the optional quoting, CRLF and
/// trailing commas the reader accepts, and random corruptions of valid text.
/// Everything is built by construction (no rejection sampling); sizes are
/// small (1..3 states/inputs/outputs, 0..3 scheduling variables) so that
/// shrinking finds tiny counterexamples.

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/number_text.h"
#include "core/scalar.h"
#include "data/experiment.h"
#include "model/lpv_model.h"
#include "model/model_file.h"
#include "model/monomial.h"

namespace lpvid::gen::files {

// ------------------------------------------------------------ numbers

/// An exact rational of a kind found in model files: small fractions, exact
/// decimals (p/10^k, p/2^k), and now and then an integer beyond 64 bits.
inline rc::Gen<Rational> file_rational() {
  return rc::gen::exec([] {
    const int kind = *rc::gen::inRange(0, 5);
    const long p = *rc::gen::inRange<long>(-1000000, 1000001);
    switch (kind) {
      case 0: return Rational(p);
      case 1: return Rational(p) / Rational(*rc::gen::inRange<long>(1, 1000));
      case 2: {
        Rational den(1);
        for (int k = *rc::gen::inRange(0, 12); k > 0; --k) den *= 10;
        return Rational(p) / den;
      }
      case 3: {
        Rational den(1);
        for (int k = *rc::gen::inRange(0, 30); k > 0; --k) den *= 2;
        return Rational(p) / den;
      }
      default: {
        Rational big(p);
        for (int k = *rc::gen::inRange(0, 30); k > 0; --k) big *= 10;
        return big;
      }
    }
  });
}

/// A random finite double (any exponent, both signs, zero).
inline rc::Gen<double> file_double() {
  return rc::gen::map(rc::gen::arbitrary<double>(), [](double x) { return std::isfinite(x) ? x : 0.0; });
}

/// The JSON text of q in a random one of the forms the reader accepts:
/// a JSON number token (integer, decimal, or mantissa+exponent) when q has a
/// terminating decimal, or a string holding a decimal or `p/q` (p/q possibly
/// not reduced, with spaces, or with the sign on the denominator).
inline std::string random_number_text(const Rational& q) {
  const std::string exact = exact_decimal_or_fraction(q);
  const bool decimal = exact.find('/') == std::string::npos;
  const int form = *rc::gen::inRange(0, 5);
  if (decimal && form == 0) return exact;  // JSON number token, e.g. -0.25 or 12
  if (decimal && form == 1) {
    // Mantissa and exponent: digits without the point, "e-<decimals>".
    std::string s = exact;
    const size_t dot = s.find('.');
    if (dot == std::string::npos) return s + "e0";
    const size_t decimals = s.size() - dot - 1;
    s.erase(dot, 1);
    // A JSON number must not have leading zeros: strip them (keep one digit).
    size_t start = s[0] == '-' ? 1 : 0;
    while (s.size() > start + 1 && s[start] == '0') s.erase(start, 1);
    return s + "e-" + std::to_string(decimals);
  }
  if (decimal && form == 2) return "\"" + exact + "\"";
  const Rational num(q.numerator()), den(q.denominator());
  const int m = *rc::gen::inRange(1, 4);
  const Rational n2 = num * Rational(m), d2 = den * Rational(m);
  if (form == 3 && num != Rational(0))  // sign on the denominator
    return "\"" + rational_to_text(-n2) + "/" + rational_to_text(-d2) + "\"";
  const std::string sp = *rc::gen::element<std::string>("", " ", "  ");
  return "\"" + sp + rational_to_text(n2) + sp + "/" + sp + rational_to_text(d2) + sp + "\"";
}

// ------------------------------------------------------------ models

/// A random model that a model file can hold, in the canonical form the
/// reader produces: distinct correction/offset basis functions, correction A,
/// B given for every basis function (possibly zero), x0 of length nx,
/// positive weight (1 with the general structure), C1/D1 only for general.
template <typename T>
rc::Gen<LpvModel<T>> file_model(rc::Gen<T> entry) {
  return rc::gen::exec([entry] {
    LpvModel<T> m;
    m.nx = *rc::gen::inRange(1, 4);
    m.nu = *rc::gen::inRange(1, 4);
    m.ny = *rc::gen::inRange(1, 4);
    const int n_rho = *rc::gen::inRange(0, 4);
    const std::vector<std::string> stems = {"rho", "p", "theta_", "_s", "Speed"};
    for (int k = 0; k < n_rho; ++k)
      m.scheduling.push_back(*rc::gen::elementOf(stems) + std::to_string(k + 1));
    // Column names: any non-empty text (escaping is part of the test).
    auto column = [](const std::string& stem, int k) {
      const std::string extra = *rc::gen::element<std::string>("", " est", "\"q\"", "\\", "é", ",x", "\t");
      return stem + extra + std::to_string(k + 1);
    };
    for (int k = 0; k < m.nu; ++k) m.columns.u.push_back(column("u", k));
    for (int k = 0; k < m.ny; ++k) m.columns.y.push_back(column("y", k));
    for (int k = 0; k < n_rho; ++k) m.columns.rho.push_back(column("r", k));

    auto mono = [n_rho] {
      Monomial f{std::vector<int>(static_cast<size_t>(n_rho), 0)};
      for (int& p : f.powers) p = *rc::gen::inRange(0, 4);
      return f;
    };
    auto matrix = [&entry](Eigen::Index r, Eigen::Index c) {
      Mat<T> v(r, c);
      for (Eigen::Index i = 0; i < r; ++i)
        for (Eigen::Index j = 0; j < c; ++j) v(i, j) = *entry;
      return v;
    };
    auto param = [&](Eigen::Index r, Eigen::Index c) {
      ParamMatrix<T> pm(r, c);
      for (int t = *rc::gen::inRange(0, 3); t > 0; --t) pm.add(mono(), matrix(r, c));
      return pm;
    };
    /// Up to `max` distinct monomials, by construction: distinct powers of
    /// the first variable (or only the constant when there is none).
    auto distinct_basis = [&](int max) {
      std::vector<Monomial> out;
      const int count = n_rho == 0 ? *rc::gen::inRange(0, 2) : *rc::gen::inRange(0, max + 1);
      for (int i = 0; i < count; ++i) {
        Monomial f = mono();
        if (n_rho > 0) f.powers[0] = i;
        out.push_back(f);
      }
      return out;
    };
    m.A = param(m.nx, m.nx);
    m.B = param(m.nx, m.nu);
    m.C = param(m.ny, m.nx);
    m.D = param(m.ny, m.nu);

    m.correction.basis = distinct_basis(4);
    for (size_t i = 0; i < m.correction.basis.size(); ++i) {
      const bool zero = *rc::gen::arbitrary<bool>();
      m.correction.A.push_back(zero ? Mat<T>(Mat<T>::Zero(m.nx, m.nx)) : matrix(m.nx, m.nx));
      m.correction.B.push_back(zero ? Mat<T>(Mat<T>::Zero(m.nx, m.nu)) : matrix(m.nx, m.nu));
    }

    const int structure = *rc::gen::inRange(0, 3);
    if (structure == 2) {
      m.uncertainty.structure = UncertaintyStructure::kGeneral;
      const int nz = *rc::gen::inRange(1, 4);
      m.uncertainty.C1 = param(nz, m.nx);
      m.uncertainty.D1 = param(nz, m.nu);
    } else {
      m.uncertainty.structure = structure == 0 ? UncertaintyStructure::kMultiplicative : UncertaintyStructure::kAdditive;
      T w = *entry;
      if (w < T(0)) w = -w;
      if (w == T(0)) w = T(1);
      m.uncertainty.weight = w;
    }

    m.offset.basis = distinct_basis(3);
    if (!m.offset.basis.empty() && *rc::gen::arbitrary<bool>())
      for (size_t j = 0; j < m.offset.basis.size(); ++j) m.offset.values.push_back(matrix(m.ny, 1));

    m.x0 = *rc::gen::arbitrary<bool>() ? Vec<T>(matrix(m.nx, 1)) : Vec<T>(Vec<T>::Zero(m.nx));
    return m;
  });
}

template <typename T>
bool same_matrix(const Mat<T>& a, const Mat<T>& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() && (a.size() == 0 || a == b);
}

template <typename T>
bool same_param(const ParamMatrix<T>& a, const ParamMatrix<T>& b) {
  if (a.rows != b.rows || a.cols != b.cols || a.terms.size() != b.terms.size()) return false;
  for (size_t i = 0; i < a.terms.size(); ++i)
    if (!(a.terms[i].basis == b.terms[i].basis) || !same_matrix(a.terms[i].value, b.terms[i].value)) return false;
  return true;
}

template <typename T, typename M>
bool same_list(const std::vector<M>& a, const std::vector<M>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (!same_matrix<T>(a[i], b[i])) return false;
  return true;
}

/// Every field equal (exactly, for doubles too).
template <typename T>
bool same_model(const LpvModel<T>& a, const LpvModel<T>& b) {
  return a.nx == b.nx && a.nu == b.nu && a.ny == b.ny && a.scheduling == b.scheduling &&
         a.columns.u == b.columns.u && a.columns.y == b.columns.y && a.columns.rho == b.columns.rho &&
         same_param(a.A, b.A) && same_param(a.B, b.B) && same_param(a.C, b.C) && same_param(a.D, b.D) &&
         a.correction.basis == b.correction.basis && same_list<T>(a.correction.A, b.correction.A) &&
         same_list<T>(a.correction.B, b.correction.B) && a.uncertainty.structure == b.uncertainty.structure &&
         a.uncertainty.weight == b.uncertainty.weight && same_param(a.uncertainty.C1, b.uncertainty.C1) &&
         same_param(a.uncertainty.D1, b.uncertainty.D1) && a.offset.basis == b.offset.basis &&
         same_list<T>(a.offset.values, b.offset.values) && same_matrix<T>(a.x0, b.x0);
}

/// A model and a model-file text for it written by hand (not by
/// write_model_json): numbers in random forms, members in random order,
/// optional keys left out when they hold their default.
struct ModelText {
  LpvModel<Rational> model;
  std::string text;
};

/// Fisher–Yates shuffle driven by rapidcheck (replayable).
template <typename X>
void shuffle(std::vector<X>& v) {
  for (size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[*rc::gen::inRange<size_t>(0, i)]);
}

inline std::string json_string(const std::string& s) { return nlohmann::json(s).dump(); }

inline std::string json_names(const std::vector<std::string>& names) {
  std::string out = "[";
  for (size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + json_string(names[i]);
  return out + "]";
}

inline std::string json_matrix_forms(const Mat<Rational>& m) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    out += i ? ", [" : "[";
    for (Eigen::Index j = 0; j < m.cols(); ++j) out += (j ? ", " : "") + random_number_text(m(i, j));
    out += "]";
  }
  return out + "]";
}

inline std::string json_vector_forms(const Vec<Rational>& v) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) out += (i ? ", " : "") + random_number_text(v(i));
  return out + "]";
}

/// Basis text with random spaces around '*' and '^' (and around the whole).
inline std::string spaced_basis(const Monomial& f, const std::vector<std::string>& names) {
  std::string out;
  for (char c : f.text(names)) {
    if (c == '*' || c == '^') {
      out += *rc::gen::element<std::string>("", " ");
      out += c;
      out += *rc::gen::element<std::string>("", " ");
    } else {
      out += c;
    }
  }
  return *rc::gen::element<std::string>("", " ") + out;
}

inline std::string json_terms_forms(const std::vector<ParamTerm<Rational>>& terms,
                                    const std::vector<std::string>& names) {
  std::string out = "[";
  for (size_t i = 0; i < terms.size(); ++i) {
    const std::string basis = "\"basis\": " + json_string(spaced_basis(terms[i].basis, names));
    const std::string value = "\"value\": " + json_matrix_forms(terms[i].value);
    out += (i ? ",\n    {" : "{") + (*rc::gen::arbitrary<bool>() ? basis + ", " + value : value + ", " + basis) + "}";
  }
  return out + "]";
}

inline rc::Gen<ModelText> model_text() {
  return rc::gen::exec([] {
    ModelText mt;
    mt.model = *file_model<Rational>(file_rational());
    const LpvModel<Rational>& m = mt.model;
    const auto& names = m.scheduling;
    std::vector<std::string> members;
    members.push_back("\"format\": \"lpvid-model/1\"");
    members.push_back("\"states\": " + std::to_string(m.nx));
    members.push_back("\"inputs\": " + std::to_string(m.nu));
    members.push_back("\"outputs\": \"" + std::to_string(m.ny) + "\"");  // counts may be strings too
    if (!names.empty() || *rc::gen::arbitrary<bool>()) members.push_back("\"scheduling\": " + json_names(names));
    members.push_back("\"columns\": {\"u\": " + json_names(m.columns.u) + ", \"y\": " + json_names(m.columns.y) +
                      ", \"rho\": " + json_names(m.columns.rho) + "}");
    std::string initial = "{";
    bool first = true;
    for (auto [key, pm] : {std::pair<const char*, const ParamMatrix<Rational>*>{"A", &m.A}, {"B", &m.B},
                           {"C", &m.C}, {"D", &m.D}}) {
      if (pm->terms.empty() && *rc::gen::arbitrary<bool>()) continue;  // absent means zero
      initial += (first ? "\n   \"" : ",\n   \"") + std::string(key) + "\": " + json_terms_forms(pm->terms, names);
      first = false;
    }
    members.push_back("\"initial\": " + initial + "}");
    if (!m.correction.basis.empty() || *rc::gen::arbitrary<bool>()) {
      std::string corr = "{\"basis\": [";
      for (size_t i = 0; i < m.correction.basis.size(); ++i)
        corr += (i ? ", " : "") + json_string(spaced_basis(m.correction.basis[i], names));
      corr += "]";
      for (auto [key, mats] : {std::pair<const char*, const std::vector<Mat<Rational>>*>{"A", &m.correction.A},
                               {"B", &m.correction.B}}) {
        std::vector<ParamTerm<Rational>> terms;
        for (size_t i = 0; i < mats->size(); ++i)
          if (!(*mats)[i].isZero() || *rc::gen::arbitrary<bool>()) terms.push_back({m.correction.basis[i], (*mats)[i]});
        // Any order: the reader matches terms to basis functions by value.
        shuffle(terms);
        if (!terms.empty() || *rc::gen::arbitrary<bool>()) {
          corr += ", \"" + std::string(key) + "\": " + json_terms_forms(terms, names);
        }
      }
      members.push_back("\"correction\": " + corr + "}");
    }
    const auto& u = m.uncertainty;
    if (u.structure == UncertaintyStructure::kGeneral) {
      std::string unc = "{\"structure\": \"general\"";
      const bool have_term = !u.C1.terms.empty() || !u.D1.terms.empty();
      if (!have_term || *rc::gen::arbitrary<bool>()) unc += ", \"nz\": " + std::to_string(u.C1.rows);
      unc += ", \"C1\": " + json_terms_forms(u.C1.terms, names) + ", \"D1\": " + json_terms_forms(u.D1.terms, names);
      members.push_back("\"uncertainty\": " + unc + "}");
    } else {
      const bool mult = u.structure == UncertaintyStructure::kMultiplicative;
      if (mult && u.weight == Rational(1) && *rc::gen::arbitrary<bool>()) {
        // default: no "uncertainty" key at all
      } else {
        std::string unc = "{";
        if (!mult || *rc::gen::arbitrary<bool>()) unc += std::string("\"structure\": ") + (mult ? "\"multiplicative\"" : "\"additive\"");
        if (u.weight != Rational(1) || *rc::gen::arbitrary<bool>())
          unc += std::string(unc.size() > 1 ? ", " : "") + "\"weight\": " + random_number_text(u.weight);
        members.push_back("\"uncertainty\": " + unc + "}");
      }
    }
    if (!m.offset.basis.empty()) {
      std::string off = "{\"basis\": [";
      for (size_t i = 0; i < m.offset.basis.size(); ++i)
        off += (i ? ", " : "") + json_string(spaced_basis(m.offset.basis[i], names));
      off += "]";
      if (!m.offset.values.empty()) {
        off += ", \"values\": [";
        for (size_t i = 0; i < m.offset.values.size(); ++i) off += (i ? ", " : "") + json_vector_forms(m.offset.values[i]);
        off += "]";
      }
      members.push_back("\"offset\": " + off + "}");
    }
    if (!m.x0.isZero() || *rc::gen::arbitrary<bool>()) members.push_back("\"x0\": " + json_vector_forms(m.x0));
    if (*rc::gen::arbitrary<bool>()) members.push_back("\"description\": \"generated\"");

    shuffle(members);  // members in any order
    mt.text = "{\n";
    for (size_t i = 0; i < members.size(); ++i) mt.text += "  " + members[i] + (i + 1 < members.size() ? ",\n" : "\n");
    mt.text += "}\n";
    return mt;
  });
}

inline void showValue(const ModelText& mt, std::ostream& os) { os << mt.text; }

// ------------------------------------------------------------ CSV

/// A table and a CSV text for it.
struct CsvText {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<long> line_numbers;
  std::string text;
};

inline void showValue(const CsvText& c, std::ostream& os) { os << c.text; }

/// A random cell: a number text, or other text without surrounding blanks,
/// possibly holding commas or quotes (then it must be quoted), or empty.
inline rc::Gen<std::string> csv_cell() {
  return rc::gen::exec([] {
    switch (*rc::gen::inRange(0, 4)) {
      case 0: return double_to_text(*file_double());
      case 1: return exact_decimal_or_fraction(*file_rational());
      case 2: return std::string();
      default: {
        const std::vector<std::string> parts = {"a", "b c", ",", "\"", "x\"y", "1.5", "é", "-", "nan"};
        std::string s;
        for (int k = *rc::gen::inRange(1, 4); k > 0; --k) s += *rc::gen::elementOf(parts);
        return s;
      }
    }
  });
}

inline std::string csv_quote_if_needed(const std::string& cell, bool force) {
  if (!force && cell.find_first_of(",\"") == std::string::npos) return cell;
  std::string out = "\"";
  for (char c : cell) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

/// A table of 1..5 columns and 0..8 rows, written with random quoting,
/// spaces around cells, LF or CRLF, trailing commas and blank lines.
inline rc::Gen<CsvText> csv_text() {
  return rc::gen::exec([] {
    CsvText c;
    const int width = *rc::gen::inRange(1, 6);
    for (int k = 0; k < width; ++k) {
      const std::string stem = *rc::gen::element<std::string>("u", "yEst", "a,b", "say \"hi\"", "Ts", "é");
      c.header.push_back(stem + std::to_string(k));
    }
    const int n = *rc::gen::inRange(0, 9);
    for (int r = 0; r < n; ++r) c.rows.push_back(*rc::gen::container<std::vector<std::string>>(static_cast<size_t>(width), csv_cell()));
    const std::string eol = *rc::gen::element<std::string>("\n", "\r\n");
    const bool trailing = *rc::gen::arbitrary<bool>();
    long line = 1;
    auto write_line = [&](const std::vector<std::string>& cells) {
      std::string s;
      for (size_t i = 0; i < cells.size(); ++i) {
        // Quote empty cells of a one-column table, else the line is blank.
        const bool force = (cells.size() == 1 && cells[i].empty()) || *rc::gen::inRange(0, 4) == 0;
        const std::string pad = *rc::gen::element<std::string>("", " ", "\t");
        s += (i ? "," : "") + pad + csv_quote_if_needed(cells[i], force) + pad;
      }
      if (trailing) s += ",";
      c.text += s + eol;
      return line++;
    };
    if (*rc::gen::arbitrary<bool>()) {
      c.text += eol;
      ++line;
    }
    write_line(c.header);
    for (const auto& row : c.rows) {
      if (*rc::gen::inRange(0, 5) == 0) {
        c.text += "  " + eol;
        ++line;
      }
      c.line_numbers.push_back(write_line(row));
    }
    if (*rc::gen::arbitrary<bool>() && c.text.size() >= eol.size())
      c.text.erase(c.text.size() - eol.size());  // no line end after the last line
    return c;
  });
}

/// A numeric CSV (header + 1..6 rows of numbers), as the data files are.
inline rc::Gen<CsvText> numeric_csv_text() {
  return rc::gen::exec([] {
    CsvText c;
    const int width = *rc::gen::inRange(1, 4);
    for (int k = 0; k < width; ++k) c.header.push_back("c" + std::to_string(k));
    const int n = *rc::gen::inRange(1, 7);
    c.text = "\"c0\"";
    for (int k = 1; k < width; ++k) c.text += ",c" + std::to_string(k);
    c.text += ",\r\n";
    for (int r = 0; r < n; ++r) {
      std::vector<std::string> row;
      for (int k = 0; k < width; ++k)
        row.push_back(*rc::gen::arbitrary<bool>() ? double_to_text(*file_double())
                                                  : exact_decimal_or_fraction(*file_rational()));
      for (int k = 0; k < width; ++k) c.text += (k ? "," : "") + row[static_cast<size_t>(k)];
      c.text += ",\r\n";
      c.rows.push_back(row);
      c.line_numbers.push_back(r + 2);
    }
    return c;
  });
}

// ------------------------------------------------------------ corruption

/// Applies 1..3 random edits to `text`: delete, insert or replace a byte
/// (bytes chosen to hit the grammar: brackets, quotes, digits, signs, NUL,
/// invalid UTF-8), delete a span, or duplicate a span.
inline rc::Gen<std::string> corrupted(const std::string& text) {
  return rc::gen::exec([text] {
    static const std::string bytes = std::string("0123456789-+.eE/\"'[]{}:,*^ \n\r\tanrxu\\") + '\0' + "\xff\xc3";
    std::string s = text;
    for (int edits = *rc::gen::inRange(1, 4); edits > 0; --edits) {
      const size_t pos = s.empty() ? 0 : *rc::gen::inRange<size_t>(0, s.size());
      const char byte = bytes[*rc::gen::inRange<size_t>(0, bytes.size())];
      switch (*rc::gen::inRange(0, 5)) {
        case 0:
          if (!s.empty()) s.erase(pos, 1);
          break;
        case 1: s.insert(pos, 1, byte); break;
        case 2:
          if (!s.empty()) s[pos] = byte;
          break;
        case 3:
          if (!s.empty()) s.erase(pos, *rc::gen::inRange<size_t>(1, 12));
          break;
        default:
          if (!s.empty()) s.insert(pos, s.substr(*rc::gen::inRange<size_t>(0, s.size()), *rc::gen::inRange<size_t>(1, 12)));
          break;
      }
    }
    return s;
  });
}

}  // namespace lpvid::gen::files
