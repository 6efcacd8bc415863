// `lpvid oracle` cannot be fooled by the program it tests. Each attack is a
// small shell script used as the outside command: it answers a fixed claim
// and, on the side, edits its own case's inputs, lpvid's copy of them,
// later cases' data or their task's tolerance. The claims are known wrong
// by construction: d_max = 0 on noisy random data (the control run, without
// the edit, must refute it), d_max = 1000 or ten times lpvid's own certified
// d_max. An edited input of its own case makes the case "tampered";
// edits of other cases change nothing: every case is judged on lpvid's copy
// with the command line's tolerance.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "support/cli_runner.h"

namespace lpvid {
namespace {

struct OracleAttack : gen::CliRunner {
  void SetUp() override {
    gen::CliRunner::SetUp();
    if (IsSkipped()) return;
    if (std::system("awk 'BEGIN{}' && sed --version >/dev/null 2>&1 && python3 -c 'import json'") != 0)
      GTEST_SKIP() << "awk, GNU sed or python3 not found";
  }
  /// Runs the oracle with `script` ($1 data, $2 task, $3 out, $4 dir) on
  /// `cases` random min_dmax cases; returns the verdict counts.
  std::map<std::string, int> attack(const std::string& name, const std::string& script, int cases, int* code) {
    write_text(file(name + ".sh"), script);
    *code = run("oracle", "--quiet --cases " + std::to_string(cases) +
                              " --seed 501 --min-n 12 --max-n 40 --kinds min_dmax --command \"sh " + file(name + ".sh") +
                              " {data} {task} {out} {dir}\" --work " + file(name) + " --report " + file(name + ".json") +
                              " --junit " + file(name + ".xml"));
    std::map<std::string, int> v;
    if (!std::filesystem::exists(file(name + ".json"))) return {{"no report", 1}};
    const nlohmann::json report = read_json(file(name + ".json"));
    for (const auto& c : report["cases"]) ++v[c["verdict"].get<std::string>()];
    return v;
  }
};

const std::string kClaimZero = "printf '{\"format\": \"lpvid-oracle-answer/1\", \"dmax\": \"0\"}' > \"$3\"\n";
const std::string kClaimHuge = "printf '{\"format\": \"lpvid-oracle-answer/1\", \"dmax\": \"1000\"}' > \"$3\"\n";
// every other case folder beside the command's own (its own and lpvid's copy of it skipped)
const std::string kOtherCases =
    "me=$(basename \"$4\")\n"
    "for d in \"$4\"/../case-*; do\n"
    "  case \"$(basename \"$d\")\" in \"$me\"|\"$me.lpvid\") continue;; esac\n";

struct Attack {
  const char* name;
  std::string script;
  std::map<std::string, int> at_least;  ///< verdict -> fewest cases
  std::vector<std::string> never;       ///< verdicts no case may get
  int exit_code;
};

TEST_F(OracleAttack, NoEditOfAnyCaseChangesAVerdict) {
  const int n = 5;
  int code = 0;
  // the control: the claim d_max = 0 is refuted by lpvid's lower end
  const auto control = attack("control", kClaimZero, n, &code);
  ASSERT_GE(control.count("refuted") ? control.at("refuted") : 0, n - 1) << output();

  const std::vector<Attack> attacks = {
      // measured before: 5/5 refutations became "undecided", exit 0
      {"own data", "printf '\\n' >> \"$1\"\n" + kClaimZero, {{"tampered", n}}, {"refuted", "undecided", "confirmed"}, 3},
      {"lpvid's copy", "printf '\\n' >> \"$4/../$(basename \"$4\").lpvid/data.csv\"\n" + kClaimZero, {{"tampered", n}},
       {"refuted", "undecided", "confirmed"}, 3},
      {"own tolerance", "sed -i 's/\"tolerance\": [^,}]*/\"tolerance\": 1e9/' \"$2\"\n" + kClaimHuge, {{"tampered", n}},
       {"confirmed", "suboptimal"}, 3},
      // measured before: the wrong claims of the later cases "confirmed"; this
      // edit (every number 0) made the whole run stop (exit 2, no report)
      {"later data",
       kOtherCases +
           "  [ -f \"$d/data.csv\" ] && awk -F, 'BEGIN{OFS=\",\"} NR==1{print;next}{for(i=1;i<=NF;i++)$i=0;print}' "
           "\"$d/data.csv\" > \"$d/z\" && mv \"$d/z\" \"$d/data.csv\"\ndone\n" +
           kClaimZero,
       {{"refuted", n - 1}}, {"confirmed", "tampered"}, 1},
      // measured before: answers 100 times too large (lpvid's own d_max times 10,
      // tests/oracle/toy_impls.py) "confirmed" under "tolerance": 1e9
      {"later tolerance",
       kOtherCases + "  [ -f \"$d/task.json\" ] && sed -i 's/\"tolerance\": [^,}]*/\"tolerance\": 1e9/' \"$d/task.json\"\ndone\n" +
           "exec python3 " + std::string(LPVID_SOURCE_DIR) + "/tests/oracle/toy_impls.py inflated " + exe +
           " \"$1\" \"$4/model.json\" \"$2\" \"$3\"\n",
       {{"suboptimal", n - 1}}, {"confirmed", "tampered"}, 0},
  };
  for (size_t k = 0; k < attacks.size(); ++k) {
    const Attack& a = attacks[k];
    SCOPED_TRACE(a.name);
    const auto v = attack("attack" + std::to_string(k), a.script, n, &code);
    for (const auto& [verdict, fewest] : a.at_least) EXPECT_GE(v.count(verdict) ? v.at(verdict) : 0, fewest) << output();
    for (const std::string& verdict : a.never) EXPECT_EQ(v.count(verdict), 0u) << verdict << "\n" << output();
    EXPECT_EQ(code, a.exit_code) << output();
  }
  // a tampered case is an error in the CI's JUnit file, with its reason
  const std::string junit = read_text(file("attack0.xml"));
  EXPECT_NE(junit.find("errors=\"5\""), std::string::npos) << junit.substr(0, 400);
  EXPECT_NE(junit.find("<error type=\"tampered\""), std::string::npos) << junit.substr(0, 800);
}

}  // namespace
}  // namespace lpvid
