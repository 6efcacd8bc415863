// The random cases of examples/random_case.h: reproducible from a seed
// (SeededDraw), and, whatever the options, a truth that satisfies
// Theorem 2.1 at the generating (δ, d_max) — checked by the library's exact
// certificate path (certify_with_taps with the generating taps, verified
// again from the file), not by the generator's own double arithmetic.
// The options beyond the historical distribution: leading zero inputs
// (docs/design.md §7.3), a delayed Δ, static blocks (model/static_blocks.h).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <type_traits>

#include "core/number_text.h"
#include "core/sha256.h"
#include "examples/random_case.h"
#include "certify/certify.h"
#include "model/model_file.h"
#include "model/simulate.h"
#include "support/gen_identify.h"
#include "support/rapidcheck_draw.h"
#include "toeplitz/fir.h"
#include "verify/certificate/certificate_check.h"

namespace lpvid {
namespace {

using namespace gen;

template <typename T>
std::string matrix_text(const Mat<T>& m) {
  std::string s = std::to_string(m.rows()) + "x" + std::to_string(m.cols()) + ":";
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      if constexpr (std::is_same_v<T, Rational>)
        s += " " + rational_to_text(m(i, j));
      else
        s += " " + double_to_text(m(i, j));
    }
  return s + "\n";
}

/// Everything a case holds, as text: equal texts are identical cases.
std::string case_text(const RandomCase& c) {
  return write_model_json(c.model) + write_model_json(c.truth) + matrix_text(Mat<Rational>(c.theta)) +
         matrix_text(c.exp.u) + matrix_text(c.exp.rho) + matrix_text(c.exp.y) + matrix_text(c.taps) +
         matrix_text(c.d) + double_to_text(c.delta) + " " + double_to_text(c.dmax) + " " +
         std::to_string(c.zero_inputs) + " " + std::to_string(c.delay);
}

RandomCase seeded_case(const RandomCaseOptions& o, uint64_t seed) {
  SeededDraw d(seed);
  return random_case(o, d);
}

/// Every option beyond the historical distribution switched on.
RandomCaseOptions all_options() {
  RandomCaseOptions o;
  o.model.allow_general = true;
  o.model.max_correction = 2;
  o.true_correction = true;
  o.leading_zero_inputs = 3;
  o.max_delay = 2;
  o.static_blocks = true;
  return o;
}

TEST(RandomCase, SameSeedGivesTheIdenticalCase) {
  for (const RandomCaseOptions& o : {RandomCaseOptions{}, all_options()})
    for (uint64_t seed : {0ULL, 1ULL, 42ULL, 0xFFFFFFFFFFFFFFFFULL}) {
      const RandomCase a = seeded_case(o, seed), b = seeded_case(o, seed);
      EXPECT_EQ(case_text(a), case_text(b)) << "seed " << seed;
      EXPECT_EQ(a.delta, b.delta);
      EXPECT_EQ(a.dmax, b.dmax);
    }
}

TEST(RandomCase, DifferentSeedsGiveDifferentCases) {
  for (const RandomCaseOptions& o : {RandomCaseOptions{}, all_options()}) {
    std::set<std::string> texts;
    for (uint64_t seed = 1; seed <= 20; ++seed) texts.insert(case_text(seeded_case(o, seed)));
    EXPECT_EQ(texts.size(), 20u);
  }
}

// The promise of `lpvid generate random --seed S`: the exact parts of a case
// (model, u, ρ, the δ draw) come from integer draws of splitmix64 and are the
// same on every platform. A change here changes every published seed: only
// accept it with a new generator version (or a new model file format: the
// model enters as its file text).
TEST(RandomCase, SeedOneIsPinned) {
  const RandomCase c = seeded_case(RandomCaseOptions{}, 1);
  const std::string exact =
      write_model_json(c.model) + matrix_text(c.exp.u) + matrix_text(c.exp.rho) + double_to_text(c.delta);
  EXPECT_EQ(sha256_hex(exact), "d05ddb279d0c2f5dbc92da42435906c1ec96cd013b27cc2754593a188bf45cb2") << exact;
}

/// The truth certified at exactly the generating (δ, d_max) from the
/// generating taps: no solve, the exact verifier decides (docs/design.md §10).
CertifiedBounds certify_truth(const RandomCase& c, const ScratchDir& dir) {
  const std::string data = dir.file("data.csv");
  write_experiment_csv(data, c.truth, c.exp);
  return written(certify_with_taps(c.truth, read_experiment(data, c.truth), c.taps,
                           certify_options(feasibility_objective(c.delta, c.dmax), data),
                           "generating taps"), dir.file("truth.json"));
}

void assert_truth_certified(const RandomCase& c) {
  ScratchDir dir("random_case");
  const CertifiedBounds b = certify_truth(c, dir);
  RC_LOG() << "n = " << c.exp.n() << ", delta = " << c.delta << ", dmax = " << c.dmax << ", zero inputs "
           << c.zero_inputs << ", delay " << c.delay << ", static " << !c.truth.statics.empty() << ": "
           << b.verified() << " " << b.reason << "\n";
  RC_ASSERT(b.verified());
  RC_ASSERT(check_certificate_file(dir.file("truth.json")).holds);
  // The noise has the stated size (in double; the exact (C2) is the certificate's).
  const double n_ny = static_cast<double>(c.exp.n() * c.truth.ny);
  RC_ASSERT(std::abs(c.d.norm() - 0.9 * c.dmax * std::sqrt(n_ny)) <= 1e-12 * c.dmax * std::sqrt(n_ny));
}

RC_GTEST_PROP(RandomCase, TruthIsCertifiedAtTheGeneratingBounds, ()) {
  RandomCaseOptions o;
  o.model.allow_general = *rc::gen::arbitrary<bool>();
  o.model.max_correction = *rc::gen::inRange(0, 3);
  o.true_correction = *rc::gen::arbitrary<bool>();
  o.zero_delta = *rc::gen::element(false, false, false, true);
  o.leading_zero_inputs = *rc::gen::element(0, 3);
  o.max_delay = *rc::gen::element(0, 2);
  o.static_blocks = *rc::gen::arbitrary<bool>();
  o.min_n = 4;
  o.max_n = 12;
  RapidcheckDraw d;
  const RandomCase c = random_case(o, d);
  RC_CLASSIFY(c.zero_inputs > 0, "leading zero inputs");
  RC_CLASSIFY(c.delay > 0, "delayed delta");
  RC_CLASSIFY(!c.truth.statics.empty(), "static block");
  assert_truth_certified(c);
}

/// u_k = 0 for the drawn leading samples and the first nonzero sample has no
/// zero entry; z (of model and truth) starts with at least as many zero
/// samples and is not identically zero (the gain row of the file comment).
RC_GTEST_PROP(RandomCase, LeadingZeroInputsGiveLeadingZeroZButNotZeroZ, ()) {
  RandomCaseOptions o;
  o.model.allow_general = true;
  o.leading_zero_inputs = 3;
  o.static_blocks = *rc::gen::arbitrary<bool>();
  o.min_n = 3;  // n − 2 < 3 exercises the cap
  o.max_n = 10;
  RapidcheckDraw d;
  const RandomCase c = random_case(o, d);
  const Eigen::Index n = c.exp.n(), m = c.zero_inputs;
  RC_CLASSIFY(m == 3, "three leading zero inputs");
  RC_ASSERT(m >= 0);
  RC_ASSERT(m <= std::min<Eigen::Index>(3, n - 2));
  for (Eigen::Index k = 0; k < m; ++k) RC_ASSERT(c.exp.u.row(k).isZero());
  for (Eigen::Index j = 0; j < c.exp.u.cols(); ++j) RC_ASSERT(c.exp.u(m, j) != Rational(0));
  for (const LpvModel<Rational>* model : {&c.model, &c.truth}) {
    const Eigen::Index zeros = leading_zero_samples(simulate(*model, c.exp).z);
    RC_LOG() << "drawn " << m << ", leading zero samples of z " << zeros << " of " << n << "\n";
    RC_ASSERT(zeros >= m);
    RC_ASSERT(zeros < n);
  }
}

/// With max_delay = j, Δ's first c.delay ≤ j taps are zero and the next one
/// is not: the delay is exactly the drawn one.
RC_GTEST_PROP(RandomCase, DelayedDeltaStartsWithExactlyTheDrawnZeroTaps, ()) {
  RandomCaseOptions o;
  o.max_delay = 2;
  o.min_n = 4;
  o.max_n = 10;
  RapidcheckDraw d;
  const RandomCase c = random_case(o, d);
  RC_CLASSIFY(c.delay == 2, "delay 2");
  RC_ASSERT(c.delay >= 0);
  RC_ASSERT(c.delay <= 2);
  RC_ASSERT(c.taps.rows() > c.delay);
  RC_ASSERT(leading_zero_samples(c.taps) == c.delay);
}

TEST(RandomCase, ZeroDeltaHasOnlyZeroTapsWhateverTheDelay) {
  RandomCaseOptions o;
  o.max_delay = 2;
  o.zero_delta = true;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    const RandomCase c = seeded_case(o, seed);
    EXPECT_TRUE(c.taps.isZero()) << "seed " << seed;
    EXPECT_EQ(c.delta, 0.0);
  }
}

