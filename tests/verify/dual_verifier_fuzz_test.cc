// The verifier on hostile dual certificates, both forms ("dual_delta_path",
// the compact recipe, and "dual_delta", the dense Y1). Genuine lower-bound
// certificates of the true Example-1 model on its noise-free data are made
// once; then
//  - a fixed number of generated edits (a fixed seed, so a fixed amount of
//    work: number fields replaced by hostile values, rows dropped or
//    repeated, bytes changed) must each end in a documented exit code of
//    `lpvid-verify certificate` (0, 1, 2 or 8), never a crash, a signal or
//    another exception; these run in the ASan/UBSan tree too
//    (scripts/test.sh --sanitize);
//  - the cases measured on the issue: u_floor = 1e292 used to kill the
//    verifier with SIGFPE (its double overflowed to −∞): now NOT_PSD from
//    a diagonal entry below the floor (exit 1); a number beyond the range of
//    a double is malformed input naming its field (exit 2); a compact point
//    above --max-dual-order and an exact elimination above --max-exact-work
//    are refused with exit 8 before the work starts, and decided when the
//    limit is raised.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

#include "certify/certificate_files.h"
#include "certify/certify.h"
#include "identify/class_interval.h"
#include "core/exit_codes.h"
#include "data/csv_reader.h"
#include "data/data_reference.h"
#include "data/experiment_builder.h"
#include "model/model_file.h"
#include "support/fixtures.h"
#include "support/scratch_dir.h"
#include "verify/certificate/certificate_check.h"
#include "verify/psd/psd_command.h"
#include "verify/psd/work_limits.h"
#include "solvers/solver_factory.h"

