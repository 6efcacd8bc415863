// A certificate names its data file by the path it was written with. Moved
// together with its data it still checks (the file of the same name beside
// it), `--data` names the file explicitly, and in every case only the
// sha256 decides: a different file under the right name is refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/cli_runner.h"

namespace lpvid {
namespace {

using gen::CliRunner;
namespace fs = std::filesystem;

struct MovedCertificate : CliRunner {};

TEST_F(MovedCertificate, ChecksBesideItsDataOrWithDataAndOnlyTheHashDecides) {
  ASSERT_EQ(run("generate", "example1 --n 40 --noise-std 0.1 --out " + file("d.csv") + " --truth-out " +
                                file("true.json")),
            0)
      << output();
  ASSERT_EQ(run("invalidate", "--data " + file("d.csv") + " --model " + file("true.json") + " --delta 0.1 --dmax 0.3 " +
                                  "--certificate " + file("c.json") + " --report " + file("r.json")),
            0)
      << output();
  fs::create_directories(file("moved"));
  fs::rename(file("c.json"), file("moved/c.json"));
  fs::rename(file("d.csv"), file("moved/d.csv"));
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("moved/c.json")), 0) << output();
  EXPECT_NE(output().find("moved/d.csv"), std::string::npos) << output();  // says which file it read

  fs::rename(file("moved/d.csv"), file("elsewhere.csv"));
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("moved/c.json")), 2) << output();  // no data anywhere
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("moved/c.json") + " --data " + file("elsewhere.csv")), 0)
      << output();

  // another file under the data's name: refused by the hash
  std::ofstream(file("moved/d.csv")) << "u1,u2,y1,y2,rho1,rho2\n0,0,0,0,0.5,0.5\n";
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("moved/c.json")), 1) << output();
  EXPECT_NE(output().find("sha256"), std::string::npos) << output();
}

}  // namespace
}  // namespace lpvid
