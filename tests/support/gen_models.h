#pragma once
/// Generators for LPV models and trajectories (docs/design.md §5), built by
/// construction (no rejection sampling) and sized by rapidcheck's size:
/// nx 1..3, nu 1..2, ny 1..2, nρ 0..2, n 1..8, monomial bases of degree ≤ 2,
/// 0..max_terms terms per matrix, random uncertainty structure. Integers
/// shrink towards 0 and sizes towards their minimum, so failing cases shrink
/// to tiny models. Also: exact comparison and readable printing of
/// counterexamples (rapidcheck finds showValue by ADL).

#include <rapidcheck.h>

#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

#include "core/number_text.h"
#include "core/scalar.h"
#include "data/experiment.h"
#include "model/lpv_model.h"
#include "model/monomial.h"
#include "model/param_matrix.h"
#include "support/gen_numbers.h"

namespace lpvid::gen {

/// Integer uniform in [lo, hi] whatever the size; shrinks towards lo.
inline rc::Gen<int> uniform_int(int lo, int hi) { return rc::gen::resize(100, rc::gen::inRange(lo, hi + 1)); }

/// A dimension or count in [lo, hi]: the upper end grows with size and is
/// reached from size 50 on (rapidcheck's inRange reaches its maximum only at
/// size 100, i.e. almost never); shrinks towards lo.
inline rc::Gen<int> sized_int(int lo, int hi) {
  return rc::gen::withSize([=](int size) {
    const int span = hi - lo;
    const int top = lo + std::min(span, (span * std::max(size, 0) + 49) / 50);
    return uniform_int(lo, top);
  });
}

/// Integer in [−max_abs, max_abs]; the range grows with size, shrinks to 0.
template <typename Int = int>
rc::Gen<Int> zero_centred_int(Int max_abs) {
  const rc::Gen<Int> zigzag_index = rc::gen::withSize([=](int size) {
    const Int span = 2 * max_abs;
    const Int top = std::min(span, (span / 50) * std::max(size, 0) + (span % 50 * std::max(size, 0) + 49) / 50);
    return rc::gen::resize(100, rc::gen::inRange<Int>(0, top + 1));
  });
  // 0, −1, 1, −2, 2, …: shrinking the index towards 0 shrinks the value to 0.
  return rc::gen::map(zigzag_index,
                      [](Int z) { return z % 2 == 0 ? static_cast<Int>(z / 2) : static_cast<Int>(-(z + 1) / 2); });
}

/// Integer entry in [−max_abs, max_abs] as a Rational (exact in double too).
inline rc::Gen<Rational> int_entry(int max_abs) {
  return rc::gen::map(zero_centred_int(max_abs), [](int v) { return Rational(v); });
}

/// p/q with |p| ≤ max_abs and 1 ≤ q ≤ max_den (shrinks to 0 and to q = 1).
inline rc::Gen<Rational> rational_entry(int max_abs, int max_den) {
  return rc::gen::map(rc::gen::pair(zero_centred_int(max_abs), sized_int(1, max_den)),
                      [](const std::pair<int, int>& pq) { return Rational(pq.first) / Rational(pq.second); });
}

/// p·2^e with |p| < 2^40 and |e| ≤ 60: a dyadic rational that a double
/// holds exactly.
inline rc::Gen<Rational> dyadic_entry() {
  return rc::gen::map(rc::gen::pair(zero_centred_int<long long>((1LL << 40) - 1), zero_centred_int(60)),
                      [](const std::pair<long long, int>& pe) {
                        Rational q(pe.first);
                        const Rational two_e(static_cast<long long>(1LL << (pe.second < 0 ? -pe.second : pe.second)));
                        return pe.second < 0 ? Rational(q / two_e) : Rational(q * two_e);
                      });
}

/// A monomial in n_rho variables of degree ≤ max_degree (constant if n_rho = 0).
inline rc::Gen<Monomial> monomial(int n_rho, int max_degree = 2) {
  return rc::gen::exec([=] {
    Monomial m{std::vector<int>(static_cast<size_t>(n_rho), 0)};
    if (n_rho == 0) return m;
    const int degree = *sized_int(0, max_degree);
    for (int t = 0; t < degree; ++t) ++m.powers[static_cast<size_t>(*uniform_int(0, n_rho - 1))];
    return m;
  });
}

/// rows × cols parameter matrix with 0..max_terms terms; constant_only
/// makes every basis function the constant 1 (an LTI matrix).
inline rc::Gen<ParamMatrix<Rational>> param_matrix(int rows, int cols, int n_rho, rc::Gen<Rational> entry,
                                                   int max_terms, bool constant_only) {
  return rc::gen::exec([=] {
    ParamMatrix<Rational> m(rows, cols);
    const int n_terms = *sized_int(0, max_terms);
    for (int t = 0; t < n_terms; ++t) {
      const Monomial f = constant_only ? constant_monomial(static_cast<size_t>(n_rho)) : *monomial(n_rho);
      m.add(f, *rational_matrix(rows, cols, entry));
    }
    return m;
  });
}

/// Options of the model generator.
struct ModelOptions {
  rc::Gen<Rational> entry = int_entry(2);  ///< every matrix entry, weight, x0
  bool lti = false;                        ///< all basis functions constant (nρ may be > 0)
  bool zero_x0 = false;                    ///< x0 left empty (zero)
  bool allow_general = true;               ///< may pick the general uncertainty structure
  int max_terms = 2;                       ///< terms per parameter matrix
  int max_correction = 2;                  ///< correction basis functions N
};

/// A random LPV model (docs/design.md §5): random sizes, terms, correction basis with
/// fixed A_i, B_i (empty list, or per-function zero or random), uncertainty
/// structure and weight, optional known offset, optional x0.
inline rc::Gen<LpvModel<Rational>> lpv_model(ModelOptions o = {}) {
  return rc::gen::exec([o] {
    LpvModel<Rational> m;
    m.nx = *sized_int(1, 3);
    m.nu = *sized_int(1, 2);
    m.ny = *sized_int(1, 2);
    const int n_rho = *sized_int(0, 2);
    for (int k = 0; k < n_rho; ++k) m.scheduling.push_back("rho" + std::to_string(k + 1));
    for (int k = 0; k < m.nu; ++k) m.columns.u.push_back("u" + std::to_string(k + 1));
    for (int k = 0; k < m.ny; ++k) m.columns.y.push_back("y" + std::to_string(k + 1));
    m.columns.rho = m.scheduling;
    m.A = *param_matrix(m.nx, m.nx, n_rho, o.entry, o.max_terms, o.lti);
    m.B = *param_matrix(m.nx, m.nu, n_rho, o.entry, o.max_terms, o.lti);
    m.C = *param_matrix(m.ny, m.nx, n_rho, o.entry, o.max_terms, o.lti);
    m.D = *param_matrix(m.ny, m.nu, n_rho, o.entry, o.max_terms, o.lti);

    const int N = *sized_int(0, o.max_correction);
    for (int i = 0; i < N; ++i)
      m.correction.basis.push_back(o.lti ? constant_monomial(static_cast<size_t>(n_rho)) : *monomial(n_rho));
    if (N > 0 && *rc::gen::arbitrary<bool>()) {
      for (int i = 0; i < N; ++i) {
        const bool zero = *rc::gen::arbitrary<bool>();
        m.correction.A.push_back(zero ? Mat<Rational>(Mat<Rational>::Zero(m.nx, m.nx))
                                      : *rational_matrix(m.nx, m.nx, o.entry));
        m.correction.B.push_back(zero ? Mat<Rational>(Mat<Rational>::Zero(m.nx, m.nu))
                                      : *rational_matrix(m.nx, m.nu, o.entry));
      }
    }

    const int structure = *uniform_int(0, o.allow_general ? 2 : 1);
    m.uncertainty.structure = structure == 0   ? UncertaintyStructure::kMultiplicative
                              : structure == 1 ? UncertaintyStructure::kAdditive
                                               : UncertaintyStructure::kGeneral;
    m.uncertainty.weight = *rc::gen::oneOf(rc::gen::just(Rational(1)), o.entry);
    if (m.uncertainty.structure == UncertaintyStructure::kGeneral) {
      const int nz = *sized_int(1, 2);
      m.uncertainty.C1 = *param_matrix(nz, m.nx, n_rho, o.entry, o.max_terms, o.lti);
      m.uncertainty.D1 = *param_matrix(nz, m.nu, n_rho, o.entry, o.max_terms, o.lti);
    }

    const int M = *sized_int(0, 2);
    for (int j = 0; j < M; ++j)
      m.offset.basis.push_back(o.lti ? constant_monomial(static_cast<size_t>(n_rho)) : *monomial(n_rho));
    if (M > 0 && *rc::gen::arbitrary<bool>())
      for (int j = 0; j < M; ++j) m.offset.values.push_back(*rational_matrix(m.ny, 1, o.entry));

    if (!o.zero_x0 && *rc::gen::arbitrary<bool>()) m.x0 = *rational_matrix(m.nx, 1, o.entry);
    return m;
  });
}

/// A trajectory for a model: n (1..8) samples of u and y with entries from
/// `entry` and ρ from `rho_entry`; constant_rho repeats ρ_0 at every sample.
inline rc::Gen<Experiment<Rational>> experiment(int nu, int ny, int n_rho, rc::Gen<Rational> entry,
                                                rc::Gen<Rational> rho_entry, bool constant_rho = false) {
  return rc::gen::exec([=] {
    Experiment<Rational> e;
    e.source = "generated";
    const int n = *sized_int(1, 8);
    e.u = *rational_matrix(n, nu, entry);
    e.y = *rational_matrix(n, ny, entry);
    if (constant_rho) {
      const Mat<Rational> rho0 = *rational_matrix(1, n_rho, rho_entry);
      e.rho = rho0.replicate(n, 1);
    } else {
      e.rho = *rational_matrix(n, n_rho, rho_entry);
    }
    return e;
  });
}

struct ModelAndData {
  LpvModel<Rational> model;
  Experiment<Rational> data;
};

/// A model and a trajectory that fits it (ρ entries from `rho_entry`,
/// default small integers).
inline rc::Gen<ModelAndData> model_and_data(ModelOptions o = {}, rc::Gen<Rational> rho_entry = int_entry(2),
                                            bool constant_rho = false) {
  return rc::gen::exec([=] {
    ModelAndData md;
    md.model = *lpv_model(o);
    md.data = *experiment(md.model.nu, md.model.ny, md.model.n_rho(), o.entry, rho_entry, constant_rho);
    return md;
  });
}

// ---------------------------------------------------------------- helpers

/// Same size and exactly equal entries (Eigen's == requires equal sizes).
template <typename A, typename B>
bool exactly_equal(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() && (a.rows() == 0 || a.cols() == 0 || a == b);
}

/// Exact value of each double entry.
inline Mat<Rational> exact_matrix(const Mat<double>& m) {
  Mat<Rational> out(m.rows(), m.cols());
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) out(i, j) = exact_rational_of_double(m(i, j));
  return out;
}

