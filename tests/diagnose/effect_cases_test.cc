// What `diagnose` must achieve: on every generated case the right effect
// kind is ranked first and chosen, and the validation RMS falls by at least
// 30 %; the control case answers `none`. Known answers by construction
// (examples/effect_cases.h: the data come from the declared LPV system plus
// exactly one effect). Also: the certificate of a model with static blocks
// verifies exactly and a changed saturation level is rejected.
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "diagnose/effect_ranking.h"
#include "diagnose/window_bounds.h"
#include "examples/effect_cases.h"
#include "fit/output_error_fit.h"
#include "certify/certify.h"
#include "model/model_file.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "support/gen_identify.h"
#include "verify/certificate/certificate_check.h"

namespace lpvid {
namespace {

using gen::ScratchDir;
using gen::write_experiment_csv;
using gen::read_experiment;

Experiment<double> to_double(const Experiment<Rational>& e) { return nearest_double(e); }

class EffectCaseTest : public ::testing::TestWithParam<std::tuple<std::string, int>> {};

TEST_P(EffectCaseTest, RightKindFirstAndValidationRmsFalls) {
  const auto [kind, seed] = GetParam();
  const EffectCase c = make_effect_case(kind, 300, static_cast<uint64_t>(seed), 0.02);
  const LpvModel<double> plain = convert_model<double>(c.declared);
  const LpvModel<double> declared = with_input_scheduling(plain);
  const Experiment<double> est = with_input_scheduling(to_double(c.estimation), plain, declared);
  const Experiment<double> val = with_input_scheduling(to_double(c.validation), plain, declared);
  RankingOptions o;
  o.max_effects = 2;
  const RankingResult r = rank_effects(declared, est, val, o);
  ASSERT_FALSE(r.rounds.empty());
  const RankingRound& first = r.rounds.front();
  if (kind == "none") {
    EXPECT_LT(first.chosen, 0) << "best: " << first.ranked.front().label << " val "
                               << first.ranked.front().rms_validation << " vs " << first.reference_validation;
    EXPECT_TRUE(r.chosen.empty());
    EXPECT_NEAR(r.after_validation, r.before_validation, 1e-12);
    return;
  }
  ASSERT_EQ(first.chosen, 0) << kind << ": nothing chosen";
  EXPECT_EQ(first.ranked.front().kind, reported_effect_kind(kind)) << "ranked first: " << first.ranked.front().label;
  ASSERT_FALSE(r.chosen.empty());
  EXPECT_EQ(r.chosen.front().kind, reported_effect_kind(kind));
  EXPECT_LE(r.after_validation, 0.7 * r.before_validation)
      << kind << ": validation RMS " << r.before_validation << " -> " << r.after_validation;
  // with the effect found, what is left is the noise (std 0.02): the model
  // after on the validation record with its polynomial maps read as
  // polynomials everywhere, as the truth's are (beyond the range a map was
  // fitted on the model continues along the tangent, model/static_blocks.h,
  // which a validation record that leaves that range pays for)
  LpvModel<double> everywhere = r.after;
  everywhere.statics.input.range.clear();
  everywhere.statics.output.range.clear();
  EXPECT_LT(validation_rms(everywhere, val, o.init_samples), 0.03) << kind;
  EXPECT_LT(r.after_validation, 0.1) << kind;
  // the reported parameters of every chosen effect are those of the final model
  for (const ScoredCandidate& c : r.chosen) {
    const auto& p = c.parameters;
    for (const char* side : {"input_map", "output_map"}) {
      if (!p.contains(side)) continue;
      const StaticMap<double>& g = std::string(side) == "input_map" ? r.after.statics.input : r.after.statics.output;
      if (p[side].contains("coefficients")) {
        EXPECT_EQ(p[side]["coefficients"].get<std::vector<double>>(), g.coefficients) << c.label;
      }
      if (p[side].contains("lower")) {
        EXPECT_EQ(p[side]["lower"].get<double>(), g.lower) << c.label;
        EXPECT_EQ(p[side]["upper"].get<double>(), g.upper) << c.label;
      }
    }
    if (p.contains("delay_samples")) {
      EXPECT_EQ(p["delay_samples"].get<int>(), r.after.statics.input_delay);
    }
    for (const auto& [key, pm] : {std::pair<const char*, const ParamMatrix<double>*>{"C", &r.after.C}, {"D", &r.after.D},
                                  {"B", &r.after.B}, {"A", &r.after.A}}) {
      if (!p.contains(key)) continue;
      bool found = false;
      for (const auto& t : pm->terms)
        if (t.basis.text(r.after.scheduling) == p["basis"].get<std::string>()) {
          found = true;
          EXPECT_EQ(p[key][0][0].get<double>(), t.value(0, 0)) << c.label << " " << key;
        }
      EXPECT_TRUE(found) << c.label << ": " << key << " term " << p["basis"] << " not in the final model";
    }
  }
}

// three input/noise realisations per kind (seeds fixed so that a failure is reproducible)
INSTANTIATE_TEST_SUITE_P(Generated, EffectCaseTest,
                         ::testing::Combine(::testing::ValuesIn(effect_case_kinds()), ::testing::Values(7, 11, 23)),
                         [](const auto& info) {
                           return std::get<0>(info.param) + "_seed" + std::to_string(std::get<1>(info.param));
                         });

TEST(EffectCases, UnknownKindIsAnInputError) {
  EXPECT_THROW(make_effect_case("gravity", 100, 1, 0.02), InputError);
  EXPECT_THROW(make_effect_case("none", 5, 1, 0.02), InputError);
}

/// The truth of a generated case, certified on estimation rows [begin, end)
/// through the data file as the CLI does (the certificate is written in `dir`).
struct CertifiedTruth {
  WindowBounds window;
  std::string certificate;
};

CertifiedTruth certify_truth(const EffectCase& c, const ScratchDir& dir, Eigen::Index begin, Eigen::Index end) {
  const std::string data = dir.file("est.csv");
  write_experiment_csv(data, c.declared, c.estimation);
  const LpvModel<double> truth = convert_model<double>(c.truth);
  const Experiment<Rational> est_q = read_experiment<Rational>(data, c.truth);
  const Experiment<double> est_d = read_experiment<double>(data, truth);
  CertifyOptions co;
  co.records = {read_data_table(data).reference};
  co.max_taps = 16;
  auto solver = make_solver("csdp");
  const WindowBounds w = certify_window(truth, ExperimentViews{est_q, est_d}, begin, end, co, *solver);
  return {w, write_certificates(w.bounds, dir.file("cert.json")).certificate};
}

/// The after-model of the input_saturation case, certified on a window: the
/// verifier recomputes sat(u) exactly; moving the saturation level in the
/// certificate text must make it invalid.
TEST(EffectCases, StaticBlockCertificateVerifiesAndTamperingIsRejected) {
  const EffectCase c = make_effect_case("input_saturation", 200, 3, 0.02);
  ScratchDir dir("effect-cert");
  const CertifiedTruth ct = certify_truth(c, dir, 0, 120);
  const WindowBounds& w = ct.window;
  ASSERT_TRUE(w.bounds.verified()) << w.bounds.reason;
  EXPECT_TRUE(check_certificate_file(ct.certificate).holds);
  // the noise is the only misfit: dmax near the noise std
  EXPECT_LT(w.bounds.dmax, 0.03);

  std::ifstream in(ct.certificate);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const size_t key = text.find("\"upper\"");
  ASSERT_NE(key, std::string::npos) << "saturation level not found in the certificate";
  const size_t open = text.find('"', key + 7), close = text.find('"', open + 1);
  ASSERT_EQ(text.substr(open + 1, close - open - 1), "0.6");
  text.replace(open + 1, close - open - 1, "0.5");
  const std::string tampered = dir.file("tampered.json");
  std::ofstream(tampered) << text;
  const CertificateVerdict v = check_certificate_file(tampered);
  EXPECT_FALSE(v.holds);
}

/// A piecewise-linear sensor (model/static_blocks.h): the verifier evaluates
/// the map exactly from the certificate's knots and values; the truth
/// certifies with d_max near the noise, a moved value is rejected.
TEST(EffectCases, PiecewiseLinearCertificateVerifiesAndTamperingIsRejected) {
  const EffectCase c = make_effect_case("output_piecewise_linear", 200, 3, 0.02);
  ScratchDir dir("pwl-cert");
  const CertifiedTruth ct = certify_truth(c, dir, 0, 120);
  ASSERT_TRUE(ct.window.bounds.verified()) << ct.window.bounds.reason;
  ASSERT_TRUE(check_certificate_file(ct.certificate).holds);
  EXPECT_LT(ct.window.bounds.dmax, 0.03);
  std::ifstream in(ct.certificate);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const size_t values = text.find("\"values\"");
  ASSERT_NE(values, std::string::npos) << "piecewise-linear values not found in the certificate";
  // the last value (2, the sensor's level at the last knot) becomes 2.1
  const size_t close = text.find(']', values), last = text.rfind(',', close);
  ASSERT_NE(close, std::string::npos);
  ASSERT_NE(last, std::string::npos);
  text.replace(last + 1, close - last - 1, "\"2.1\"");
  const std::string tampered = dir.file("tampered.json");
  std::ofstream(tampered) << text;
  EXPECT_FALSE(check_certificate_file(tampered).holds);
}

/// A model scheduled on its own state ("@x1", model/state_scheduling.h):
/// the certifier and the verifier both recompute ρ from the certified model
/// in exact arithmetic. The truth certifies with d_max near the noise; a
/// changed x1² coefficient or a changed x0 (which moves the whole ρ
/// trajectory) must be rejected, and so must the same model with a plain
/// data column in place of "@x1".
TEST(EffectCases, StateScheduledCertificateVerifiesAndTamperingIsRejected) {
  const EffectCase c = make_effect_case("state_feedback", 160, 3, 0.02);
  ScratchDir dir("state-cert");
  const CertifiedTruth ct = certify_truth(c, dir, 40, 140);
  const WindowBounds& w = ct.window;
  ASSERT_TRUE(w.bounds.verified()) << w.bounds.reason;
  ASSERT_TRUE(check_certificate_file(ct.certificate).holds);
  EXPECT_LT(w.bounds.dmax, 0.03);

  std::ifstream in(ct.certificate);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  const auto tampered_verdict = [&](const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    std::string t = text;
    if (at != std::string::npos) t.replace(at, from.size(), to);
    const std::string path = dir.file("tampered.json");
    std::ofstream(path) << t;
    return check_certificate_file(path);
  };
  EXPECT_FALSE(tampered_verdict("\"-0.006\"", "\"-0.0061\"").holds) << "x1^2 coefficient";
  EXPECT_FALSE(tampered_verdict("\"@x1\"", "\"rho1\"").holds) << "scheduling column";
  const size_t x0 = text.find("\"x0\"");
  ASSERT_NE(x0, std::string::npos);
  const size_t open = text.find('"', text.find('[', x0)), close = text.find('"', open + 1);
  const std::string first = text.substr(open, close - open + 1);
  EXPECT_FALSE(tampered_verdict(text.substr(x0, close + 1 - x0),
                                text.substr(x0, open - x0) + "\"" + (first == "\"1\"" ? "2" : "1") + "\"")
                   .holds)
      << "x0(1) " << first;
}

}  // namespace
}  // namespace lpvid
