#include "examples/random_case.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/SVD>

#include "core/number_text.h"
#include "core/rms.h"
#include "model/param_matrix.h"
#include "model/simulate.h"
#include "toeplitz/fir.h"
#include "toeplitz/tap_toeplitz.h"

namespace lpvid {

int SeededDraw::integer(int lo, int hi) {
  if (hi < lo) throw std::invalid_argument("SeededDraw::integer: empty range");
  return stream_.uniform_int(lo, hi);
}

bool SeededDraw::coin() { return (stream_.next_u64() >> 63) != 0; }

namespace random_case_detail {

Rational decimal_entry(RandomDraw& draw, int max_k, int den) {
  const int z = draw.integer(0, 2 * max_k);
  const int k = z % 2 == 0 ? z / 2 : -(z + 1) / 2;  // 0, −1, 1, −2, 2, …
  return Rational(k) / Rational(den);
}

Rational nonzero_decimal(RandomDraw& draw, int max_k, int den) {
  const int k = draw.integer(1, max_k);
  return Rational(draw.coin() ? -k : k) / Rational(den);
}

std::vector<Monomial> distinct_monomials(std::vector<Monomial> from, int count, RandomDraw& draw) {
  const int n = static_cast<int>(from.size()), k = std::min(count, n);
  for (int i = 0; i < k; ++i) std::swap(from[static_cast<size_t>(i)], from[static_cast<size_t>(draw.integer(i, n - 1))]);
  from.resize(static_cast<size_t>(std::max(k, 0)));
  return from;
}

Rational decimal_round(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*e", digits - 1, x);
  return rational_from_text(buf);
}

/// The law of one matrix entry: k/den, |k| ≤ max_k, never 0 if `nonzero`.
struct DecimalLaw {
  int max_k, den;
  bool nonzero = false;
  Rational operator()(RandomDraw& draw) const {
    return nonzero ? nonzero_decimal(draw, max_k, den) : decimal_entry(draw, max_k, den);
  }
};

/// rows × cols entries of `law`, drawn row by row.
Mat<Rational> decimal_matrix(RandomDraw& draw, Eigen::Index rows, Eigen::Index cols, DecimalLaw law) {
  Mat<Rational> m(rows, cols);
  for (Eigen::Index i = 0; i < rows; ++i)
    for (Eigen::Index j = 0; j < cols; ++j) m(i, j) = law(draw);
  return m;
}

std::vector<std::string> names(const char* prefix, int count) {
  std::vector<std::string> v;
  for (int k = 0; k < count; ++k) v.push_back(prefix + std::to_string(k + 1));
  return v;
}

/// The ρ-dependent terms a model may use: every non-constant monomial of
/// degree ≤ 2 (|f(ρ)| ≤ 1 for |ρ| ≤ 1), none for an LTI model.
struct RhoTerms {
  int n_rho = 0;
  std::vector<Monomial> terms;

