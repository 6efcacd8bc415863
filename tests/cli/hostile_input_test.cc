// Hostile and failing inputs through the real binaries: each ends
// with a message naming the problem and the documented exit code
// (src/cli/report.h: 2 bad input, 6 I/O failure; lpvid-verify the same), and
// a failed run leaves none of its outputs behind. How long each takes is
// measured by bench/hostile_inputs.sh, not here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_runner.h"
#include "support/fixtures.h"

namespace lpvid {
namespace {

using gen::CliRunner;

const std::string kData = gen::kExample1Fixtures + "noise_free_n40.csv";
const std::string kModel = gen::kExample1Fixtures + "true_model.json";

struct HostileInput : CliRunner {
  /// The text of a file.
  static std::string read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  void write(const std::string& path, const std::string& text) const { std::ofstream(path, std::ios::binary) << text; }
  bool has(const std::string& needle) const { return output().find(needle) != std::string::npos; }
  /// A consistency certificate of the true model on its own noise-free data
  /// (the data is copied next to it, since the certificate names it relatively).
  std::string make_certificate() {
    const std::string data = file("data.csv"), cert = file("c.json");
    write(data, read(kData));
    EXPECT_EQ(run("invalidate", "--data " + data + " --model " + kModel + " --certificate " + cert), 0) << output();
    return cert;
  }
  /// The certificate with the value of "key" (a JSON string) replaced, written to `name`.
  std::string with_field(const std::string& cert, const std::string& key, const std::string& value,
                         const std::string& name) {
    std::string t = read(cert);
    const size_t k = t.find("\"" + key + "\"");
    EXPECT_NE(k, std::string::npos) << key;
    const size_t open = t.find('"', t.find(':', k));
    const size_t close = t.find('"', open + 1);
    t.replace(open + 1, close - open - 1, value);
    const std::string out = file(name);
    write(out, t);
    return out;
  }
};

TEST_F(HostileInput, DeviceFilesAreNotInputs) {
  EXPECT_EQ(run("invalidate", "--data /dev/zero --model " + kModel), 2);
  EXPECT_TRUE(has("/dev/zero") && has("not a regular file")) << output();
  EXPECT_EQ(run("invalidate", "--data " + kData + " --model /dev/zero"), 2);
  EXPECT_TRUE(has("not a regular file")) << output();
  EXPECT_EQ(run_program(verify_exe, "psd /dev/zero"), 2);
  EXPECT_TRUE(has("not a regular file")) << output();
  EXPECT_EQ(run_program(verify_exe, "certificate /dev/zero"), 2);
  EXPECT_TRUE(has("not a regular file")) << output();
}

TEST_F(HostileInput, MissingFilesAreBadInput) {
  EXPECT_EQ(run("invalidate", "--data " + file("nope.csv") + " --model " + kModel), 2);
  EXPECT_TRUE(has("nope.csv") && has("no such file")) << output();
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("nope.json")), 2);
  EXPECT_TRUE(has("no such file")) << output();
}

TEST_F(HostileInput, NumbersLongerThanTheDigitLimitAreRejected) {
  const std::string cert = make_certificate();
  ASSERT_EQ(run_program(verify_exe, "certificate " + cert), 0) << output();
  // A 10^5-digit denominator, and a bound of 10^4000 (4001 digits).
  const std::string huge = with_field(cert, "delta2", "1/1" + std::string(100000, '0'), "huge.json");
  EXPECT_EQ(run_program(verify_exe, "certificate " + huge), 2);
  EXPECT_TRUE(has("100002 digits") && has("--max-digits")) << output();
  const std::string big = with_field(cert, "delta2", "1e4000", "big.json");
  EXPECT_EQ(run_program(verify_exe, "--max-digits 4000 certificate " + big), 2);
  EXPECT_TRUE(has("4001 digits")) << output();
  // Within the digit limit but beyond the range of a double, a number is
  // malformed wherever it stands (exit 2, its field named)...
  EXPECT_EQ(run_program(verify_exe, "certificate " + big), 2) << output();
  EXPECT_TRUE(has("delta2") && has("range of a double")) << output();
  // ...within it, it reaches the exact check: a larger δ² than needed is
  // still a true claim (the Δ form is balanced by a power of two, so 1e300
  // costs no more than 1).
  EXPECT_EQ(run_program(verify_exe, "certificate " + with_field(cert, "delta2", "1e300", "large.json")), 0) << output();
  // A δ² of 1e-200 is far below what the data need: the claim is false.
  EXPECT_EQ(run_program(verify_exe, "certificate " + with_field(cert, "delta2", "1e-200", "small.json")), 1) << output();
  // So is δ² = 1/10^5000 (5001 digits, within the limit): decided, not left
  // to integers of 10^5000 (its time is measured by bench/hostile_inputs.sh).
  const std::string tiny = with_field(cert, "delta2", "1/1" + std::string(5000, '0'), "tiny.json");
  EXPECT_EQ(run_program(verify_exe, "certificate " + tiny), 1) << output();
  EXPECT_TRUE(has("(C1) fails")) << output();
}

