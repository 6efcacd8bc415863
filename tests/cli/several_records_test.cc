// Several records on the command line (docs/several_records.md), through the
// real binary: `--data` repeated, each followed by its own `--rows`; the
// report's "records" list (file, rows, sha256, samples and each record's
// figures) and the pairing errors. Two records of a first-order LTI system
// at two input amplitudes, written here; the model is x+ = x/2 + u, y = x.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/number_text.h"
#include "support/cli_runner.h"

namespace lpvid {
namespace {

using gen::CliRunner;

const char* kFirstOrderModel = R"({
  "format": "lpvid-model/1",
  "states": 1, "inputs": 1, "outputs": 1, "scheduling": [],
  "columns": {"u": ["u"], "y": ["y"]},
  "initial": {"A": [{"basis": "1", "value": [["1/2"]]}], "B": [{"basis": "1", "value": [[1]]}],
              "C": [{"basis": "1", "value": [[1]]}]},
  "uncertainty": {"structure": "additive", "weight": "1/10"}
})";

/// One record of the plant x+ = 0.55 x + u, y = x + small noise (the model's
/// pole is 0.5: the residual is not zero), input amplitude `amp`.
struct Record {
  std::vector<double> u, y;
};

Record make_record(double amp, int n) {
  Record r;
  double x = 0;
  for (int k = 0; k < n; ++k) {
    char text[64];
    std::snprintf(text, sizeof text, "%.6f", amp * (std::sin(0.3 * k) + 0.5 * std::cos(1.1 * k)));
    r.u.push_back(std::stod(text));  // the numbers as the file holds them
    std::snprintf(text, sizeof text, "%.6f", x + 0.01 * std::sin(2.3 * k + amp));
    r.y.push_back(std::stod(text));
    x = 0.55 * x + r.u.back();
  }
  return r;
}

std::string csv_of(const Record& r) {
  std::string s = "u,y\n";
  char line[80];
  for (size_t k = 0; k < r.u.size(); ++k) {
    std::snprintf(line, sizeof line, "%.6f,%.6f\n", r.u[k], r.y[k]);
    s += line;
  }
  return s;
}

/// ‖y − ŷ‖² over rows [b, e) with ŷ the model's free run from 0 over those rows
/// (computed here, independently of the program).
double residual_energy(const Record& r, size_t b, size_t e) {
  double x = 0, sum = 0;
  for (size_t k = b; k < e; ++k) {
    sum += (r.y[k] - x) * (r.y[k] - x);
    x = 0.5 * x + r.u[k];
  }
  return sum;
}

struct SeveralRecordsCli : CliRunner {
  Record a = make_record(1.0, 60), b = make_record(3.0, 100);
  void SetUp() override {
    CliRunner::SetUp();
    if (IsSkipped()) return;
    write_text(file("model.json"), kFirstOrderModel);
    write_text(file("a.csv"), csv_of(a));
    write_text(file("b.csv"), csv_of(b));
  }
  /// `lpvid invalidate` with `data` (the --data/--rows words) at a fixed dmax.
  int invalidate(const std::string& data, const std::string& report) {
    return run("invalidate", "--quiet " + data + " --model " + file("model.json") + " --dmax 0.5 --certificate " +
                                 file("c.json") + " --report " + report);
  }
  std::string sha256_of(const std::string& path) {  // by the system's sha256sum, not by lpvid
    std::string line;
    if (FILE* p = ::popen(("sha256sum " + path).c_str(), "r")) {
      char buf[128];
      if (std::fgets(buf, sizeof buf, p)) line = buf;
      ::pclose(p);
    }
    return line.substr(0, 64);
  }
  std::string two_records() const { return "--data " + file("a.csv") + " --data " + file("b.csv") + " --rows 0:80"; }
};