  /// Whether the next matrix gets a ρ term (a coin, drawn only if there are terms).
  bool draw_use(RandomDraw& draw) const { return !terms.empty() && draw.coin(); }
};

/// rows × cols matrix: a constant term plus, if `with_rho_term`, one ρ term
/// (a random monomial of `rho`); `row0` (if given, 1 × cols) replaces row 0
/// of the constant term, and then row 0 of the ρ term is zero, so that row 0
/// is the same at every ρ.
ParamMatrix<Rational> param(RandomDraw& draw, int rows, int cols, const RhoTerms& rho, DecimalLaw entry,
                            bool with_rho_term, const Mat<Rational>* row0 = nullptr) {
  ParamMatrix<Rational> m(rows, cols);
  Mat<Rational> c = decimal_matrix(draw, rows, cols, entry);
  if (row0) c.row(0) = *row0;
  m.add(constant_monomial(static_cast<size_t>(rho.n_rho)), c);
  if (with_rho_term && !rho.terms.empty()) {
    const Monomial f = rho.terms[static_cast<size_t>(draw.integer(0, static_cast<int>(rho.terms.size()) - 1))];
    Mat<Rational> v = decimal_matrix(draw, rows, cols, entry);
    if (row0) v.row(0).setZero();
    m.add(f, v);
  }
  return m;
}

/// (g, 0, …, 0) with g ≠ 0 (±0.1 … ±1).
Mat<Rational> first_gain_row(RandomDraw& draw, int cols) {
  Mat<Rational> r = Mat<Rational>::Zero(1, cols);
  r(0, 0) = nonzero_decimal(draw, 10, 10);
  return r;
}

/// B, C, D and the uncertainty channel of `m` (sizes and A already set),
/// with the nonzero-gain row of the file comment.
void draw_io_and_uncertainty(LpvModel<Rational>& m, const RandomModelOptions& o, const RhoTerms& rho,
                             RandomDraw& draw) {
  const DecimalLaw entry{10, 10};
  const int structure = draw.integer(0, o.allow_general ? 2 : (o.allow_additive ? 1 : 0));
  const bool feedthrough = draw.coin();
  if (structure == 0 && !feedthrough) {
    // z_1(0) = W·c·b·u_0(0) ≠ 0 through the state.
    const Mat<Rational> b0 = first_gain_row(draw, m.nu), c0 = first_gain_row(draw, m.nx);
    const bool rb = rho.draw_use(draw);
    m.B = param(draw, m.nx, m.nu, rho, entry, rb, &b0);
    const bool rc = rho.draw_use(draw);
    m.C = param(draw, m.ny, m.nx, rho, entry, rc, &c0);
    m.D = ParamMatrix<Rational>(m.ny, m.nu);
  } else {
    const bool rb = rho.draw_use(draw);
    m.B = param(draw, m.nx, m.nu, rho, entry, rb);
    const bool rc = rho.draw_use(draw);
    m.C = param(draw, m.ny, m.nx, rho, entry, rc);
    if (structure == 0) {
      const Mat<Rational> d0 = first_gain_row(draw, m.nu);
      const bool rd = rho.draw_use(draw);
      m.D = param(draw, m.ny, m.nu, rho, entry, rd, &d0);  // z_0(0) = W·d·u_0(0) ≠ 0
    } else if (draw.coin()) {
      const bool rd = rho.draw_use(draw);
      m.D = param(draw, m.ny, m.nu, rho, entry, rd);
    } else {
      m.D = ParamMatrix<Rational>(m.ny, m.nu);
    }
  }
  m.uncertainty.structure = structure == 0   ? UncertaintyStructure::kMultiplicative
                            : structure == 1 ? UncertaintyStructure::kAdditive
                                             : UncertaintyStructure::kGeneral;
  if (structure == 2) {
    const int nz = draw.integer(1, 2);
    const Mat<Rational> d0 = first_gain_row(draw, m.nu);
    const bool rc1 = rho.draw_use(draw);
    m.uncertainty.C1 = param(draw, nz, m.nx, rho, entry, rc1);
    const bool rd1 = rho.draw_use(draw);
    m.uncertainty.D1 = param(draw, nz, m.nu, rho, entry, rd1, &d0);  // z_0(0) = d·u_0(0)
  } else {
    const int w = draw.integer(0, 2);  // W ∈ {1, 1/2, 2}
    m.uncertainty.weight = w == 0 ? Rational(1) : (w == 1 ? Rational(1) / Rational(2) : Rational(2));
  }
}

/// Sets the first 0 … max_zeros samples of u to zero (at most n − 2, so that
/// the path through the state still reaches z inside the record); returns
/// how many.
int zero_leading_inputs(Experiment<Rational>& exp, int max_zeros, RandomDraw& draw) {
  if (max_zeros <= 0) return 0;  // nothing drawn: the historical distribution
  const int n = static_cast<int>(exp.n());
  const int m = draw.integer(0, std::max(0, std::min(max_zeros, n - 2)));
  exp.u.topRows(m).setZero();
  return m;
}

/// The generating Δ before scaling: `delay` zero taps, then K ∈ [1, max_taps]
/// taps with entries k/10, |k| ≤ 10 (all zero for zero_delta). With a delay
/// option the first of these has a nonzero h(0, 0), so the delay is exactly
/// `delay` (without one, the historical law: all K taps may be zero).
Mat<double> raw_taps(const RandomCaseOptions& o, Eigen::Index cols, int delay, RandomDraw& draw) {
  const int K = draw.integer(1, o.max_taps);
  Mat<double> raw = Mat<double>::Zero(delay + K, cols);
  if (o.zero_delta) return raw;
  raw.bottomRows(K) = nearest_double(decimal_matrix(draw, K, cols, DecimalLaw{10, 10}));
  if (o.max_delay > 0) raw(delay, 0) = nearest_double(nonzero_decimal(draw, 10, 10));
  return raw;
}

}  // namespace random_case_detail

namespace rcd = random_case_detail;

// ------------------------------------------------------------------ FIR Δ

Mat<double> fir_toeplitz(const Mat<double>& taps, Eigen::Index horizon, Eigen::Index ny, Eigen::Index nz) {
  Mat<double> h = Mat<double>::Zero(horizon, ny * nz);  // exactly `horizon` taps: the dense builder's L
  const Eigen::Index K = std::min(taps.rows(), horizon);
  h.topRows(K) = taps.topRows(K);
  return tap_toeplitz_dense(h, ny, nz);
}

double fir_norm(const Mat<double>& taps, Eigen::Index horizon, Eigen::Index ny, Eigen::Index nz) {
  if (horizon == 0 || taps.size() == 0) return 0.0;
  // Singular values only; BDCSVD is Jacobi below 16 columns and fast above.
  const Eigen::BDCSVD<Mat<double>> svd(fir_toeplitz(taps, horizon, ny, nz));
  return svd.singularValues()(0);
}

Mat<double> fir_apply_full(const Mat<double>& taps, const Mat<double>& z, Eigen::Index ny) {
  return apply_fir(taps, z, ny, z.rows());
}

// ------------------------------------------------------------------ bases

std::vector<Monomial> all_monomials(int n_rho, int max_degree) {
  std::vector<Monomial> out{constant_monomial(static_cast<size_t>(n_rho))};
  std::vector<Monomial> frontier = out;
  for (int deg = 1; deg <= max_degree; ++deg) {
    std::vector<Monomial> next;
    for (const Monomial& m : frontier)
      for (int k = 0; k < n_rho; ++k) {
        // only raise variables at or after the last non-zero power: each monomial once
        bool later = true;
        for (int j = k + 1; j < n_rho; ++j)
          if (m.powers[static_cast<size_t>(j)] > 0) later = false;
        if (!later) continue;
        Monomial x = m;
        ++x.powers[static_cast<size_t>(k)];
        next.push_back(x);
      }
    out.insert(out.end(), next.begin(), next.end());
    frontier = next;
  }
  return out;
}

// ------------------------------------------------------------------ generators

LpvModel<Rational> random_model(const RandomModelOptions& o, RandomDraw& draw) {
  LpvModel<Rational> m;
  m.nx = draw.integer(o.min_nx, o.max_nx);
  m.nu = draw.integer(1, o.max_nu);
  m.ny = draw.integer(1, o.max_ny);
  const int n_rho = draw.integer(o.min_rho, o.max_rho);
  m.scheduling = rcd::names("rho", n_rho);
  m.columns.u = rcd::names("u", m.nu);
  m.columns.y = rcd::names("y", m.ny);
  m.columns.rho = m.scheduling;
  rcd::RhoTerms rho{n_rho, {}};
  if (!o.lti)
    for (const Monomial& f : all_monomials(n_rho))
      if (!f.is_constant()) rho.terms.push_back(f);

  // A: each term has |entries| ≤ 0.4/nx, at most two terms: ‖A(ρ)‖∞ ≤ 0.8.
  const bool ra = rho.draw_use(draw);
  m.A = rcd::param(draw, m.nx, m.nx, rho, rcd::DecimalLaw{4, 10 * m.nx}, ra);
  rcd::draw_io_and_uncertainty(m, o, rho, draw);

  const std::vector<Monomial> candidates =
      o.lti ? std::vector<Monomial>{constant_monomial(static_cast<size_t>(n_rho))} : all_monomials(n_rho);
  const int size = static_cast<int>(candidates.size());
  const int N = draw.integer(std::min(o.min_correction, size), std::min(o.max_correction, size));
  m.correction.basis = rcd::distinct_monomials(candidates, N, draw);
  return m;
}

Experiment<Rational> random_trajectory(int nu, int n_rho, int min_n, int max_n, RandomDraw& draw) {
  Experiment<Rational> e;
  e.source = "generated";
  const int n = draw.integer(min_n, max_n);
  e.u = rcd::decimal_matrix(draw, n, nu, rcd::DecimalLaw{10, 10, true});
  e.rho = rcd::decimal_matrix(draw, n, n_rho, rcd::DecimalLaw{10, 10});
  return e;
}

StaticBlocks<Rational> random_static_blocks(RandomDraw& draw) {
  StaticBlocks<Rational> s;
  if (draw.coin()) {
    // lower < 0 < upper: g_in(v) ≠ 0 iff v ≠ 0, so the gain row of z survives.
    s.input.kind = StaticKind::kSaturation;
    s.input.lower = Rational(-draw.integer(2, 10)) / Rational(10);
    s.input.upper = Rational(draw.integer(2, 10)) / Rational(10);
  }
  if (draw.coin()) {
    // g_out(v) = c₀ + v + c₂v², |c₂| ≤ 0.1: a mild curvature on the output.
    s.output.kind = StaticKind::kPolynomial;
    const Rational c0 = rcd::decimal_entry(draw, 2, 10);
    s.output.coefficients = {c0, Rational(1), rcd::nonzero_decimal(draw, 10, 100)};
  }
  return s;
}

void generate_output(RandomCase& c, const Mat<double>& raw_taps, const Mat<double>& noise_dir) {
  const Simulation<Rational> sim = simulate(c.truth, c.exp);
  const Mat<double> out = nearest_double(sim.output), z = nearest_double(sim.z);  // g_out(ŷ + Φ), z
  const Eigen::Index n = c.exp.n(), ny = c.truth.ny, nz = c.truth.nz();
  const double sigma = fir_norm(raw_taps, n, ny, nz);
  c.taps = sigma > 0 ? Mat<double>(raw_taps * (c.delta / (sigma * (1.0 + 1e-6)))) : raw_taps;
  const Mat<double> w = fir_apply_full(c.taps, z, ny);
  c.d = noise_dir * (0.9 * c.dmax * std::sqrt(static_cast<double>(n * ny)) / noise_dir.norm());
  const Mat<double> y = out + w + c.d;
  c.exp.y = Mat<Rational>(n, ny);
  for (Eigen::Index k = 0; k < n; ++k)
    for (Eigen::Index i = 0; i < ny; ++i) c.exp.y(k, i) = rcd::decimal_round(y(k, i), 12);
}

RandomCase random_case(const RandomCaseOptions& o, RandomDraw& draw) {
  RandomCase c;
  c.model = random_model(o.model, draw);
  if (o.static_blocks) c.model.statics = random_static_blocks(draw);
  c.exp = random_trajectory(c.model.nu, c.model.n_rho(), o.min_n, o.max_n, draw);
  c.zero_inputs = rcd::zero_leading_inputs(c.exp, o.leading_zero_inputs, draw);
  c.truth = c.model;
  if (o.true_correction && !c.model.correction.basis.empty()) {
    const CorrectionLayout L = output_correction_layout(c.model);
    c.theta = rcd::decimal_matrix(draw, L.size(), 1, rcd::DecimalLaw{4, 20});
    c.truth = fold_correction(c.model, c.theta);
  }
  const Eigen::Index ny = c.truth.ny, nz = c.truth.nz(), n = c.exp.n();
  c.delay = o.max_delay > 0 ? draw.integer(0, o.max_delay) : 0;
  const Mat<double> raw = rcd::raw_taps(o, ny * nz, c.delay, draw);
  const Mat<double> dir = nearest_double(rcd::decimal_matrix(draw, n, ny, rcd::DecimalLaw{10, 10, true}));
  c.delta = o.zero_delta ? 0.0 : draw.integer(5, 50) / 100.0;
  // d_max relative to the size of the noise-free output (w included).
  const double frac = draw.integer(1, 30) / 100.0;
  RandomCase probe = c;
  probe.dmax = 0.0;
  generate_output(probe, raw, dir);  // noise-free y (up to rounding) to measure its RMS
  double scale = rms(nearest_double(probe.exp.y));
  if (!(scale > 1e-6)) scale = 1.0;
  c.dmax = frac * scale;
  generate_output(c, raw, dir);
  return c;
}

}  // namespace lpvid
