// The total work budget of one certificate check (--max-total-work,
// --max-records; verify/certificate/work_budget.h): a certificate whose
// declared sizes exceed it is refused with exit 8 before the work starts,
// and a data file named by many records is read and hashed once.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/exit_codes.h"
#include "core/sha256.h"
#include "support/scratch_dir.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/data_file_cache.h"
#include "verify/certificate/work_budget.h"
#include "verify/psd/work_limits.h"
#include "verify/verify_command_line.h"

namespace lpvid {
namespace {

using nlohmann::json;

/// x+ = [0 1; -0.12 0.7] x + [0; 1] u, y = [0.25 0.5] x, additive uncertainty.
json siso_model() {
  return json::parse(R"({"format": "lpvid-model/1", "states": 2, "inputs": 1, "outputs": 1, "scheduling": [],
    "columns": {"u": ["u"], "y": ["y"]},
    "initial": {"A": [{"basis": "1", "value": [[0, 1], ["-0.12", "0.7"]]}],
                "B": [{"basis": "1", "value": [[0], [1]]}],
                "C": [{"basis": "1", "value": [["0.25", "0.5"]]}]},
    "correction": {"basis": ["1"]}, "uncertainty": {"structure": "additive", "weight": "0.1"}})");
}

/// A data file of `rows` rows "u,y" with 4-decimal values; returns its sha256.
std::string write_data(const std::string& path, long rows) {
  std::string text = "u,y\n";
  for (long k = 0; k < rows; ++k)
    text += std::to_string((k * 37) % 19 - 9) + ".25," + std::to_string((k * 11) % 7 - 3) + ".5\n";
  std::ofstream(path) << text;
  return sha256_hex(text);
}

void write_json(const std::string& path, const json& j) { std::ofstream(path) << j.dump(); }

/// A consistent claim, form "delta" (one zero tap on a horizon of `horizon`
/// samples: each record's length), on `reference`: checking it simulates
/// the model exactly over every row.
json primal_certificate(const json& reference, long horizon) {
  json c = {{"format", "lpvid-certificate/1"}, {"claim", "consistent"}};
  c.update(reference);
  c.update({{"model", siso_model()}, {"toeplitz_mode", "signal"}, {"noise_normalisation", "rms"}, {"delta2", "1"},
            {"dmax2", "100000"}, {"form", "delta"}, {"delta_taps", {{0}}}, {"delta_horizon", horizon}});
  return c;
}

/// A class lower bound whose tree has `leaves` leaves of horizon `order`.
json class_certificate(const std::string& data_file, long leaves, long order) {
  json leaf = {{"epsilon", "1"}, {"horizon", order}, {"sigma", "1"}, {"t", "1"}, {"mu", "1"},
               {"u_exponent", -51}, {"x", "1e30"}, {"u_floor", "1/2"}};
  leaf["g"] = json::array();
  leaf["taps"] = json::array();
  for (long k = 0; k < order; ++k) {
    leaf["g"].push_back({0});
    leaf["taps"].push_back({0});
  }
  // a comb in preorder: split, leaf, split, leaf, …, leaf, leaf
  json preorder = json::array();
  for (long k = 0; k + 1 < leaves; ++k) {
    preorder.push_back({{"split", 0}});
    preorder.push_back({{"leaf", leaf}});
  }
  preorder.push_back({{"leaf", leaf}});
  return {{"format", "lpvid-certificate/1"}, {"claim", "class_lower_bound"},
          {"data", {{"file", data_file}, {"sha256", std::string(64, '0')}}}, {"model", siso_model()},
          {"toeplitz_mode", "signal"}, {"noise_normalisation", "rms"}, {"objective", "min_dmax"}, {"delta2", "1"},
          {"lower_bound", "0"}, {"form", "dual_delta_path"},
          {"class", {{"unknowns", {{"correction", true}, {"offset", false}, {"x0", false}}},
                     {"parameters", {"C[1](1,1)", "C[1](1,2)", "D[1](1,1)"}}, {"free", json::array()},
                     {"center", {"0", "0", "0"}}, {"radius", {"1/100", "1/100", "1/100"}}, {"horizon", order},
                     {"nodes", preorder}}}};
}

int verify(const std::vector<std::string>& args) { return run_lpvid_verify(args); }

TEST(WorkBudget, AClassCertificateAboveTheTotalIsRefusedBeforeItsDataAreRead) {
  gen::ScratchDir dir("budget-class");
  const std::string path = dir.file("class.json");
  write_json(path, class_certificate("absent.csv", 8, 64));  // the data file does not exist
  // 8 leaves of order 64: their rebuilds 8·64³ ≈ 2.1·10⁶ floating
  // multiply-adds, their exact sums 8·64² ≈ 3.3·10⁴ operations.
  EXPECT_EQ(verify({"--max-floating-work", "1e6", "certificate", path}), kExitWorkLimit);
  EXPECT_EQ(verify({"--max-total-work", "3e4", "certificate", path}), kExitWorkLimit);
  // Within the limits the check goes on and then finds the data missing (not
  // exit 8): the refusals above came before anything was read.
  const int within = verify({"--max-floating-work", "1e8", "--max-total-work", "1e8", "certificate", path});
  EXPECT_TRUE(within == kExitBadInput || within == kExitIo) << within;
}

// Before the exact parse (about 70 bytes of memory per byte of text): the
// streaming pass counts the leaves however their key is spelt in JSON
// ("\u006ceaf" is "leaf") and refuses; within the limit it lets the text through.
TEST(WorkBudget, DeclaredLeavesAreRefusedBeforeTheTextIsParsed) {
  std::string text = class_certificate("absent.csv", 8, 64).dump();
  for (size_t at = text.find("\"leaf\""); at != std::string::npos; at = text.find("\"leaf\"", at))
    text.replace(at, 6, "\"\\u006ceaf\"");
  ASSERT_EQ(text.find("\"leaf\""), std::string::npos);
  const VerifyWorkLimits saved = verify_work_limits();
  verify_work_limits().max_floating_work = 1e6;  // 8 leaves of order 64: about 2.1e6
  EXPECT_THROW(refuse_declared_text(text, "escaped.json"), WorkLimitError);
  verify_work_limits().max_floating_work = 1e8;
  EXPECT_NO_THROW(refuse_declared_text(text, "escaped.json"));
  EXPECT_NO_THROW(refuse_declared_text("{not json", "broken.json"));  // the parser says what is wrong
  verify_work_limits() = saved;
}

TEST(WorkBudget, ALongRecordIsRefusedBeforeItsExactSimulationAndCheckedWithinTheLimit) {
  gen::ScratchDir dir("budget-long");
  const std::string data = dir.file("d.csv"), path = dir.file("c.json");
  const std::string sha = write_data(data, 1000);
  write_json(path, primal_certificate({{"data", {{"file", "d.csv"}, {"sha256", sha}}}}, 1000));
  const Certificate c = read_certificate(path);
  const double work = simulation_work(c, {1000}, {20, 0});
  ASSERT_GT(work, 1e6);  // the (C1) check of order 1000 comes first: 10⁹
  const std::string below = std::to_string(1e9 + work / 2);
  testing::internal::CaptureStderr();
  EXPECT_EQ(verify({"--max-total-work", below, "certificate", path}), kExitWorkLimit);
  const std::string why = testing::internal::GetCapturedStderr();
  EXPECT_NE(why.find("the exact simulation of 1000 rows"), std::string::npos) << why;
  EXPECT_NE(why.find("--max-total-work"), std::string::npos) << why;
  const std::size_t reads = data_file_reads();
  EXPECT_EQ(verify({"certificate", path}), kExitOk);  // the defaults check it
  EXPECT_EQ(data_file_reads(), reads + 1);
}

TEST(WorkBudget, OneOutputOneInputOnALongHorizonIsChargedItsProofInDoubles) {
  // (C1) of order L: the exact route's L³, or for one output and one input
  // from a horizon of 4096 on the proof in doubles, L³/6 + L²
  // (verify/certificate/tap_gram_filter.h), counted here from its definition.
  gen::ScratchDir dir("budget-structured");
  const std::string path = dir.file("c.json");
  const VerifyWorkLimits saved = verify_work_limits();
  verify_work_limits().max_total_work = 1e13;  // nothing is counted without a limit
  verify_work_limits().max_floating_work = 1e13;
  const auto declared = [&](long horizon) {
    write_json(path, primal_certificate({{"data", {{"file", "d.csv"}, {"sha256", std::string(64, '0')}}}}, horizon));
    charge_declared_work(read_certificate(path));
    return std::make_pair(total_work_charged(), floating_work_charged());
  };
  const double L = 5000, below = 4000;
  EXPECT_EQ(declared(5000), std::make_pair(0.0, L * L * L / 6 + L * L));  // in doubles: floating work
  EXPECT_EQ(declared(4000), std::make_pair(below * below * below, 0.0));  // the exact matrix
  verify_work_limits() = saved;
}

TEST(WorkBudget, TheDefaultsAdmitTheFullHorizonOfTenThousandSamples) {
  // The declared parts of the two ends of a record of 10 000 samples, one
  // output and one input, one Δ over the whole record: the upper end's
  // (C1) proof in doubles (L³/6 + L²) and the lower end's compact dual
  // point (a rebuild of order L, L³, and its exact sums, L²), each within
  // lpvid-verify's defaults; one more leaf of that order is not.
  gen::ScratchDir dir("budget-defaults");
  const std::string path = dir.file("c.json");
  const VerifyWorkLimits saved = verify_work_limits();
  verify_work_limits() = default_verify_work_limits();
  const double L = 10000;
  write_json(path, primal_certificate({{"data", {{"file", "d.csv"}, {"sha256", std::string(64, '0')}}}}, 10000));
  EXPECT_NO_THROW(charge_declared_work(read_certificate(path)));
  EXPECT_DOUBLE_EQ(floating_work_charged(), L * L * L / 6 + L * L);
  write_json(path, class_certificate("d.csv", 1, 10000));
  EXPECT_NO_THROW(charge_declared_work(read_certificate(path)));
  EXPECT_DOUBLE_EQ(floating_work_charged(), L * L * L);
  EXPECT_DOUBLE_EQ(total_work_charged(), L * L);
  EXPECT_NO_THROW(require_dual_order(10000));
  write_json(path, class_certificate("d.csv", 2, 10000));
  EXPECT_THROW(charge_declared_work(read_certificate(path)), WorkLimitError);
  verify_work_limits() = saved;
}

TEST(WorkBudget, TheSimulationEstimateGrowsQuadraticallyWithTheRecordAndRestartsPerRecord) {
  gen::ScratchDir dir("budget-estimate");
  const std::string path = dir.file("c.json");
  write_json(path, primal_certificate({{"data", {{"file", "d.csv"}, {"sha256", std::string(64, '0')}}}}, 1));
  const Certificate c = read_certificate(path);
  const double one = simulation_work(c, {20000}, {20, 0}), twice = simulation_work(c, {40000}, {20, 0});
  EXPECT_GT(twice, 3.5 * one);
  EXPECT_LT(twice, 4.5 * one);
  EXPECT_LT(simulation_work(c, {20000, 20000}, {20, 0}), 0.6 * twice);  // each record from its own x0
  TextTable t;
  t.header = {"u", "y", "note"};
  t.rows = {{"0.5", "1e4000", "123456789012345678901234567890123456789012345678901234567890"}};
  const DataBits bits = table_bits(t, c.model.columns);
  EXPECT_GT(bits.signals, 4000 * 3.3);   // y's decimal exponent counts
  EXPECT_LT(bits.signals, 4100 * 6.7);   // the note is not a column of the model
  EXPECT_EQ(bits.scheduling, 0);
}

TEST(WorkBudget, TenThousandRecordsOfOneFileReadAndHashItOnce) {
  gen::ScratchDir dir("budget-records");
  const std::string data = dir.file("d.csv"), path = dir.file("c.json");
  const std::string sha = write_data(data, 20000);
  json records = json::array();
  for (long k = 0; k < 10000; ++k)
    records.push_back({{"file", "d.csv"}, {"sha256", sha}, {"rows", {2 * k, 2 * k + 2}}});
  write_json(path, primal_certificate({{"records", records}}, 2));
  EXPECT_EQ(verify({"certificate", path}), kExitWorkLimit);  // above the default --max-records
  const std::size_t reads = data_file_reads();
  EXPECT_EQ(verify({"--max-records", "10000", "certificate", path}), kExitOk);
  EXPECT_EQ(data_file_reads(), reads + 1);
}

}  // namespace
}  // namespace lpvid
