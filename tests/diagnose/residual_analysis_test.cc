// Residual analysis (diagnose/residual_analysis.h) on signals whose answer
// is known from mathematics: white noise, AR(1), a scaled candidate plus
// noise, a residual orthogonal to the candidate, a delayed input.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/input_error.h"
#include "diagnose/residual_analysis.h"
#include "support/test_signals.h"

namespace lpvid {
namespace {

/// e(t) = a·e(t−1) + w(t), w white.
Mat<double> ar1(Eigen::Index n, double a, unsigned seed) {
  Mat<double> e = gaussian(n, 1, seed);
  for (Eigen::Index t = 1; t < n; ++t) e(t, 0) += a * e(t - 1, 0);
  return e;
}

TEST(ResidualAnalysis, RmsKnownValues) {
  Mat<double> r(2, 2);
  r << 3, 1, 4, -1;
  const ResidualRms rms = residual_rms(r);
  EXPECT_DOUBLE_EQ(rms.per_output(0), std::sqrt(12.5));
  EXPECT_DOUBLE_EQ(rms.per_output(1), 1.0);
  EXPECT_DOUBLE_EQ(rms.overall, std::sqrt(27.0 / 4));
}

TEST(ResidualAnalysis, DefaultLagsAndBand) {
  EXPECT_EQ(residual_max_lag(1000), 25);
  EXPECT_EQ(residual_max_lag(40), 10);
  EXPECT_EQ(residual_max_lag(3), 1);
  ResidualAnalysisOptions o;
  o.max_lag = 7;
  EXPECT_EQ(residual_max_lag(1000, o), 7);
  EXPECT_NEAR(whiteness_band(400, 0.99), 2.575829 / 20, 1e-7);
  EXPECT_NEAR(whiteness_band(400, 0.95), 1.959964 / 20, 1e-7);
}

TEST(ResidualAnalysis, WhiteNoiseIsWhite) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Mat<double> r = gaussian(2000, 2, seed);
    const WhitenessResult w = residual_whiteness(r);
    EXPECT_EQ(w.max_lag, 25);
    EXPECT_TRUE(w.white) << "seed " << seed;
    ASSERT_EQ(w.outputs.size(), 2u);
    for (const AutocorrelationTest& t : w.outputs) {
      EXPECT_DOUBLE_EQ(t.rho[0], 1.0);
      EXPECT_LE(t.outside_99, 2) << "seed " << seed;  // expected 25 · 1 % = 0.25
      EXPECT_LE(t.outside_95, 5) << "seed " << seed;  // expected 1.25
      EXPECT_LT(t.q, t.q_threshold);
      EXPECT_NEAR(t.q_threshold, 44.314, 1e-3);  // χ²_0.99(25)
    }
  }
}

TEST(ResidualAnalysis, Ar1IsNotWhite) {
  const Mat<double> r = ar1(2000, 0.8, 7);
  const WhitenessResult w = residual_whiteness(r);
  EXPECT_FALSE(w.white);
  EXPECT_FALSE(w.outputs[0].white);
  EXPECT_NEAR(w.outputs[0].rho[1], 0.8, 0.04);
  EXPECT_NEAR(w.outputs[0].rho[2], 0.64, 0.06);
  EXPECT_GE(w.outputs[0].outside_99, 5);
  EXPECT_GT(w.outputs[0].q, 10 * w.outputs[0].q_threshold);
}

TEST(ResidualAnalysis, OffsetShowsAsCorrelation) {
  // Not mean-corrected (Ljung §16.6): a missing output offset is not white.
  Mat<double> r = gaussian(1000, 1, 4);
  r.array() += 1.0;
  EXPECT_FALSE(residual_whiteness(r).white);
}

