#pragma once
/// Residual analysis for closing the loop on measured data (docs/design.md §9.1).
///
/// The residual of a model on data is r = y − ŷ − Φ (n samples × ny
/// outputs, one column per output). If the model explains everything but
/// the noise, r is white and uncorrelated with past inputs and with any
/// signal the model leaves out. The tests here are the classical residual
/// tests of Ljung, System Identification: Theory for the User, 2nd ed.,
/// 1999, §16.6 ("Residual analysis") and Box, Jenkins & Reinsel, Time
/// Series Analysis, §8.2 (portmanteau test).
///
/// Conventions:
///  - correlations are not mean-corrected (as in Ljung §16.6): a model that
///    misses an output offset leaves a residual with a non-zero mean, and
///    that shows as autocorrelation at every lag, which is what it is;
///  - the default number of lags is L = min(25, n/4) (at least 1);
///  - the confidence band of a normalised correlation of n samples of white
///    noise is ±z_{(1+level)/2}/√n (asymptotically normal, variance 1/n):
///    ±2.576/√n at 99 %, ±1.960/√n at 95 %.
///
/// Errors: lpvid::InputError for empty, mismatched or non-finite signals;
/// std::invalid_argument for option values out of range. All functions are
/// pure (no state, no I/O).

#include <string>
#include <vector>

#include "core/scalar.h"

namespace lpvid {

struct ResidualAnalysisOptions {
  int max_lag = -1;      ///< L; -1: min(25, n/4), at least 1; must be < n
  double level = 0.99;   ///< confidence level of the whiteness verdicts, in (0, 1)
};

/// Root mean square of each column and of all entries.
struct ResidualRms {
  Vec<double> per_output;  ///< sqrt(Σ_t r_i(t)² / n)
  double overall = 0;      ///< sqrt(Σ_{t,i} r_i(t)² / (n·ny))
};

ResidualRms residual_rms(const Mat<double>& r);

/// Throws InputError("<what>: …") unless m has rows, columns and only
/// finite entries (the check every function here applies to its signals).
void require_signal(const Mat<double>& m, const std::string& what);

/// The number of lags used for n samples: options.max_lag, or min(25, n/4)
/// (at least 1). Throws std::invalid_argument when max_lag >= n or < -1.
int residual_max_lag(Eigen::Index n, const ResidualAnalysisOptions& options = {});

/// ±z/√n for a two-sided confidence level: the band that a normalised
/// correlation of n samples of white noise stays in with that probability.
double whiteness_band(Eigen::Index n, double level);

/// Normalised correlation ρ_ab(k) = Σ_{t=k}^{n−1} a(t)·b(t−k) / √(Σa²·Σb²)
/// for k = 0..max_lag (Ljung eq. 16.61 divided by √(R_a(0)·R_b(0))).
/// A zero signal gives 0 at every lag.
std::vector<double> normalised_correlation(const Vec<double>& a, const Vec<double>& b, int max_lag);

/// Autocorrelation test of one output's residual.
struct AutocorrelationTest {
  std::vector<double> rho;   ///< ρ(k), k = 0..L (ρ(0) = 1 unless r ≡ 0)
  int outside_99 = 0;        ///< lags 1..L with |ρ(k)| > band_99
  int outside_95 = 0;        ///< lags 1..L with |ρ(k)| > band_95
  /// Ljung–Box portmanteau statistic Q = n(n+2) Σ_{k=1}^{L} ρ(k)²/(n−k)
  /// (Ljung & Box, Biometrika 65, 1978); χ²(L) under whiteness.
  double q = 0;
  /// χ²_{level}(L), chi_square_quantile. The degrees of freedom are not
  /// reduced by the number of fitted parameters (Box–Jenkins use L − p for
  /// ARMA residuals); with L = 25 and few parameters the difference is small
  /// and errs towards calling a residual white.
  double q_threshold = 0;
  bool white = true;         ///< q <= q_threshold
};

struct WhitenessResult {
  int max_lag = 0;           ///< L
  double level = 0.99;
  double band_99 = 0, band_95 = 0;          ///< whiteness_band(n, 0.99 / 0.95)
  std::vector<AutocorrelationTest> outputs;  ///< one per column of r
  bool white = true;         ///< every output white
};

/// Autocorrelation of each residual column with its band and the
/// Ljung–Box verdict at options.level.
WhitenessResult residual_whiteness(const Mat<double>& r, const ResidualAnalysisOptions& options = {});

/// Correlation of residual output i with input j at lags 0..L:
/// ρ_{r_i u_j}(k) = Σ_t r_i(t)·u_j(t−k) / √(Σr_i²·Σu_j²) (Ljung §16.6:
/// a value outside the band at lag k ≥ 0 says that u(t−k) still explains
/// part of the output, e.g. a wrong delay or missing dynamics).
struct CrossCorrelation {
  int output = 0, input = 0;
  std::vector<double> rho;   ///< k = 0..L
  double max_abs = 0;        ///< max_k |ρ(k)|
  int max_lag_at = 0;        ///< the k of max_abs (the smallest on ties)
  int outside_99 = 0;        ///< lags 0..L outside band_99
  bool significant = false;  ///< max_abs above the band at options.level
};

struct CrossCorrelationResult {
  int max_lag = 0;
  double band_99 = 0, band_95 = 0, band = 0;  ///< band: at options.level
  std::vector<CrossCorrelation> pairs;         ///< (output, input) row-major: output·nu + input
};

CrossCorrelationResult residual_input_correlation(const Mat<double>& r, const Mat<double>& u,
                                                  const ResidualAnalysisOptions& options = {});

/// A named signal that an effect the model lacks would add to the output,
/// n × m (e.g. u², sat(u), y(t−1)·x(t), one column per channel).
struct CandidateSignal {
  std::string name;
  Mat<double> columns;
};

/// Tolerance of the least-squares projection: the candidate's columns are
/// scaled to unit norm, and a column-pivoted QR treats a pivot
/// |R_kk| <= kProjectionTolerance·|R_11| as zero (the column depends on
/// the earlier ones), so rank-deficient candidates are projected on the
/// span of their independent columns.
inline constexpr double kProjectionTolerance = 1e-10;

/// How much of the residual a candidate explains.
struct CandidateShare {
  std::string name;
  /// 1 − ‖r − P r‖²/‖r‖² (Frobenius), P the orthogonal projection on the
  /// span of the candidate's columns; each output is regressed on all
  /// columns. In [0, 1]; 0 when r ≡ 0.
  double share = 0;
  Vec<double> share_per_output;  ///< the same for each output column
  int rank = 0;                  ///< dimension of the span (numerical rank)
  /// ny × m normalised correlations ⟨r_i, c_j⟩/(‖r_i‖·‖c_j‖) (0 where a
  /// norm is 0); for one column, correlation² = share.
  Mat<double> correlation;
  double max_abs_correlation = 0;
};

/// One entry per candidate, in the given order. Throws InputError when a
/// candidate has no columns, a different number of rows, or non-finite
/// entries.
std::vector<CandidateShare> candidate_shares(const Mat<double>& r, const std::vector<CandidateSignal>& candidates);

/// Everything above for one residual.
struct ResidualAnalysis {
  ResidualRms rms;
  WhitenessResult whiteness;
  CrossCorrelationResult input_correlation;  ///< empty pairs when u has no columns
  std::vector<CandidateShare> candidates;
};

ResidualAnalysis analyse_residual(const Mat<double>& r, const Mat<double>& u,
                                  const std::vector<CandidateSignal>& candidates,
                                  const ResidualAnalysisOptions& options = {});

}  // namespace lpvid
