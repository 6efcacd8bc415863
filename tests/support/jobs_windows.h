#pragma once
/// A record cut into two windows for the `lpvid jobs` tests, with a known
/// answer by construction: example1 data (noise RMS 0.01) whose y1 is
/// shifted by 0.3 from row 60 on, so the true model explains window 0
/// (rows 0-59) within (delta, dmax) = (0.45, 0.05) and not window 1.

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/number_text.h"
#include "support/cli_runner.h"

namespace lpvid::gen {

struct JobsMerge : CliRunner {
  /// example1, 120 rows, y1 shifted by 0.3 from row 60 on.
  void make_data() {
    ASSERT_EQ(run("generate", "example1 --n 120 --noise-std 0.01 --out " + file("g.csv") + " --truth-out " +
                                  file("true.json")),
              0)
        << output();
    std::istringstream in(read_text(file("g.csv")));
    std::string line, out;
    std::getline(in, line);
    ASSERT_EQ(line, "u1,u2,y1,y2,rho1,rho2");
    out = line + "\n";
    for (int k = 0; std::getline(in, line); ++k) {
      std::vector<std::string> cells;
      std::stringstream ss(line);
      for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
      ASSERT_EQ(cells.size(), 6u) << line;
      if (k >= 60) cells[2] = exact_decimal_or_fraction(rational_from_text(cells[2]) + rational_from_text("0.3"));
      for (size_t i = 0; i < cells.size(); ++i) out += (i ? "," : "") + cells[i];
      out += "\n";
    }
    write_text(file("d.csv"), out);
  }
  /// Plans with `objective` (e.g. "--delta 0.45 --dmax 0.05") and runs every job.
  void plan_and_run(const std::string& objective) {
    make_data();
    ASSERT_EQ(run("jobs", "plan --data " + file("d.csv") + " --model " + file("true.json") + " " + objective +
                              " --window-length 60 --dir " + file("J")),
              0)
        << output();
    run_program("bash", file("J/jobs.txt"));
  }
  /// Job k's command line with each (from, to) replaced once, run.
  int rerun_job(int k, const std::vector<std::pair<std::string, std::string>>& edits) {
    std::istringstream in(read_text(file("J/jobs.txt")));
    std::string line;
    for (int i = 0; i <= k; ++i) std::getline(in, line);
    for (const auto& [from, to] : edits) {
      const size_t at = line.find(from);
      EXPECT_NE(at, std::string::npos) << from << " not in " << line;
      if (at != std::string::npos) line.replace(at, from.size(), to);
    }
    write_text(file("job.sh"), line + "\n");
    return run_program("bash", file("job.sh"));
  }
  /// `lpvid jobs merge`; its report (null when none was written).
  nlohmann::json merge(int* code) {
    *code = run("jobs", "merge --quiet --dir " + file("J"));
    return std::filesystem::exists(file("J/merged.json")) ? read_json(file("J/merged.json")) : nlohmann::json();
  }
};


}  // namespace lpvid::gen