TEST(ResidualAnalysis, ZeroResidualIsWhite) {
  const WhitenessResult w = residual_whiteness(Mat<double>::Zero(50, 1));
  EXPECT_TRUE(w.white);
  EXPECT_EQ(w.outputs[0].q, 0.0);
  EXPECT_EQ(candidate_shares(Mat<double>::Zero(50, 1), {{"c", gaussian(50, 1, 1)}})[0].share, 0.0);
}

TEST(ResidualAnalysis, CrossCorrelationFindsTheDelay) {
  const Eigen::Index n = 1500;
  const Mat<double> u = gaussian(n, 2, 11);
  Mat<double> r = 0.3 * gaussian(n, 1, 12);
  for (Eigen::Index t = 3; t < n; ++t) r(t, 0) += u(t - 3, 1);  // r(t) ← u2(t − 3)
  const CrossCorrelationResult c = residual_input_correlation(r, u);
  ASSERT_EQ(c.pairs.size(), 2u);
  EXPECT_EQ(c.pairs[1].output, 0);
  EXPECT_EQ(c.pairs[1].input, 1);
  EXPECT_EQ(c.pairs[1].max_lag_at, 3);
  EXPECT_TRUE(c.pairs[1].significant);
  EXPECT_NEAR(c.pairs[1].max_abs, 1 / std::sqrt(1.09), 0.04);  // 1/√(1 + 0.3²)
  EXPECT_GE(c.pairs[1].outside_99, 1);
  EXPECT_LE(c.pairs[1].outside_99, 3);  // lag 3, and by chance (1 % a lag) maybe another
  EXPECT_LE(c.pairs[0].outside_99, 2);  // u1 plays no part
  EXPECT_LT(c.pairs[0].max_abs, 0.1);
}

TEST(ResidualAnalysis, ShareOfAScaledCandidatePlusNoise) {
  const Eigen::Index n = 3000;
  const Mat<double> c = gaussian(n, 1, 21), e = 0.5 * gaussian(n, 1, 22);
  for (double a : {0.2, 1.0, 3.0}) {
    const Mat<double> r = a * c + e;
    const double expected = a * a * c.squaredNorm() / (a * a * c.squaredNorm() + e.squaredNorm());
    const CandidateShare s = candidate_shares(r, {{"c", c}})[0];
    EXPECT_EQ(s.name, "c");
    EXPECT_EQ(s.rank, 1);
    EXPECT_NEAR(s.share, expected, 0.02) << "a " << a;
    EXPECT_NEAR(s.correlation(0, 0) * s.correlation(0, 0), s.share, 1e-12);  // one column: ρ² = share
  }
}

TEST(ResidualAnalysis, OrthogonalResidualHasNoShare) {
  const Mat<double> c = gaussian(500, 3, 31);
  Mat<double> r = gaussian(500, 2, 32);
  r -= c * c.colPivHouseholderQr().solve(r);  // remove the part in span(c)
  const CandidateShare s = candidate_shares(r, {{"c", c}})[0];
  EXPECT_LT(s.share, 1e-12);
  EXPECT_LT(s.max_abs_correlation, 1e-10);
  EXPECT_EQ(s.rank, 3);
}

TEST(ResidualAnalysis, RankDeficientCandidate) {
  const Mat<double> c = gaussian(400, 1, 41);
  const Mat<double> r = 2 * c + gaussian(400, 1, 42);
  Mat<double> dup(400, 3);
  dup << c, -2e6 * c, Mat<double>::Zero(400, 1);
  const std::vector<CandidateShare> s = candidate_shares(r, {{"single", c}, {"dup", dup}});
  EXPECT_EQ(s[1].rank, 1);
  EXPECT_NEAR(s[1].share, s[0].share, 1e-12);
  EXPECT_EQ(s[1].correlation.cols(), 3);
  EXPECT_EQ(s[1].correlation(0, 2), 0.0);
}