TEST_F(SeveralRecordsCli, TheReportListsEachRecordWithItsHashRowsAndSamples) {
  const int code = invalidate(two_records(), file("r.json"));
  ASSERT_TRUE(code == 0 || code == 4) << output();  // 4: the solver side may not certify yet; the figures do not depend on it
  const nlohmann::json r = read_json(file("r.json"));
  ASSERT_TRUE(r.contains("records")) << r.dump(1);
  const nlohmann::json& list = r["records"];
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0]["file"], file("a.csv"));
  EXPECT_TRUE(list[0]["rows"].is_null());
  EXPECT_EQ(list[0]["sha256"], sha256_of(file("a.csv")));
  EXPECT_EQ(list[0]["samples"], 60);
  EXPECT_EQ(list[1]["file"], file("b.csv"));
  EXPECT_EQ(list[1]["rows"], nlohmann::json::array({0, 80}));
  EXPECT_EQ(list[1]["sha256"], sha256_of(file("b.csv")));
  EXPECT_EQ(list[1]["samples"], 80);
  EXPECT_EQ(r["samples"], 140);
  // each record's RMS residual from its own free run from rest (computed here)
  EXPECT_NEAR(list[0]["rms_residual"].get<double>(), std::sqrt(residual_energy(a, 0, 60) / 60), 1e-9);
  EXPECT_NEAR(list[1]["rms_residual"].get<double>(), std::sqrt(residual_energy(b, 0, 80) / 80), 1e-9);
  // the printout shows one line per record and the pooled line
  EXPECT_NE(output().find("pooled"), std::string::npos) << output();
}

TEST_F(SeveralRecordsCli, ThePooledRmsIsTheSampleWeightedCombinationOfTheRecords) {
  invalidate(two_records(), file("r.json"));
  const nlohmann::json r = read_json(file("r.json"));
  ASSERT_TRUE(r.contains("records") && r.contains("records_pooled")) << output();
  double weighted = 0, samples = 0;
  for (const nlohmann::json& rec : r["records"]) {
    const double n = rec["samples"].get<double>(), rms = rec["rms_residual"].get<double>();
    weighted += n * rms * rms;
    samples += n;
  }
  const nlohmann::json& pooled = r["records_pooled"];
  EXPECT_EQ(pooled["samples"].get<double>(), samples);
  const double rms = pooled["rms_residual"].get<double>();
  EXPECT_NEAR(rms * rms, weighted / samples, 1e-12 * rms * rms);
  EXPECT_LT(pooled["fit_percent"].get<double>(), 100.0);
}

TEST_F(SeveralRecordsCli, SwappingTheRecordsSwapsTheirLinesAndKeepsThePooledFigures) {
  invalidate(two_records(), file("r1.json"));
  invalidate("--data " + file("b.csv") + " --rows 0:80 --data " + file("a.csv"), file("r2.json"));
  const nlohmann::json r1 = read_json(file("r1.json")), r2 = read_json(file("r2.json"));
  ASSERT_TRUE(r1.contains("records") && r2.contains("records"));
  EXPECT_EQ(r1["records"][0], r2["records"][1]);
  EXPECT_EQ(r1["records"][1], r2["records"][0]);
  EXPECT_NEAR(r1["records_pooled"]["rms_residual"].get<double>(), r2["records_pooled"]["rms_residual"].get<double>(), 1e-12);
  EXPECT_EQ(r1["status"], r2["status"]);
  EXPECT_EQ(r1["delta"], r2["delta"]);
}

TEST_F(SeveralRecordsCli, DiagnoseGivesOneOutcomeInEitherOrderOfTheRecords) {
  // diagnose puts the records in a canonical order (by their samples at the
  // fits' precision)
  // before any fit: listing them the other way round changes no figure
  const std::string tail = " --model " + file("model.json") + " --max-effects 1 --window-length 40 --max-windows 1";
  ASSERT_EQ(run("diagnose", "--quiet --data " + file("a.csv") + " --data " + file("b.csv") + tail + " --report " +
                                file("d1.json")),
            0)
      << output();
  ASSERT_EQ(run("diagnose", "--quiet --data " + file("b.csv") + " --data " + file("a.csv") + tail + " --report " +
                                file("d2.json")),
            0)
      << output();
  const nlohmann::json r1 = read_json(file("d1.json")), r2 = read_json(file("d2.json"));
  for (const char* key : {"estimation", "selection", "effects", "rounds"}) EXPECT_EQ(r1[key], r2[key]) << key;
  EXPECT_EQ(r1["before"]["rms_estimation"], r2["before"]["rms_estimation"]);
  EXPECT_EQ(r1["after"]["rms_estimation"], r2["after"]["rms_estimation"]);
  EXPECT_EQ(r1["after"]["delta"], r2["after"]["delta"]);
}