/// The experiment with every entry converted exactly to double (for small
/// integers and dyadics; the generators only make such values there).
inline Experiment<double> to_double_experiment(const Experiment<Rational>& e) {
  Experiment<double> d;
  d.source = e.source;
  d.u = to_double_matrix(e.u);
  d.y = to_double_matrix(e.y);
  d.rho = to_double_matrix(e.rho);
  return d;
}

inline bool param_matrices_equal(const ParamMatrix<Rational>& a, const ParamMatrix<Rational>& b) {
  if (a.rows != b.rows || a.cols != b.cols || a.terms.size() != b.terms.size()) return false;
  for (size_t j = 0; j < a.terms.size(); ++j)
    if (!(a.terms[j].basis == b.terms[j].basis) || !exactly_equal(a.terms[j].value, b.terms[j].value))
      return false;
  return true;
}

template <typename M>
bool lists_equal(const std::vector<M>& a, const std::vector<M>& b) {
  if (a.size() != b.size()) return false;
  for (size_t j = 0; j < a.size(); ++j)
    if (!exactly_equal(a[j], b[j])) return false;
  return true;
}

/// Every field of two exact models is equal.
inline bool models_equal(const LpvModel<Rational>& a, const LpvModel<Rational>& b) {
  return a.nx == b.nx && a.nu == b.nu && a.ny == b.ny && a.scheduling == b.scheduling &&
         a.columns.u == b.columns.u && a.columns.y == b.columns.y && a.columns.rho == b.columns.rho &&
         param_matrices_equal(a.A, b.A) && param_matrices_equal(a.B, b.B) && param_matrices_equal(a.C, b.C) &&
         param_matrices_equal(a.D, b.D) && a.correction.basis == b.correction.basis &&
         lists_equal(a.correction.A, b.correction.A) && lists_equal(a.correction.B, b.correction.B) &&
         a.uncertainty.structure == b.uncertainty.structure && a.uncertainty.weight == b.uncertainty.weight &&
         param_matrices_equal(a.uncertainty.C1, b.uncertainty.C1) &&
         param_matrices_equal(a.uncertainty.D1, b.uncertainty.D1) && a.offset.basis == b.offset.basis &&
         lists_equal(a.offset.values, b.offset.values) && exactly_equal(a.x0, b.x0);
}

}  // namespace lpvid::gen

