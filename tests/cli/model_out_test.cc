// identify --model-out writes the exact model its bounds are about: Theorem
// 2.1 on that file (lpvid invalidate, the same objective) is the same
// problem, so its certified interval must overlap identify's (both are
// certified enclosures of one optimum).
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "support/cli_runner.h"

namespace lpvid {
namespace {

using gen::CliRunner;

struct ModelOut : CliRunner {};

TEST_F(ModelOut, InvalidateOnTheWrittenModelReproducesIdentifysInterval) {
  ASSERT_EQ(run("generate", "example1 --n 50 --noise-std 0.1 --out " + file("d.csv") + " --model-out " +
                                file("init.json")),
            0)
      << output();
  ASSERT_EQ(run("identify", "--data " + file("d.csv") + " --model " + file("init.json") + " --delta 0.3 --model-out " +
                                file("id.json") + " --report " + file("id_report.json")),
            0)
      << output();
  ASSERT_EQ(run("invalidate", "--data " + file("d.csv") + " --model " + file("id.json") + " --delta 0.3 --report " +
                                  file("inv_report.json")),
            0)
      << output();
  EXPECT_NE(output().find("no correction"), std::string::npos) << output();  // θ is folded in
  const nlohmann::json a = read_json(file("id_report.json"))["interval"];
  const nlohmann::json b = read_json(file("inv_report.json"))["interval"];
  ASSERT_TRUE(a["lower_verified"].get<bool>() && a["upper_verified"].get<bool>()) << a.dump();
  ASSERT_TRUE(b["lower_verified"].get<bool>() && b["upper_verified"].get<bool>()) << b.dump();
  EXPECT_LE(a["lower"].get<double>(), b["upper"].get<double>());
  EXPECT_LE(b["lower"].get<double>(), a["upper"].get<double>());
  // and identify refuses an unwritable --model-out before any work
  EXPECT_EQ(run("identify", "--data " + file("d.csv") + " --model " + file("init.json") +
                                " --delta 0.3 --model-out /nonexistent_dir/m.json"),
            6)
      << output();
}

}  // namespace
}  // namespace lpvid
