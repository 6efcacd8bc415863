// A tested program cannot leave a process behind to work on later cases.
// The outside command below answers a wrong claim (d_max = 0 on noisy data:
// lpvid's lower end refutes it) and starts, detached in a session of its own
// (setsid), a swapper that keeps replacing the data.csv of every case folder
// of the run — lpvid's copies (*.lpvid) and the commands' copies, the next
// case's as soon as it exists — with all-zero data (on which d_max = 0 is
// right) and putting the original back a moment later. Left running, such a
// process swapped lpvid's copy of a later case between its writing and its
// reading and restored it before the byte comparison: false "confirmed"
// verdicts. Every case must be refuted or tampered, never confirmed; the
// swapper must be killed when its command ends and named in the report.
#include <gtest/gtest.h>

#include <signal.h>

#include <cerrno>
#include <string>

#include "support/cli_runner.h"

namespace lpvid {
namespace {

// $1 data, $2 task, $3 out, $4 dir, $5 the folder for the swapper's pid
const char* kHostile = R"(work=$(dirname "$4"); pidfile="$5/$(basename "$4").pid"
setsid sh -c '
  echo $$ > "$2"
  i=0
  while [ -d "$1" ] && [ $i -lt 3000 ]; do
    for f in "$1"/*.lpvid/data.csv "$1"/case-*/data.csv; do
      [ -f "$f" ] || continue
      awk -F, "BEGIN{OFS=\",\"} NR==1{print;next}{for(i=1;i<=NF;i++)\$i=0;print}" "$f" > "$f.zero" &&
        cp "$f" "$f.keep" && mv "$f.zero" "$f" && sleep 0.005 && mv "$f.keep" "$f"
    done
    i=$((i+1))
  done' swapper "$work" "$pidfile" < /dev/null > /dev/null 2>&1 &
while [ ! -s "$pidfile" ]; do sleep 0.01; done
printf '{"format": "lpvid-oracle-answer/1", "dmax": "0"}' > "$3"
)";

struct OracleSurvivor : gen::CliRunner {
  void SetUp() override {
    gen::CliRunner::SetUp();
    if (IsSkipped()) return;
    if (std::system("command -v setsid >/dev/null && awk 'BEGIN{}' && sleep 0.001") != 0)
      GTEST_SKIP() << "setsid, awk or a fractional sleep not found";
  }
};

TEST_F(OracleSurvivor, DetachedSwapperIsKilledAndNeverConfirms) {
  const int cases = 20;
  write_text(file("hostile.sh"), kHostile);
  std::filesystem::create_directories(file("pids"));
  const int code = run("oracle", "--quiet --cases " + std::to_string(cases) +
                                     " --seed 701 --min-n 12 --max-n 30 --kinds min_dmax --case-timeout 30 --command \"sh " +
                                     file("hostile.sh") + " {data} {task} {out} {dir} " + file("pids") + "\" --work " +
                                     file("work") + " --report " + file("report.json"));
  ASSERT_TRUE(std::filesystem::exists(file("report.json"))) << output();
  const nlohmann::json report = read_json(file("report.json"));
  ASSERT_EQ(report["cases"].size(), static_cast<size_t>(cases)) << output();
  int refuted_or_tampered = 0;
  for (const auto& c : report["cases"]) {
    const std::string name = c["case"].get<std::string>(), verdict = c["verdict"].get<std::string>();
    SCOPED_TRACE(name + ": " + verdict + ": " + c["reason"].get<std::string>());
    EXPECT_NE(verdict, "confirmed");
    refuted_or_tampered += verdict == "refuted" || verdict == "tampered";
    // the case's swapper is among the processes killed after its command ended
    const std::string pid = read_text(file("pids/" + name + ".pid"));
    ASSERT_FALSE(pid.empty());
    EXPECT_TRUE(c.contains("survivors")) << c.dump();
    bool named = false;
    if (c.contains("survivors"))
      for (const auto& s : c["survivors"]) named = named || s.get<std::string>().rfind(std::to_string(std::stol(pid)) + " (", 0) == 0;
    EXPECT_TRUE(named) << c["survivors"].dump() << " lacks the swapper " << pid;
    // and it is gone
    EXPECT_TRUE(::kill(static_cast<pid_t>(std::stol(pid)), 0) != 0 && errno == ESRCH) << "swapper " << pid << " still runs";
  }
  EXPECT_EQ(refuted_or_tampered, cases) << output();
  // the text report names them too, one line per case
  const std::string text = output();
  size_t lines = 0;
  for (size_t at = text.find("survivors killed after the command ended"); at != std::string::npos;
       at = text.find("survivors killed after the command ended", at + 1))
    ++lines;
  EXPECT_EQ(lines, static_cast<size_t>(cases)) << text;
  EXPECT_EQ(code, 3) << text;  // tampered cases are errors of the command
}

}  // namespace
}  // namespace lpvid
