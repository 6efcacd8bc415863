// A stop requested from another thread (core/stop_request.h) ends an
// in-process run (the Python module's way of running lpvid) with exit code
// 130 and none of its outputs, without ending the process; once the request
// is withdrawn, the next run gives the answer of a run never stopped.
// (Failed before: there was no request_stop; a run could only be ended by a
// signal, which ended the whole process.)
// No timing is asserted: bench/stop_latency.py measures how soon a run stops.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <future>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include "cli/command_line.h"
#include "core/exit_codes.h"
#include "core/stop_request.h"
#include "support/cli_runner.h"
#include "verify/verify_command_line.h"

namespace lpvid {
namespace {

using gen::CliRunner;

/// Splits "a b c" into words (the tests' arguments have no spaces in them).
std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

struct StopRequest : CliRunner {
  void TearDown() override {
    clear_stop();
    CliRunner::TearDown();
  }
  /// A small known case (the paper's Example 1, 40 noise-free samples).
  std::string small_invalidate(const std::string& certificate) const {
    const std::string data = std::string(LPVID_SOURCE_DIR) + "/fixtures/example1/noise_free_n40.csv";
    const std::string model = std::string(LPVID_SOURCE_DIR) + "/fixtures/example1/initial_model.json";
    return "invalidate --data " + data + " --model " + model + " --delta 1 --quiet --certificate " + certificate;
  }
};

// A long certification (a 2000-sample record: far longer than the wait
// below) is stopped from another thread: exit 130, no certificate or report
// left, and the process goes on; after clear_stop the small case gives
// byte for byte the certificate of a run before any stop.
TEST_F(StopRequest, StoppedRunEndsWithCode130AndLeavesNothing) {
  ASSERT_EQ(cli::run_lpvid(words(small_invalidate(file("before.json")))), kExitOk);
  ASSERT_EQ(run("generate", "effect-case --effect output_polynomial --n 2000 --seed 5 --out " + file("long.csv") +
                                " --validation-out " + file("long_test.csv") + " --model-out " + file("long.json")),
            0)
      << output();
  const std::string long_run = "invalidate --data " + file("long.csv") + " --model " + file("long.json") +
                               " --delta 0.5 --quiet --certificate " + file("long.cert.json") + " --report " +
                               file("long.report.json");
  std::future<int> code = std::async(std::launch::async, [&] { return cli::run_lpvid(words(long_run)); });
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // into the run (not a measurement)
  request_stop();
  EXPECT_EQ(code.get(), kExitInterrupted);
  EXPECT_TRUE(stop_requested());
  EXPECT_FALSE(std::filesystem::exists(file("long.cert.json")));
  EXPECT_FALSE(std::filesystem::exists(file("long.report.json")));

  clear_stop();
  ASSERT_EQ(cli::run_lpvid(words(small_invalidate(file("after.json")))), kExitOk);
  EXPECT_EQ(read_text(file("after.json")), read_text(file("before.json")));
}

// A request made before a run stops it at its first check, and lasts until
// withdrawn; both command lines map it to 130 with nothing written.
TEST_F(StopRequest, PendingRequestStopsEveryRunUntilCleared) {
  request_stop();
  EXPECT_EQ(cli::run_lpvid(words(small_invalidate(file("a.json")))), kExitInterrupted);
  EXPECT_FALSE(std::filesystem::exists(file("a.json")));
  // the exact LDL^T of a 3x3 positive definite matrix checks between pivots
  write_text(file("m.txt"), "2 1 0\n1 2 1\n0 1 2\n");
  EXPECT_EQ(run_lpvid_verify({"psd", "--exact-only", file("m.txt")}), kExitInterrupted);
  clear_stop();
  EXPECT_FALSE(stop_requested());
  EXPECT_EQ(run_lpvid_verify({"psd", "--exact-only", file("m.txt")}), kExitOk);
  EXPECT_EQ(cli::run_lpvid(words(small_invalidate(file("a.json")))), kExitOk);
  EXPECT_TRUE(std::filesystem::exists(file("a.json")));
}

/// The long option names of the option column of `help` (lines that start
/// with "-x," or "--name"), read independently of the option table.
std::set<std::string> help_option_names(const std::string& help) {
  std::set<std::string> names;
  const std::regex column(R"(^\s+(-[-\w,]+))");
  const std::regex name(R"(--([\w-]+))");
  std::istringstream in(help);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, column)) continue;
    const std::string col = m[1];
    for (auto it = std::sregex_iterator(col.begin(), col.end(), name); it != std::sregex_iterator(); ++it)
      names.insert((*it)[1]);
  }
  names.erase("help");
  return names;
}

std::set<std::string> table_names(const std::vector<OptionInfo>& options) {
  std::set<std::string> names;
  for (const OptionInfo& o : options)
    if (!o.positional) names.insert(o.names.begin(), o.names.end());
  return names;
}

const OptionInfo* find_option(const std::vector<OptionInfo>& options, const std::string& name) {
  for (const OptionInfo& o : options)
    for (const std::string& n : o.names)
      if (n == name) return &o;
  return nullptr;
}

// The option table lists what `lpvid diagnose --help` prints (parsed from
// the help text), the top-level options, nested commands and the verifier's.
TEST_F(StopRequest, OptionTableListsTheOptionsTheHelpPrints) {
  const OptionTable table = cli::lpvid_option_table();
  ASSERT_EQ(run("diagnose", "--help"), 0) << output();
  const std::set<std::string> help = help_option_names(output());
  ASSERT_GT(help.size(), 10u) << output();
  ASSERT_TRUE(table.count("diagnose"));
  EXPECT_EQ(table_names(table.at("diagnose")), help);

  ASSERT_TRUE(table.count(""));
  const OptionInfo* timeout = find_option(table.at(""), "timeout");
  ASSERT_NE(timeout, nullptr);
  EXPECT_FALSE(timeout->flag);
  EXPECT_FALSE(timeout->multi);
  EXPECT_NE(find_option(table.at(""), "max-file-mb"), nullptr);
  EXPECT_EQ(find_option(table.at(""), "version"), nullptr);
  EXPECT_TRUE(table.count("jobs plan"));

  const OptionInfo* quiet = find_option(table.at("invalidate"), "quiet");
  ASSERT_NE(quiet, nullptr);
  EXPECT_TRUE(quiet->flag);
  const OptionInfo* data = find_option(table.at("invalidate"), "data");
  ASSERT_NE(data, nullptr);
  EXPECT_TRUE(data->required);
  EXPECT_TRUE(data->multi);  // one --data per record
  EXPECT_FALSE(data->flag);

  const OptionTable verify = lpvid_verify_option_table();
  ASSERT_TRUE(verify.count("lpvid-verify psd"));
  const OptionInfo* exact_only = find_option(verify.at("lpvid-verify psd"), "exact-only");
  ASSERT_NE(exact_only, nullptr);
  EXPECT_TRUE(exact_only->flag);
  const OptionInfo* file = find_option(verify.at("lpvid-verify psd"), "file");
  ASSERT_NE(file, nullptr);
  EXPECT_TRUE(file->positional && file->required);
  EXPECT_NE(find_option(verify.at("lpvid-verify"), "max-exact-work"), nullptr);
}

}  // namespace
}  // namespace lpvid