namespace lpvid {
namespace {

/// Genuine lower-bound certificates of both dual forms, next to their data (made once).
struct GenuineDuals {
  gen::ScratchDir dir{"dual_fuzz"};
  std::string compact, dense, klass;
  GenuineDuals() {
    const std::string data = dir.file("data.csv");
    {
      std::ifstream in(gen::kExample1Fixtures + "noise_free_n40.csv", std::ios::binary);
      std::ofstream(data, std::ios::binary) << in.rdbuf();
    }
    const LpvModel<Rational> model = read_model_file<Rational>(gen::kExample1Fixtures + "true_model.json");
    const Experiment<Rational> exp = make_experiment<Rational>(read_table(data), model.columns);
    auto solver = make_solver("csdp");
    compact = lower_certificate(model, exp, data, false, *solver);
    dense = lower_certificate(model, exp, data, true, *solver);
    klass = class_certificate(data, *solver);
  }
  /// A class lower bound (docs/class_lower_bound.md) of the initial Example-1
  /// model with the correction basis 1, rho1, rho2: three leaves of a box.
  std::string class_certificate(const std::string& data, SdpSolver& solver) {
    LpvModel<Rational> model = read_model_file<Rational>(gen::kExample1Fixtures + "initial_model.json");
    model.correction.basis.resize(3);
    model.correction.A.resize(3);
    model.correction.B.resize(3);
    const LpvModel<double> model_d = convert_model<double>(model);
    const Experiment<Rational> exp = make_experiment<Rational>(read_table(data), model.columns);
    const Experiment<double> exp_d = make_experiment<double>(read_table(data), model_d.columns);
    IdentifyOptions io;
    io.objective.kind = BoundObjective::Kind::kWeighted;
    io.method = IdentifyMethod::kAlternating;
    CertifyOptions co;
    co.objective = io.objective;
    co.records = {read_data_table(data).reference};
    const Problem problem{model, model_d, exp, exp_d};
    IdentifiedModel id = identify_and_certify(problem, io, co, solver);
    ClassBoundOptions o;
    o.max_leaves = 3;
    const ClassInterval ci = class_interval(id, problem, co, o, solver);
    if (!ci.bound.certified()) throw std::runtime_error("no class certificate: " + ci.bound.reason);
    const std::string path = dir.file("class.json");
    write_certificate_at(*ci.bound.certificate, path);
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::string lower_certificate(const LpvModel<Rational>& model, const Experiment<Rational>& exp, const std::string& data,
                                bool dense_dual, SdpSolver& solver) {
    CertifyOptions o;
    o.objective.kind = BoundObjective::Kind::kMinDmax;
    o.objective.delta = 0.1;
    o.records = {read_data_table(data).reference};
    o.dense_dual = dense_dual;
    const CertifiedBounds b = certify_fixed_model(model, exp, o, solver);
    if (!b.lower.verified()) throw std::runtime_error("no verified lower end: " + b.lower.reason);
    const std::string path = dir.file(dense_dual ? "dense.json" : "compact.json");
    write_certificates(b, path);
    std::ifstream in(lower_certificate_path(path), std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  /// `lpvid-verify certificate` on `text` written next to the data, with the
  /// program's default work limits (the edits: a smaller exact-work limit, so
  /// that the sanitizer tree's run stays short; exit 8 is a documented outcome).
  int check(const std::string& text, std::string* out_text = nullptr, double exact_work = kDefaultMaxExactWork) const {
    const std::string path = dir.file("t.json");
    std::ofstream(path, std::ios::binary) << text;
    std::ostringstream out, err;
    const VerifyWorkLimits saved = verify_work_limits();
    verify_work_limits() = {kDefaultMaxDualOrder, exact_work};
    const int code = run_certificate_command(path, out, err);
    verify_work_limits() = saved;
    if (out_text) *out_text = out.str() + err.str();
    return code;
  }
};

const GenuineDuals& genuine_duals() {
  static const GenuineDuals g;
  return g;
}

/// The text with the value of `"key": …` replaced by `value` (a JSON value's text).
std::string with_dual_value(const std::string& text, const std::string& key, const std::string& value) {
  const size_t k = text.find("\"" + key + "\":");
  if (k == std::string::npos) throw std::runtime_error("no key " + key);
  const size_t start = text.find_first_not_of(' ', k + key.size() + 3);
  size_t end = start;
  if (text[start] == '"') end = text.find('"', start + 1) + 1;
  else
    while (end < text.size() && text[end] != ',' && text[end] != '\n' && text[end] != '}') ++end;
  return text.substr(0, start) + value + text.substr(end);
}

TEST(DualCertificateVerifierFuzz, TheGenuineCertificatesOfBothFormsHold) {
  std::string out;
  EXPECT_NE(genuine_duals().compact.find("\"dual_delta_path\""), std::string::npos);
  EXPECT_NE(genuine_duals().dense.find("\"dual_delta\""), std::string::npos);
  EXPECT_EQ(genuine_duals().check(genuine_duals().compact, &out), kExitOk) << out;
  EXPECT_EQ(genuine_duals().check(genuine_duals().dense, &out), kExitOk) << out;
}

TEST(DualCertificateVerifierFuzz, AFloorOfOneE292IsNotPsdInsteadOfAFloatingPointException) {
  std::string out;
  EXPECT_EQ(genuine_duals().check(with_dual_value(genuine_duals().compact, "u_floor", "\"1e292\""), &out), kExitInvalidated) << out;
  EXPECT_NE(out.find("below u_floor"), std::string::npos) << out;
  EXPECT_EQ(genuine_duals().check(with_dual_value(genuine_duals().compact, "u_floor", "\"-1e292\""), &out), kExitBadInput) << out;
}

TEST(DualCertificateVerifierFuzz, NumbersBeyondTheRangeOfADoubleAreMalformedWithTheirField) {
  const struct {
    const std::string* text;
    const char* key;
    const char* field;
  } cases[] = {{&genuine_duals().compact, "u_floor", "dual.u_floor"}, {&genuine_duals().compact, "mu", "dual.mu"},
               {&genuine_duals().compact, "sigma", "dual.sigma"},    {&genuine_duals().dense, "sigma", "dual.sigma"},
               {&genuine_duals().dense, "delta2", "delta2"},          {&genuine_duals().compact, "lower_bound", "lower_bound"}};
  for (const auto& c : cases)
    for (const std::string& value :
         {std::string("\"1e309\""), std::string("\"-2e308\""), std::string("\"1e4000\""), "\"1" + std::string(400, '0') + "/3\""}) {
      std::string out;
      EXPECT_EQ(genuine_duals().check(with_dual_value(*c.text, c.key, value), &out), kExitBadInput) << c.key << " = " << value << ": " << out;
      EXPECT_NE(out.find(c.field), std::string::npos) << out;
    }
  // At the edge: DBL_MAX itself and tiny numbers are numbers a certificate may carry (judged, not refused).
  std::string out;
  const int code = genuine_duals().check(with_dual_value(genuine_duals().compact, "u_floor", "\"1.7976931348623157e308\""), &out);
  EXPECT_EQ(code, kExitInvalidated) << out;
}

/// One generated edit of `text` (its number fields, rows or bytes).
std::string edited_dual(const std::string& text, std::mt19937_64& rng) {
  static const std::vector<std::string> hostile = {
      "\"1e292\"", "\"-1e292\"", "\"1e308\"", "\"1.8e308\"", "\"1e309\"", "\"4.9e-324\"", "\"1e-400\"", "\"0\"",
      "\"-0\"", "\"1/3\"", "\"-1\"", "\"1e4001\"", "\"nan\"", "\"inf\"", "\"2\"", "0", "1", "-1", "4000", "-4001",
      "2147483648", "\"123456789012345678901234567890\"", "\"0.5\"", "[]", "[[1]]", "null", "\"\""};
  const size_t info = text.find("\"info\"");
  std::string s = text.substr(0, info), tail = text.substr(info);
  std::uniform_int_distribution<size_t> pos(0, s.size() - 1);
  switch (rng() % 4) {
    case 0:
    case 1: {  // a value after some "key": or inside an array: a hostile number
      size_t p = pos(rng);
      while (p < s.size() && !(s[p] == '"' && p > 0 && (s[p - 1] == ' ' || s[p - 1] == '['))) ++p;
      if (p >= s.size()) break;
      const size_t end = s.find_first_of(",]\n", p + 1);
      s.replace(p, end - p, hostile[rng() % hostile.size()]);
      break;
    }
    case 2: {  // a matrix row dropped or repeated
      size_t p = s.find("\n", pos(rng));
      if (p == std::string::npos) break;
      const size_t q = s.find("\n", p + 1);
      if (q == std::string::npos) break;
      const std::string line = s.substr(p, q - p);
      if (rng() % 2) s.erase(p, q - p);
      else s.insert(p, line);
      break;
    }
    default: {  // bytes
      static const std::string bytes = "0123456789-+.eE/\"[]{}:, \n";
      for (int k = 1 + static_cast<int>(rng() % 3); k > 0; --k) s[pos(rng)] = bytes[rng() % bytes.size()];
    }
  }
  return s + tail;
}

/// A fixed number of edits per form (fixed seed): each ends in 0, 1, 2 or 8.
void fuzz_dual(const std::string& text, std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  for (int i = 0; i < count; ++i) {
    const std::string bad = edited_dual(text, rng);
    std::string out;
    const int code = genuine_duals().check(bad, &out, 1e8);
    ASSERT_TRUE(code == kExitOk || code == kExitInvalidated || code == kExitBadInput || code == kExitWorkLimit)
        << "edit " << i << " (seed " << seed << "): exit " << code << ": " << out.substr(0, 400);
  }
}

TEST(DualCertificateVerifierFuzz, EditsOfTheCompactFormEndInADocumentedExitCode) { fuzz_dual(genuine_duals().compact, 33, 300); }

TEST(DualCertificateVerifierFuzz, EditsOfTheDenseFormEndInADocumentedExitCode) { fuzz_dual(genuine_duals().dense, 34, 300); }

TEST(DualCertificateVerifierFuzz, TheGenuineClassCertificateHoldsAndItsEditsEndInADocumentedExitCode) {
  std::string out;
  ASSERT_EQ(genuine_duals().check(genuine_duals().klass, &out), kExitOk) << out;
  fuzz_dual(genuine_duals().klass, 35, 150);
}

/// `lpvid-verify args` (the program); its exit code, output in *out.
int run_verify_program(const std::string& args, std::string* out) {
  const std::string program = std::string(LPVID_BINARY_DIR) + "/lpvid-verify";
  const std::string log = genuine_duals().dir.file("run.txt");
  const int s = std::system((program + " " + args + " >" + log + " 2>&1").c_str());
  std::ifstream in(log);
  *out = std::string(std::istreambuf_iterator<char>(in), {});
  return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
}

TEST(DualCertificateVerifierLimits, ACompactPointAboveTheOrderLimitIsNotCheckedUntilTheLimitIsRaised) {
  if (!std::ifstream(std::string(LPVID_BINARY_DIR) + "/lpvid-verify")) GTEST_SKIP() << "lpvid-verify not built";
  const std::string path = genuine_duals().dir.file("order.json");
  std::ofstream(path) << genuine_duals().compact;
  std::string out;
  // Example 1 (n = 40, one leading zero of z): horizon 39, ny = 2, so U has order 78.
  EXPECT_EQ(run_verify_program("certificate " + path + " --max-dual-order 77", &out), kExitWorkLimit) << out;
  EXPECT_NE(out.find("--max-dual-order"), std::string::npos) << out;
  EXPECT_EQ(run_verify_program("certificate " + path + " --max-dual-order 78", &out), kExitOk) << out;
  EXPECT_EQ(run_verify_program("certificate " + path, &out), kExitOk) << out;
}

TEST(DualCertificateVerifierLimits, AnExactEliminationAboveTheWorkLimitIsNotStartedUntilTheLimitIsRaised) {
  if (!std::ifstream(std::string(LPVID_BINARY_DIR) + "/lpvid-verify")) GTEST_SKIP() << "lpvid-verify not built";
  // v·vᵀ (rank one, PSD and singular): no filter proves it, the exact path decides PSD.
  const std::string path = genuine_duals().dir.file("rank1.txt");
  {
    std::ofstream m(path);
    for (int i = 1; i <= 30; ++i) {
      for (int j = 1; j <= 30; ++j) m << (j > 1 ? " " : "") << i * j;
      m << "\n";
    }
  }
  std::string out;
  EXPECT_EQ(run_verify_program("psd " + path + " --max-exact-work 1000", &out), kExitWorkLimit) << out;
  EXPECT_NE(out.find("--max-exact-work"), std::string::npos) << out;
  EXPECT_EQ(run_verify_program("psd " + path, &out), kExitOk) << out;
  EXPECT_EQ(out.rfind("PSD", 0), 0u) << out;
}

TEST(DualCertificateVerifierLimits, TheLibraryRunsUnlimitedAndALimitNamesItsOption) {
  EXPECT_EQ(verify_work_limits().max_dual_order, 0);
  EXPECT_EQ(verify_work_limits().max_exact_work, 0);
  require_exact_work(100000, 1e9);  // unlimited: no throw
  require_dual_order(1000000);
  const VerifyWorkLimits saved = verify_work_limits();
  verify_work_limits() = {10, 1000};
  std::string why;
  try {
    require_exact_work(30, 300);  // 11 primes × 30³/3 = 99000 operations
  } catch (const WorkLimitError& e) {
    why = e.what();
  }
  EXPECT_THROW(require_dual_order(11), WorkLimitError);
  verify_work_limits() = saved;
  EXPECT_NE(why.find("--max-exact-work"), std::string::npos) << why;
}

}  // namespace
}  // namespace lpvid