TEST_F(SeveralRecordsCli, AMalformedSecondFileIsNamedAndNothingIsWritten) {
  std::string bad = csv_of(b);
  bad.replace(bad.find('\n', 40) + 1, 1, "x");  // a cell of the second data row no longer a number
  write_text(file("bad.csv"), bad);
  EXPECT_EQ(invalidate("--data " + file("a.csv") + " --data " + file("bad.csv"), file("r.json")), 2);
  EXPECT_NE(output().find("bad.csv"), std::string::npos) << output();
  EXPECT_FALSE(std::filesystem::exists(file("r.json")));
  EXPECT_FALSE(std::filesystem::exists(file("c.json")));
}

TEST_F(SeveralRecordsCli, RecordsWithDifferentColumnsNameBothFiles) {
  std::string wide = "u,y,extra\n";
  for (size_t k = 0; k < 50; ++k) wide += std::to_string(b.u[k]) + "," + std::to_string(b.y[k]) + ",0\n";
  write_text(file("wide.csv"), wide);
  EXPECT_EQ(invalidate("--data " + file("a.csv") + " --data " + file("wide.csv"), file("r.json")), 2);
  EXPECT_NE(output().find("wide.csv"), std::string::npos) << output();
  EXPECT_NE(output().find("a.csv"), std::string::npos) << output();
}

TEST_F(SeveralRecordsCli, ARowsBelongsToTheDataBeforeIt) {
  // before the first --data
  EXPECT_EQ(invalidate("--rows 0:10 --data " + file("a.csv") + " --data " + file("b.csv"), file("r.json")), 2);
  EXPECT_NE(output().find("before the first --data"), std::string::npos) << output();
  // two for one --data
  EXPECT_EQ(invalidate("--data " + file("a.csv") + " --rows 0:10 --rows 0:20 --data " + file("b.csv"), file("r.json")), 2);
  EXPECT_NE(output().find("has a --rows already"), std::string::npos) << output();
  // more --rows than --data
  EXPECT_EQ(invalidate("--data " + file("a.csv") + " --rows 0:10 --rows 0:20", file("r.json")), 2);
  EXPECT_NE(output().find("--rows"), std::string::npos) << output();
  // a window past the end of its own file names that file
  EXPECT_EQ(invalidate("--data " + file("a.csv") + " --rows 0:70 --data " + file("b.csv"), file("r.json")), 2);
  EXPECT_NE(output().find("a.csv has only 60 rows"), std::string::npos) << output();
  EXPECT_FALSE(std::filesystem::exists(file("r.json")));
}

TEST_F(SeveralRecordsCli, OneRecordKeepsTheOneRecordReport) {
  invalidate("--rows 0:50 --data " + file("b.csv"), file("r.json"));  // one --data: its --rows may come first, as before
  const nlohmann::json r = read_json(file("r.json"));
  EXPECT_FALSE(r.contains("records"));
  EXPECT_EQ(r["samples"], 50);
  EXPECT_EQ(output().find("pooled"), std::string::npos) << output();
}

TEST_F(SeveralRecordsCli, CompareScoresEachRecordFromItsOwnStartAndPoolsThem) {
  ASSERT_EQ(run("compare", "--data " + file("a.csv") + " --data " + file("b.csv") + " --rows 20:80 --model " +
                               file("model.json") + " --report " + file("r.json")),
            0)
      << output();
  const nlohmann::json r = read_json(file("r.json"));
  ASSERT_TRUE(r.contains("records")) << r.dump(1);
  ASSERT_EQ(r["records"].size(), 2u);
  EXPECT_EQ(r["records"][1]["rows"], nlohmann::json::array({20, 80}));
  // each record a free run from the model's x0 at its own first row (computed here)
  EXPECT_NEAR(r["records"][0]["rms"].get<double>(), std::sqrt(residual_energy(a, 0, 60) / 60), 1e-9);
  EXPECT_NEAR(r["records"][1]["rms"].get<double>(), std::sqrt(residual_energy(b, 20, 80) / 60), 1e-9);
  // pooled: every sample of both records
  const double pooled = std::sqrt((residual_energy(a, 0, 60) + residual_energy(b, 20, 80)) / 120);
  EXPECT_NEAR(r["rms"].get<double>(), pooled, 1e-9);
  EXPECT_EQ(r["samples"], 120);
  // --out writes one record's series: refused for several
  EXPECT_EQ(run("compare", "--data " + file("a.csv") + " --data " + file("b.csv") + " --model " + file("model.json") +
                               " --out " + file("s.csv")),
            2);
  EXPECT_NE(output().find("--out"), std::string::npos) << output();
}