namespace lpvid {

// Readable counterexamples (found by rapidcheck through ADL).

inline void show_matrix(const Mat<Rational>& m, std::ostream& os) {
  os << "[";
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    os << (i ? ", [" : "[");
    for (Eigen::Index j = 0; j < m.cols(); ++j) os << (j ? ", " : "") << rational_to_text(m(i, j));
    os << "]";
  }
  os << "]";
}

inline void show_param(const char* name, const ParamMatrix<Rational>& p, const std::vector<std::string>& names,
                       std::ostream& os) {
  os << "  " << name << " (" << p.rows << "x" << p.cols << "):";
  if (p.terms.empty()) os << " 0";
  for (const auto& t : p.terms) {
    os << " + " << t.basis.text(names) << "*";
    show_matrix(t.value, os);
  }
  os << "\n";
}

inline void showValue(const LpvModel<Rational>& m, std::ostream& os) {
  const auto& s = m.scheduling;
  os << "LpvModel nx=" << m.nx << " nu=" << m.nu << " ny=" << m.ny << " n_rho=" << m.n_rho()
     << " structure=" << to_string(m.uncertainty.structure) << " W=" << rational_to_text(m.uncertainty.weight)
     << "\n";
  show_param("A", m.A, s, os);
  show_param("B", m.B, s, os);
  show_param("C", m.C, s, os);
  show_param("D", m.D, s, os);
  for (size_t i = 0; i < m.correction.basis.size(); ++i) {
    os << "  correction f" << i + 1 << " = " << m.correction.basis[i].text(s);
    if (!m.correction.A.empty()) {
      os << " A_i=";
      show_matrix(m.correction.A[i], os);
      os << " B_i=";
      show_matrix(m.correction.B[i], os);
    }
    os << "\n";
  }
  if (m.uncertainty.structure == UncertaintyStructure::kGeneral) {
    show_param("C1", m.uncertainty.C1, s, os);
    show_param("D1", m.uncertainty.D1, s, os);
  }
  for (size_t j = 0; j < m.offset.basis.size(); ++j) {
    os << "  offset h" << j + 1 << " = " << m.offset.basis[j].text(s);
    if (!m.offset.values.empty()) {
      os << " phi=";
      show_matrix(m.offset.values[j], os);
    }
    os << "\n";
  }
  os << "  x0=";
  show_matrix(m.x0, os);
  os << "\n";
}

inline void showValue(const Experiment<Rational>& e, std::ostream& os) {
  os << "Experiment n=" << e.n() << " u=";
  show_matrix(e.u, os);
  os << " y=";
  show_matrix(e.y, os);
  os << " rho=";
  show_matrix(e.rho, os);
  os << "\n";
}

}  // namespace lpvid

namespace lpvid::gen {

inline void showValue(const ModelAndData& md, std::ostream& os) {
  lpvid::showValue(md.model, os);
  lpvid::showValue(md.data, os);
}

}  // namespace lpvid::gen
