#include "diagnose/residual_analysis.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/input_error.h"
#include "core/rms.h"
#include "diagnose/quantiles.h"

namespace lpvid {
namespace {

void check_rows(const Mat<double>& m, Eigen::Index n, const std::string& what) {
  if (m.rows() != n)
    throw InputError(what + ": " + std::to_string(m.rows()) + " samples, the residual has " + std::to_string(n));
}

void check_level(double level) {
  if (!(level > 0 && level < 1)) throw std::invalid_argument("residual analysis: level must be in (0, 1)");
}

/// Number of lags 1..L with |rho(k)| > band (from index `first`).
int count_outside(const std::vector<double>& rho, double band, size_t first) {
  int c = 0;
  for (size_t k = first; k < rho.size(); ++k) c += std::abs(rho[k]) > band;
  return c;
}

}  // namespace

void require_signal(const Mat<double>& m, const std::string& what) {
  if (m.rows() == 0 || m.cols() == 0)
    throw InputError(what + ": empty signal (" + std::to_string(m.rows()) + " x " + std::to_string(m.cols()) + ")");
  for (Eigen::Index j = 0; j < m.cols(); ++j)
    for (Eigen::Index i = 0; i < m.rows(); ++i)
      if (!std::isfinite(m(i, j)))
        throw InputError(what + ": non-finite value at sample " + std::to_string(i) + ", column " + std::to_string(j));
}

ResidualRms residual_rms(const Mat<double>& r) {
  require_signal(r, "residual");
  ResidualRms out;
  const double n = static_cast<double>(r.rows());
  out.per_output = (r.colwise().squaredNorm().transpose() / n).cwiseSqrt();
  out.overall = rms(r);
  return out;
}

int residual_max_lag(Eigen::Index n, const ResidualAnalysisOptions& options) {
  if (n < 2) throw InputError("residual analysis: at least 2 samples are needed, got " + std::to_string(n));
  if (options.max_lag < -1) throw std::invalid_argument("residual analysis: max_lag must be >= 0 (or -1 for the default)");
  if (options.max_lag == -1) return static_cast<int>(std::max<Eigen::Index>(1, std::min<Eigen::Index>(25, n / 4)));
  if (options.max_lag >= n)
    throw std::invalid_argument("residual analysis: max_lag " + std::to_string(options.max_lag) + " must be below the " +
                                std::to_string(n) + " samples");
  return options.max_lag;
}

double whiteness_band(Eigen::Index n, double level) {
  check_level(level);
  if (n <= 0) throw std::invalid_argument("whiteness_band: no samples");
  return normal_quantile((1 + level) / 2) / std::sqrt(static_cast<double>(n));
}

std::vector<double> normalised_correlation(const Vec<double>& a, const Vec<double>& b, int max_lag) {
  if (a.size() != b.size()) throw InputError("normalised_correlation: signals of different lengths");
  if (max_lag < 0 || max_lag >= a.size()) throw std::invalid_argument("normalised_correlation: max_lag out of range");
  std::vector<double> rho(static_cast<size_t>(max_lag) + 1, 0.0);
  const double scale = std::sqrt(a.squaredNorm() * b.squaredNorm());
  if (scale == 0) return rho;
  const Eigen::Index n = a.size();
  for (int k = 0; k <= max_lag; ++k) rho[static_cast<size_t>(k)] = a.tail(n - k).dot(b.head(n - k)) / scale;
  return rho;
}

WhitenessResult residual_whiteness(const Mat<double>& r, const ResidualAnalysisOptions& options) {
  require_signal(r, "residual");
  check_level(options.level);
  const Eigen::Index n = r.rows();
  WhitenessResult out;
  out.max_lag = residual_max_lag(n, options);
  out.level = options.level;
  out.band_99 = whiteness_band(n, 0.99);
  out.band_95 = whiteness_band(n, 0.95);
  const double threshold = chi_square_quantile(options.level, out.max_lag);
  const double nd = static_cast<double>(n);
  for (Eigen::Index i = 0; i < r.cols(); ++i) {
    AutocorrelationTest t;
    const Vec<double> col = r.col(i);
    t.rho = normalised_correlation(col, col, out.max_lag);
    t.outside_99 = count_outside(t.rho, out.band_99, 1);
    t.outside_95 = count_outside(t.rho, out.band_95, 1);
    for (int k = 1; k <= out.max_lag; ++k) t.q += t.rho[static_cast<size_t>(k)] * t.rho[static_cast<size_t>(k)] / (nd - k);
    t.q *= nd * (nd + 2);
    t.q_threshold = threshold;
    t.white = t.q <= threshold;
    out.white = out.white && t.white;
    out.outputs.push_back(std::move(t));
  }
  return out;
}

CrossCorrelationResult residual_input_correlation(const Mat<double>& r, const Mat<double>& u,
                                                  const ResidualAnalysisOptions& options) {
  require_signal(r, "residual");
  require_signal(u, "input");
  check_rows(u, r.rows(), "input");
  check_level(options.level);
  CrossCorrelationResult out;
  out.max_lag = residual_max_lag(r.rows(), options);
  out.band_99 = whiteness_band(r.rows(), 0.99);
  out.band_95 = whiteness_band(r.rows(), 0.95);
  out.band = whiteness_band(r.rows(), options.level);
  for (Eigen::Index i = 0; i < r.cols(); ++i) {
    for (Eigen::Index j = 0; j < u.cols(); ++j) {
      CrossCorrelation c;
      c.output = static_cast<int>(i);
      c.input = static_cast<int>(j);
      c.rho = normalised_correlation(r.col(i), u.col(j), out.max_lag);
      for (size_t k = 0; k < c.rho.size(); ++k) {
        if (std::abs(c.rho[k]) > c.max_abs) {
          c.max_abs = std::abs(c.rho[k]);
          c.max_lag_at = static_cast<int>(k);
        }
      }
      c.outside_99 = count_outside(c.rho, out.band_99, 0);
      c.significant = c.max_abs > out.band;
      out.pairs.push_back(std::move(c));
    }
  }
  return out;
}

namespace {

CandidateShare candidate_share(const Mat<double>& r, const CandidateSignal& cand) {
  const std::string what = "candidate '" + cand.name + "'";
  require_signal(cand.columns, what);
  check_rows(cand.columns, r.rows(), what);
  CandidateShare out;
  out.name = cand.name;
  const Eigen::Index ny = r.cols(), m = cand.columns.cols();
  const Vec<double> cnorm = cand.columns.colwise().norm().transpose();
  const Vec<double> rnorm = r.colwise().norm().transpose();
  out.correlation = Mat<double>::Zero(ny, m);
  for (Eigen::Index i = 0; i < ny; ++i)
    for (Eigen::Index j = 0; j < m; ++j)
      if (rnorm(i) > 0 && cnorm(j) > 0) out.correlation(i, j) = r.col(i).dot(cand.columns.col(j)) / (rnorm(i) * cnorm(j));
  out.max_abs_correlation = out.correlation.cwiseAbs().maxCoeff();

  // Projection on unit-norm columns (zero columns stay zero and are
  // dropped by the pivoting): P r = Q1·Q1ᵀ·r with Q1 the first rank()
  // columns of the pivoted QR's Q. (Eigen's solve() is not used: it counts
  // nonzero pivots with its own eps-level threshold, not with setThreshold.)
  Mat<double> c = cand.columns;
  for (Eigen::Index j = 0; j < m; ++j)
    if (cnorm(j) > 0) c.col(j) /= cnorm(j);
  Eigen::ColPivHouseholderQR<Mat<double>> qr(c.rows(), c.cols());
  qr.setThreshold(kProjectionTolerance);
  qr.compute(c);
  out.rank = static_cast<int>(qr.rank());
  const Mat<double> q1 = qr.householderQ() * Mat<double>::Identity(r.rows(), out.rank);
  const Mat<double> fitted = q1 * (q1.transpose() * r);
  const Vec<double> left = (r - fitted).colwise().squaredNorm().transpose();
  const Vec<double> energy = r.colwise().squaredNorm().transpose();
  out.share_per_output = Vec<double>::Zero(ny);
  for (Eigen::Index i = 0; i < ny; ++i)
    if (energy(i) > 0) out.share_per_output(i) = std::clamp(1 - left(i) / energy(i), 0.0, 1.0);
  out.share = energy.sum() > 0 ? std::clamp(1 - left.sum() / energy.sum(), 0.0, 1.0) : 0.0;
  return out;
}

}  // namespace

std::vector<CandidateShare> candidate_shares(const Mat<double>& r, const std::vector<CandidateSignal>& candidates) {
  require_signal(r, "residual");
  std::vector<CandidateShare> out;
  out.reserve(candidates.size());
  for (const CandidateSignal& c : candidates) out.push_back(candidate_share(r, c));
  return out;
}

ResidualAnalysis analyse_residual(const Mat<double>& r, const Mat<double>& u,
                                  const std::vector<CandidateSignal>& candidates,
                                  const ResidualAnalysisOptions& options) {
  ResidualAnalysis out;
  out.rms = residual_rms(r);
  out.whiteness = residual_whiteness(r, options);
  if (u.cols() > 0) out.input_correlation = residual_input_correlation(r, u, options);
  else out.input_correlation = {out.whiteness.max_lag, out.whiteness.band_99, out.whiteness.band_95,
                                whiteness_band(r.rows(), options.level), {}};
  out.candidates = candidate_shares(r, candidates);
  return out;
}

}  // namespace lpvid