// compare's --x0 (model|fit) is one option for the call, not one per record:
// after two --data it fits each record's start (it crashed before), and a
// fitted start is never worse than the model's on that record (least squares).
TEST_F(SeveralRecordsCli, CompareFitsTheStartOfEachOfSeveralRecords) {
  ASSERT_EQ(run("compare", "--data " + file("a.csv") + " --data " + file("b.csv") + " --rows 20:80 --model " +
                               file("model.json") + " --x0 fit --report " + file("f.json")),
            0)
      << output();
  const nlohmann::json r = read_json(file("f.json"));
  ASSERT_EQ(r["records"].size(), 2u) << r.dump(1);
  EXPECT_LE(r["records"][0]["rms"].get<double>(), std::sqrt(residual_energy(a, 0, 60) / 60) * (1 + 1e-9));
  EXPECT_LE(r["records"][1]["rms"].get<double>(), std::sqrt(residual_energy(b, 20, 80) / 60) * (1 + 1e-9));
}

// The certificate of several records names every record and verifies.
TEST_F(SeveralRecordsCli, TheCertificateNamesBothRecordsAndVerifies) {
  ASSERT_EQ(invalidate(two_records(), file("r.json")), 0) << output();
  const nlohmann::json c = read_json(file("c.json"));
  ASSERT_TRUE(c.contains("records")) << c.dump(1);
  ASSERT_EQ(c["records"].size(), 2u);
  EXPECT_EQ(c["records"][0]["sha256"], sha256_of(file("a.csv")));
  EXPECT_EQ(c["records"][1]["sha256"], sha256_of(file("b.csv")));
  EXPECT_EQ(c["records"][1]["rows"], nlohmann::json::array({0, 80}));
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("c.json")), 0) << output();
}

TEST_F(SeveralRecordsCli, TheOrderOfTheRecordsDoesNotChangeTheBounds) {
  ASSERT_EQ(invalidate(two_records(), file("r1.json")), 0) << output();
  ASSERT_EQ(invalidate("--data " + file("b.csv") + " --rows 0:80 --data " + file("a.csv"), file("r2.json")), 0) << output();
  const nlohmann::json r1 = read_json(file("r1.json")), r2 = read_json(file("r2.json"));
  EXPECT_NEAR(r1["delta"].get<double>(), r2["delta"].get<double>(), 1e-6 * r1["delta"].get<double>());
}

// --x0 on the command line: each record's own initial state, paired with the
// --data before it like --rows. Known answers by construction: two records
// made by the model x+ = x/2 + u, y = x itself from x0 = 2 and x0 = -3 (y
// written with 6 decimals), so with each record's own x0 the residual is
// rounding only and the model is consistent at tiny bounds; from the model's
// x0 = 0 each record keeps the transient 2·(1/2)^k (resp. −3·(1/2)^k), noise
// RMS about 0.3 ≫ 0.001, which no Δ with δ = 0.001 explains.

/// n rows of the model itself from x(0) = x0, amplitude `amp`.
std::string record_csv(double x0, double amp, int n) {
  std::string s = "u,y\n";
  double x = x0;
  for (int k = 0; k < n; ++k) {
    char u[32], line[80];
    std::snprintf(u, sizeof u, "%.6f", amp * std::sin(0.4 * k + amp));
    std::snprintf(line, sizeof line, "%s,%.6f\n", u, x);
    s += line;
    x = 0.5 * x + std::stod(u);
  }
  return s;
}

Rational exact(const nlohmann::json& v) { return rational_from_text(v.is_string() ? v.get<std::string>() : v.dump()); }

struct RecordInitialState : CliRunner {
  void SetUp() override {
    CliRunner::SetUp();
    if (IsSkipped()) return;
    write_text(file("model.json"), kFirstOrderModel);
    write_text(file("a.csv"), record_csv(2, 1.0, 50));
    write_text(file("b.csv"), record_csv(-3, 2.0, 70));
  }
  int invalidate(const std::string& data) {
    return run("invalidate", "--quiet " + data + " --model " + file("model.json") +
                                 " --delta 0.001 --dmax 0.001 --certificate " + file("c.json") + " --report " + file("r.json"));
  }
};