/// The maps drawn are the ones the generator's argument needs: a saturation
/// with lower < 0 < upper (a nonzero input stays nonzero) and an output
/// polynomial v + c₂v² + c₀ with a small c₂.
void expect_static_blocks_as_documented(const StaticBlocks<Rational>& s) {
  EXPECT_EQ(s.input_delay, 0);
  if (s.input.kind == StaticKind::kSaturation) {
    EXPECT_LT(s.input.lower, Rational(0));
    EXPECT_GT(s.input.upper, Rational(0));
  } else {
    EXPECT_TRUE(s.input.is_identity());
  }
  if (s.output.kind == StaticKind::kPolynomial) {
    ASSERT_EQ(s.output.coefficients.size(), 3u);
    EXPECT_EQ(s.output.coefficients[1], Rational(1));
    EXPECT_LE(s.output.coefficients[2] * s.output.coefficients[2], Rational(1) / Rational(100));
  } else {
    EXPECT_TRUE(s.output.is_identity());
  }
}

// The exact simulation handles the blocks as model/static_blocks.h says:
// the LPV part sees g_in(u), and output = g_out(ŷ + Φ).
void expect_simulation_composes_the_blocks(const RandomCase& c) {
  LpvModel<Rational> bare = c.truth;
  bare.statics = StaticBlocks<Rational>{};
  Experiment<Rational> through = c.exp;
  through.u = c.truth.statics.input.apply(c.exp.u);
  const Simulation<Rational> with = simulate(c.truth, c.exp), without = simulate(bare, through);
  EXPECT_TRUE(with.z == without.z);
  EXPECT_TRUE(with.output == c.truth.statics.output.apply(Mat<Rational>(without.yhat + without.offset)));
}

