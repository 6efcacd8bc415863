#include "model/lpv_model.h"

#include <stdexcept>
#include <string>

#include "core/number_text.h"

namespace lpvid {

const char* to_string(UncertaintyStructure s) {
  switch (s) {
    case UncertaintyStructure::kMultiplicative:
      return "multiplicative";
    case UncertaintyStructure::kAdditive:
      return "additive";
    case UncertaintyStructure::kGeneral:
      return "general";
  }
  return "unknown";
}

/// docs/design.md §5: nz = ny (multiplicative, z = W·ŷ), nu (additive, z = W·u), or the
/// rows of the given C1/D1 (general). A 0×0 C1 or D1 without terms counts as
/// "not given" (identically zero), so only the other one fixes nz.
template <typename T>
int LpvModel<T>::nz() const {
  switch (uncertainty.structure) {
    case UncertaintyStructure::kMultiplicative:
      return ny;
    case UncertaintyStructure::kAdditive:
      return nu;
    case UncertaintyStructure::kGeneral: {
      const ParamMatrix<T>& c1 = uncertainty.C1;
      const ParamMatrix<T>& d1 = uncertainty.D1;
      const bool c1_absent = c1.rows == 0 && c1.cols == 0 && c1.empty();
      const bool d1_absent = d1.rows == 0 && d1.cols == 0 && d1.empty();
      if (c1_absent) return static_cast<int>(d1.rows);
      if (d1_absent) return static_cast<int>(c1.rows);
      if (c1.rows != d1.rows)
        throw std::invalid_argument("general uncertainty channel: C1 has " + std::to_string(c1.rows) +
                                    " rows but D1 has " + std::to_string(d1.rows) + " (both must be nz)");
      return static_cast<int>(c1.rows);
    }
  }
  throw std::invalid_argument("unknown uncertainty structure");
}

template struct LpvModel<double>;
template struct LpvModel<Rational>;

namespace {

// Scalar conversions used by convert_model. Rational -> double rounds to
// nearest (once); double -> Rational is exact (every double is dyadic).
template <typename To, typename From>
struct ScalarConvert;

template <>
struct ScalarConvert<double, double> {
  static double run(double x) { return x; }
};
template <>
struct ScalarConvert<Rational, Rational> {
  static Rational run(const Rational& x) { return x; }
};
template <>
struct ScalarConvert<double, Rational> {
  static double run(const Rational& x) { return nearest_double(x); }
};
template <>
struct ScalarConvert<Rational, double> {
  static Rational run(double x) { return exact_rational_of_double(x); }
};

template <typename To, typename From>
To conv(const From& x) {
  return ScalarConvert<To, From>::run(x);
}

template <typename To, typename From>
Mat<To> conv(const Mat<From>& m) {
  Mat<To> out(m.rows(), m.cols());
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) out(i, j) = conv<To>(m(i, j));
  return out;
}

template <typename To, typename From>
Vec<To> conv(const Vec<From>& v) {
  Vec<To> out(v.size());
  for (Eigen::Index i = 0; i < v.size(); ++i) out(i) = conv<To>(v(i));
  return out;
}

template <typename To, typename From>
ParamMatrix<To> conv(const ParamMatrix<From>& p) {
  ParamMatrix<To> out(p.rows, p.cols);
  out.terms.reserve(p.terms.size());
  for (const auto& t : p.terms) out.terms.push_back({t.basis, conv<To>(t.value)});
  return out;
}

}  // namespace

template <typename To, typename From>
LpvModel<To> convert_model(const LpvModel<From>& m) {
  LpvModel<To> out;
  out.nx = m.nx;
  out.nu = m.nu;
  out.ny = m.ny;
  out.scheduling = m.scheduling;
  out.columns = m.columns;
  out.signal_info = m.signal_info;
  out.A = conv<To>(m.A);
  out.B = conv<To>(m.B);
  out.C = conv<To>(m.C);
  out.D = conv<To>(m.D);
  out.correction.basis = m.correction.basis;
  for (const auto& a : m.correction.A) out.correction.A.push_back(conv<To>(a));
  for (const auto& b : m.correction.B) out.correction.B.push_back(conv<To>(b));
  out.uncertainty.structure = m.uncertainty.structure;
  out.uncertainty.weight = conv<To>(m.uncertainty.weight);
  out.uncertainty.C1 = conv<To>(m.uncertainty.C1);
  out.uncertainty.D1 = conv<To>(m.uncertainty.D1);
  out.statics.input_delay = m.statics.input_delay;
  for (auto [dst, src] : {std::pair{&out.statics.input, &m.statics.input}, std::pair{&out.statics.output, &m.statics.output}}) {
    dst->kind = src->kind;
    dst->lower = conv<To>(src->lower);
    dst->upper = conv<To>(src->upper);
    for (const auto& c : src->coefficients) dst->coefficients.push_back(conv<To>(c));
    for (const auto& x : src->knots) dst->knots.push_back(conv<To>(x));
    for (const auto& x : src->range) dst->range.push_back(conv<To>(x));
  }
  out.offset.basis = m.offset.basis;
  for (const auto& v : m.offset.values) out.offset.values.push_back(conv<To>(v));
  out.state_offset.basis = m.state_offset.basis;
  for (const auto& v : m.state_offset.values) out.state_offset.values.push_back(conv<To>(v));
  out.x0 = conv<To>(m.x0);
  for (const auto& x : m.later_x0) out.later_x0.push_back(conv<To>(x));
  return out;
}

template LpvModel<double> convert_model<double, double>(const LpvModel<double>&);
template LpvModel<double> convert_model<double, Rational>(const LpvModel<Rational>&);
template LpvModel<Rational> convert_model<Rational, Rational>(const LpvModel<Rational>&);
template LpvModel<Rational> convert_model<Rational, double>(const LpvModel<double>&);

}  // namespace lpvid