TEST_F(RecordInitialState, EachRecordFromItsOwnX0IsConsistentAndTheCertificateCarriesIt) {
  ASSERT_EQ(invalidate("--data " + file("a.csv") + " --x0 2 --data " + file("b.csv") + " --x0=-3"), 0) << output();
  const nlohmann::json c = read_json(file("c.json"));
  ASSERT_EQ(c["records"].size(), 2u) << c.dump(1);
  EXPECT_EQ(exact(c["records"][0]["x0"][0]), Rational(2));
  EXPECT_EQ(exact(c["records"][1]["x0"][0]), Rational(-3));
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("c.json")), 0) << output();
  // the same data from the model's x0 = 0: not consistent at these bounds
  EXPECT_EQ(invalidate("--data " + file("a.csv") + " --data " + file("b.csv")), 1) << output();
  // --x0 after --rows and a negative value as its own word
  EXPECT_EQ(invalidate("--data " + file("a.csv") + " --x0 2 --data " + file("b.csv") + " --rows 0:60 --x0 -3"), 0)
      << output();
}

TEST_F(RecordInitialState, OneRecordWithX0KeepsTheOneRecordCertificate) {
  EXPECT_EQ(invalidate("--data " + file("a.csv")), 1) << output();
  ASSERT_EQ(invalidate("--x0 2 --data " + file("a.csv")), 0) << output();
  const nlohmann::json c = read_json(file("c.json"));
  EXPECT_FALSE(c.contains("records")) << c.dump(1);
  EXPECT_TRUE(c.contains("data")) << c.dump(1);
  EXPECT_EQ(exact(c["model"]["x0"][0]), Rational(2)) << c["model"].dump();
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("c.json")), 0) << output();
}

TEST_F(RecordInitialState, ABadX0IsNamedAndNothingIsWritten) {
  EXPECT_EQ(invalidate("--data " + file("a.csv") + " --x0 1,2 --data " + file("b.csv")), 2) << output();
  EXPECT_NE(output().find("--x0 1,2: 2 value(s), the model has 1 state(s)"), std::string::npos) << output();
  EXPECT_EQ(invalidate("--data " + file("a.csv") + " --data " + file("b.csv") + " --x0 two"), 2) << output();
  EXPECT_NE(output().find("--x0 two"), std::string::npos) << output();
  EXPECT_EQ(invalidate("--x0 1 --data " + file("a.csv") + " --data " + file("b.csv")), 2) << output();
  EXPECT_NE(output().find("before the first --data"), std::string::npos) << output();
  EXPECT_EQ(invalidate("--data " + file("a.csv") + " --x0 1 --x0 2 --data " + file("b.csv")), 2) << output();
  EXPECT_NE(output().find("has a --x0 already"), std::string::npos) << output();
  EXPECT_FALSE(std::filesystem::exists(file("r.json")));
  EXPECT_FALSE(std::filesystem::exists(file("c.json")));
}

// diagnose fits each record's own initial state: the same two records (the
// model's own free runs from x0 = 2 and x0 = -3), no effect tried; the
// declared model is then exact on both records from their own states, and
// the report lists those states. One state for both would leave the
// transients 2·(1/2)^k and −3·(1/2)^k in at least one record.
TEST_F(RecordInitialState, DiagnoseFitsEachRecordsOwnInitialState) {
  ASSERT_EQ(run("diagnose", "--quiet --data " + file("a.csv") + " --data " + file("b.csv") + " --model " +
                                file("model.json") + " --max-effects 0 --max-windows 1 --report " + file("d.json")),
            0)
      << output();
  const nlohmann::json r = read_json(file("d.json"));
  ASSERT_EQ(r["records"].size(), 2u) << r.dump(1);
  // canonical order: the shorter record (a.csv, 50 rows, from x0 = 2) first
  EXPECT_NEAR(r["records"][0]["x0_before"][0].get<double>(), 2.0, 1e-5) << r["records"].dump(1);
  EXPECT_NEAR(r["records"][1]["x0_before"][0].get<double>(), -3.0, 1e-5) << r["records"].dump(1);
  for (const auto& rec : r["records"]) EXPECT_LT(rec["rms_before"].get<double>(), 1e-5) << rec.dump(1);
}

}  // namespace
}  // namespace lpvid
