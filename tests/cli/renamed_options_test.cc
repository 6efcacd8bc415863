// Renamed options: each old name is refused (exit 2) with a message naming
// the new one, and nothing is written; options a command would ignore are
// refused; a misspelt option gets "did you mean --x?". The expected texts
// are the option names the commands define (docs/cli.md "Renamed options").
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/cli_runner.h"

namespace lpvid {
namespace {

using gen::CliRunner;

struct RenamedOptions : CliRunner {
  /// Expects exit 2 and every piece of `words` in the output.
  void refused(const std::string& command, const std::string& args, const std::vector<std::string>& words) {
    EXPECT_EQ(run(command, args), 2) << command << " " << args << "\n" << output();
    for (const std::string& w : words) EXPECT_NE(output().find(w), std::string::npos) << w << "\n" << output();
  }
};

TEST_F(RenamedOptions, EachOldNameNamesTheNewOne) {
  const std::string fit = "--data d.csv ";
  refused("jobs", "plan --data d.csv --model m.json --dir J --window 100",
          {"lpvid jobs plan: --window was renamed to --window-length"});
  refused("diagnose", "--data d.csv --model m.json --max-delay 3",
          {"lpvid diagnose: --max-delay was renamed to --max-input-delay"});
  refused("fit-linear", fit + "--out " + file("m.json"), {"lpvid fit-linear: --out was renamed to --model-out"});
  refused("fit-linear", fit + "--validation-data v.csv", {"lpvid fit-linear: --validation-data was renamed to --validation"});
  refused("fit-linear", fit + "--validation-u uVal", {"--validation-u was renamed to --validation-columns"});
  refused("fit-linear", fit + "--validation-y yVal", {"--validation-y was renamed to --validation-columns"});
  refused("compare", "--data d.csv --model m.json --plot p.png", {"lpvid compare: --plot was renamed to --plots DIR"});
  refused("tradeoff", "--data d.csv --model m.json --plot p.png", {"lpvid tradeoff: --plot was renamed to --plots"});
  refused("tradeoff", "--data d.csv --model m.json --no-plot", {"lpvid tradeoff: --no-plot is gone"});
  refused("generate", "example1 --out " + file("g.csv") + " --noise-variance 0.1",
          {"lpvid generate: --noise-variance was renamed to --noise-std"});
  EXPECT_FALSE(std::filesystem::exists(file("m.json")));
  EXPECT_FALSE(std::filesystem::exists(file("g.csv")));
}

TEST_F(RenamedOptions, IgnoredOptionsAreRefused) {
  const std::string certify = "--data d.csv --model m.json --program p.dat-s --solution p.sol ";
  refused("certify", certify + "--solver sdpa", {"lpvid certify: --solver", "solved outside"});
  refused("certify", certify + "--verbose", {"lpvid certify: --verbose"});
  const std::string plan = "plan --data d.csv --model m.json --dir J ";
  for (const char* o : {"--verbose", "--quiet"}) refused("jobs", plan + o, {std::string("lpvid jobs plan: ") + o});
  for (const char* o : {"--certificate c.json", "--report r.json", "--write-sdpa p.dat-s"})
    refused("jobs", plan + o, {"lpvid jobs plan: " + std::string(o).substr(0, std::string(o).find(' ')), "jobs merge"});
  refused("fit-linear", "--data d.csv --order 2 --max-order 3", {"--max-order", "--order auto"});
  // diagnose --max-degree was taken as the input limit on polynomial degrees
  refused("diagnose", "--data d.csv --model m.json --max-degree 3", {"--max-degree", "--degree"});
  // select-basis --max-degree was its candidate terms' degree: one meaning per name, now --degree as in diagnose
  refused("select-basis", "--data d.csv --model m.json --delta 0.1 --dmax 0.1 --max-degree 1", {"--max-degree", "--degree"});
}

TEST_F(RenamedOptions, HiddenFromHelp) {
  ASSERT_EQ(run("jobs", "plan --help"), 0);
  for (const char* o : {"--window ", "--certificate", "--report", "--write-sdpa", "--verbose"})
    EXPECT_EQ(output().find(o), std::string::npos) << o << "\n" << output();
  EXPECT_NE(output().find("--window-length"), std::string::npos);
  ASSERT_EQ(run("certify", "--help"), 0);
  EXPECT_EQ(output().find("--solver "), std::string::npos) << output();  // --solver-exit-code stays
}

TEST_F(RenamedOptions, FitLinearHalfValidationPairIsRefused) {
  // --u u1,u2 --y y1: three validation columns, inputs then output
  ASSERT_EQ(run("generate", "example1 --n 40 --out " + file("d.csv")), 0) << output();
  const std::string base = "--data " + file("d.csv") + " --u u1,u2 --y y1 --order 1 --model-out " + file("m.json");
  refused("fit-linear", base + " --validation-columns u1,u2", {"--validation-columns", "3 here", "got 2"});
  EXPECT_FALSE(std::filesystem::exists(file("m.json")));
  EXPECT_EQ(run("fit-linear", base + " --validation-columns u1,u2,y1"), 0) << output();
  EXPECT_NE(output().find("rms_validation"), std::string::npos) << output();
}

TEST_F(RenamedOptions, DidYouMean) {
  refused("diagnose", "--data d.csv --model m.json --max-efects 2", {"unknown option --max-efects; did you mean --max-effects?"});
  refused("jobs", "plan --data d.csv --model m.json --dir J --window-lenght 5", {"did you mean --window-length?"});
  refused("fit-linear", "--data d.csv --modle-out m.json", {"did you mean --model-out?"});
  refused("invalidate", "--data d.csv --model m.json --certifcate c.json", {"did you mean --certificate?"});
  refused("tradeoff", "--data d.csv --model m.json --plot p.png", {"lpvid tradeoff: --plot was renamed to --plots"});
  refused("tradeoff", "--data d.csv --model m.json --no-plot", {"lpvid tradeoff: --no-plot is gone"});
  refused("generate", "example1 --out g.csv --sed 3", {"did you mean --seed?"});
  EXPECT_EQ(run_program(verify_exe, "certificate c.json --dta d.csv"), 2) << output();
  EXPECT_NE(output().find("lpvid-verify certificate: unknown option --dta; did you mean --data?"), std::string::npos)
      << output();
  refused("diagnose", "--data d.csv --model m.json --zzzzzzzzzz 1", {"not expected"});  // nothing close: no guess
  EXPECT_EQ(output().find("did you mean"), std::string::npos) << output();
}

}  // namespace
}  // namespace lpvid