TEST_F(HostileInput, PolynomialDegreeAboveTheLimitIsRejected) {
  std::string coefficients = "0, 1";
  for (int i = 0; i < 1999; ++i) coefficients += ", 0";
  std::string model = read(kModel);
  const size_t brace = model.rfind('}');
  model.insert(brace, ",\n  \"static\": {\"output\": {\"kind\": \"polynomial\", \"coefficients\": [" + coefficients + "]}}\n");
  const std::string path = file("degree2000.json");
  write(path, model);
  EXPECT_EQ(run("invalidate", "--data " + kData + " --model " + path), 2);
  EXPECT_TRUE(has("degree 2000") && has("--max-degree")) << output();
}

TEST_F(HostileInput, RowsAboveTheSampleLimitAreRejectedAndTheLimitCanBeRaised) {
  EXPECT_EQ(run("invalidate", "--max-samples 10 --data " + kData + " --model " + kModel), 2);
  EXPECT_TRUE(has("more than 10 data rows") && has("--max-samples")) << output();
  EXPECT_EQ(run("invalidate", "--max-samples 40 --data " + kData + " --model " + kModel + " --certificate " + file("c.json")),
            0)
      << output();
}

TEST_F(HostileInput, RowWindowsMustBeTwoWholeIntegers) {
  for (const std::string rows : {"3:7x", "3", "a:9", "-1:5", "9:9", "1:", " 1:5"}) {
    EXPECT_EQ(run("invalidate", "--rows '" + rows + "' --data " + kData + " --model " + kModel), 2) << rows;
    EXPECT_TRUE(has("--rows") && has("'" + rows + "'")) << output();
  }
  EXPECT_EQ(run("invalidate", "--rows 0:41 --data " + kData + " --model " + kModel), 2);
  EXPECT_TRUE(has("only 40 rows")) << output();
}

TEST_F(HostileInput, FilesAboveTheSizeLimitAreRejected) {
  EXPECT_EQ(run("invalidate", "--max-file-mb 0.001 --data " + kData + " --model " + kModel), 2);
  EXPECT_TRUE(has("file too large") && has("--max-file-mb")) << output();
}

TEST_F(HostileInput, AnUnwritableReportIsAnIoFailureAndLeavesNoCertificate) {
  const std::string cert = file("c.json");
  EXPECT_EQ(run("invalidate", "--data " + kData + " --model " + kModel + " --certificate " + cert +
                                  " --report " + file("missing_dir/r.json")),
            6);
  EXPECT_TRUE(has("cannot write report")) << output();
  EXPECT_FALSE(std::filesystem::exists(cert)) << "the certificate of a failed run was left behind";
  for (const auto& e : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
}

TEST_F(HostileInput, SimulateToAMissingDirectoryIsAnIoFailure) {
  EXPECT_EQ(run("simulate", "--data " + kData + " --model " + kModel + " --out " + file("missing_dir/x.csv")), 6);
  EXPECT_TRUE(has("cannot write")) << output();
}

}  // namespace
}  // namespace lpvid