// Properties of the share: in [0, 1]; invariant to scaling r and the
// candidate; never smaller with more columns; 1 for a candidate that
// contains r.
RC_GTEST_PROP(ResidualAnalysis, ShareProperties, ()) {
  const int n = *rc::gen::inRange(5, 60);
  const int ny = *rc::gen::inRange(1, 3);
  const int m = *rc::gen::inRange(1, 4);
  const unsigned seed = *rc::gen::arbitrary<unsigned>();
  const Mat<double> r = gaussian(n, ny, seed), c = gaussian(n, m + 1, seed + 1);
  const double a = *rc::gen::element(-3.0, 0.01, 250.0), b = *rc::gen::element(1e-3, -1.0, 1e4);
  const std::vector<CandidateShare> s =
      candidate_shares(r, {{"part", c.leftCols(m)}, {"all", c}, {"scaled", b * c.leftCols(m)}, {"r", r}});
  const double part = s[0].share;
  RC_ASSERT(part >= 0.0 && part <= 1.0);
  RC_ASSERT(s[1].share >= part - 1e-12);
  RC_ASSERT(std::abs(s[2].share - part) < 1e-9);
  RC_ASSERT(std::abs(candidate_shares(a * r, {{"part", c.leftCols(m)}})[0].share - part) < 1e-9);
  RC_ASSERT(s[3].share > 1 - 1e-9);
  for (Eigen::Index i = 0; i < ny; ++i) RC_ASSERT(s[0].share_per_output(i) >= 0.0 && s[0].share_per_output(i) <= 1.0);
}

TEST(ResidualAnalysis, AnalyseCombinesEverything) {
  const Mat<double> r = ar1(300, 0.5, 51), u = gaussian(300, 1, 52);
  const ResidualAnalysis a = analyse_residual(r, u, {{"u", u}});
  EXPECT_EQ(a.rms.per_output.size(), 1);
  EXPECT_FALSE(a.whiteness.white);
  EXPECT_EQ(a.input_correlation.pairs.size(), 1u);
  EXPECT_EQ(a.candidates.size(), 1u);
  const ResidualAnalysis no_u = analyse_residual(r, Mat<double>(300, 0), {});
  EXPECT_TRUE(no_u.input_correlation.pairs.empty());
  EXPECT_EQ(no_u.input_correlation.max_lag, a.whiteness.max_lag);
}

TEST(ResidualAnalysis, BadInputThrows) {
  const Mat<double> ok = gaussian(20, 1, 61);
  Mat<double> nan = ok, inf = ok;
  nan(5, 0) = std::numeric_limits<double>::quiet_NaN();
  inf(3, 0) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(residual_rms(Mat<double>()), InputError);
  EXPECT_THROW(residual_rms(nan), InputError);
  EXPECT_THROW(residual_whiteness(inf), InputError);
  EXPECT_THROW(residual_whiteness(Mat<double>::Ones(1, 1)), InputError);
  EXPECT_THROW(residual_input_correlation(ok, gaussian(19, 1, 1)), InputError);
  EXPECT_THROW(residual_input_correlation(ok, nan), InputError);
  EXPECT_THROW(candidate_shares(ok, {{"short", gaussian(19, 1, 1)}}), InputError);
  EXPECT_THROW(candidate_shares(ok, {{"empty", Mat<double>(20, 0)}}), InputError);
  EXPECT_THROW(candidate_shares(ok, {{"nan", nan}}), InputError);
  EXPECT_THROW(normalised_correlation(ok.col(0), gaussian(19, 1, 1).col(0), 2), InputError);
  ResidualAnalysisOptions o;
  o.max_lag = 20;
  EXPECT_THROW(residual_whiteness(ok, o), std::invalid_argument);
  o.max_lag = -2;
  EXPECT_THROW(residual_whiteness(ok, o), std::invalid_argument);
  o = {};
  o.level = 1.0;
  EXPECT_THROW(residual_whiteness(ok, o), std::invalid_argument);
  try {
    candidate_shares(ok, {{"sat(u)", nan}});
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sat(u)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("sample 5"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lpvid
