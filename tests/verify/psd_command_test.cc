#include "verify/psd/psd_command.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "support/gen_matrices.h"
#include "verify/psd/exact_psd.h"
#include "verify/psd/rational_matrix_io.h"

namespace lpvid {
namespace {

std::string fixture(const std::string& name) { return std::string(LPVID_SOURCE_DIR) + "/fixtures/psd/" + name; }

struct CommandRun {
  int code;
  std::string out, err;
};

CommandRun run(const std::string& path, bool exact_only = false) {
  std::ostringstream out, err;
  PsdCommandOptions options;
  options.exact_only = exact_only;
  const int code = run_psd_command(path, out, err, options);
  return {code, out.str(), err.str()};
}

std::string first_word(const std::string& s) { return s.substr(0, s.find_first_of(" \n")); }

struct Known {
  const char* file;
  const char* word;
  int code;
};

/// fixtures/psd/README.md lists how each was made.
const Known kKnown[] = {
    {"psd_singular_decimal_6.txt", "PSD", 0},
    {"indefinite_by_1e-30.txt", "NOT_PSD", 1},
    {"pd_by_1e-30.txt", "PD", 0},
    {"indefinite_by_1e-30_4.txt", "NOT_PSD", 1},
    {"pd_by_1e-30_4.txt", "PD", 0},
    {"zero_pivot_2x2.txt", "NOT_PSD", 1},
    {"zero_pivot_3x3.txt", "NOT_PSD", 1},
    {"zero_row_psd.txt", "PSD", 0},
    {"zero_diag_nonzero_offdiag_3x3.txt", "NOT_PSD", 1},
    {"negative_diagonal.txt", "NOT_PSD", 1},
    {"hilbert_4.txt", "PD", 0},
    {"hilbert_12.txt", "PD", 0},
    {"fools_float_cholesky.txt", "NOT_PSD", 1},
    {"psd_rank15_of_20.txt", "PSD", 0},
    {"pd_gram_30.txt", "PD", 0},
};

const char* const kMalformed[] = {
    "bad_ragged.txt", "bad_nonsquare.txt", "bad_nonsymmetric.txt", "bad_zero_denominator.txt", "bad_nan.txt",
    "bad_inf.txt",    "bad_garbage.txt",   "bad_comma.txt",        "bad_empty.txt",            "bad_hex.txt",
};

TEST(PsdCommandTest, FixturesGiveTheirKnownVerdicts) {
  for (const Known& k : kKnown) {
    for (bool exact_only : {false, true}) {
      const CommandRun r = run(fixture(k.file), exact_only);
      EXPECT_EQ(first_word(r.out), k.word) << k.file << (exact_only ? " --exact-only" : "") << "\n" << r.out << r.err;
      EXPECT_EQ(r.code, k.code) << k.file;
      EXPECT_EQ(r.err, "") << k.file;
      EXPECT_NE(r.out.find("  n: "), std::string::npos) << k.file;
      if (exact_only) {
        EXPECT_NE(r.out.find("decided by: exact"), std::string::npos) << k.file;
      }
    }
  }
}

TEST(PsdCommandTest, NotPsdPrintsPivotAndWitness) {
  const CommandRun r = run(fixture("zero_pivot_3x3.txt"), true);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("pivot index: 2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("witness: vector v of size 3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("v'Mv = -"), std::string::npos) << r.out;
}

TEST(PsdCommandTest, MalformedInputExitsWithTwo) {
  for (const char* name : kMalformed) {
    const CommandRun r = run(fixture(name));
    EXPECT_EQ(r.code, 2) << name << "\n" << r.out;
    EXPECT_EQ(r.out, "") << name;
    EXPECT_NE(r.err.find("error"), std::string::npos) << name;
    EXPECT_NE(r.err.find(name), std::string::npos) << name << ": the message names the file\n" << r.err;
  }
  EXPECT_EQ(run("/nonexistent/M.txt").code, 2);
  EXPECT_EQ(run(LPVID_SOURCE_DIR).code, 2);  // a directory
}

/// The real binary, when it has been built in the same tree.
TEST(PsdCommandTest, BinaryExitCodes) {
  const std::string exe = std::string(LPVID_BINARY_DIR) + "/lpvid-verify";
  if (!std::filesystem::exists(exe)) GTEST_SKIP() << exe << " not built";
  auto status = [&](const std::string& args) {
    const int s = std::system((exe + " " + args + " >/dev/null 2>&1").c_str());
    return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
  };
  EXPECT_EQ(status("psd " + fixture("hilbert_4.txt")), 0);
  EXPECT_EQ(status("psd " + fixture("zero_row_psd.txt")), 0);
  EXPECT_EQ(status("psd --exact-only " + fixture("zero_pivot_2x2.txt")), 1);
  EXPECT_EQ(status("psd " + fixture("bad_nonsymmetric.txt")), 2);
  EXPECT_EQ(status("psd"), 2);          // missing file argument
  EXPECT_EQ(status(""), 2);             // missing subcommand
  EXPECT_EQ(status("psd --help"), 0);
}

RC_GTEST_PROP(PsdCommandProperty, ExitCodeMatchesTheConstruction, ()) {
  const bool negative = *rc::gen::arbitrary<bool>();
  const auto k = negative ? *gen::with_negative() : *rc::gen::oneOf(gen::psd_gram(true), gen::pd_gram_plus());
  const std::string path =
      (std::filesystem::temp_directory_path() / ("lpvid_psd_command_" + std::to_string(::getpid()) + ".txt")).string();
  write_rational_matrix_file(path, k.M);
  const CommandRun r = run(path);
  std::remove(path.c_str());
  RC_ASSERT(r.code == (negative ? 1 : 0));
  RC_ASSERT(first_word(r.out) == std::string(verdict_word(decide_psd_exact(k.M).verdict)));
}

}  // namespace
}  // namespace lpvid