TEST(RandomCase, StaticBlocksAreDrawnAndSimulated) {
  RandomCaseOptions o;
  o.static_blocks = true;
  int saturations = 0, polynomials = 0, none = 0;
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    const RandomCase c = seeded_case(o, seed);
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_static_blocks_as_documented(c.model.statics);
    EXPECT_EQ(write_model_json(c.model), write_model_json(c.truth));  // no correction: the same model
    expect_simulation_composes_the_blocks(c);
    saturations += c.model.statics.input.kind == StaticKind::kSaturation;
    polynomials += c.model.statics.output.kind == StaticKind::kPolynomial;
    none += c.model.statics.empty();
  }
  EXPECT_GT(saturations, 0);
  EXPECT_GT(polynomials, 0);
  EXPECT_GT(none, 0);
  // Off (the default), no block is ever drawn.
  for (uint64_t seed = 1; seed <= 10; ++seed) EXPECT_TRUE(seeded_case(RandomCaseOptions{}, seed).model.statics.empty());
}

RC_GTEST_PROP(RandomCase, CasesWithStaticBlocksAreConsistent, ()) {
  RandomCaseOptions o;
  o.model.allow_general = true;
  o.static_blocks = true;
  o.min_n = 4;
  o.max_n = 12;
  RapidcheckDraw d;
  const RandomCase c = random_case(o, d);
  RC_CLASSIFY(c.truth.statics.input.kind == StaticKind::kSaturation, "input saturation");
  RC_CLASSIFY(c.truth.statics.output.kind == StaticKind::kPolynomial, "output polynomial");
  assert_truth_certified(c);
}

}  // namespace
}  // namespace lpvid
