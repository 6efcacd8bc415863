// A window job of `lpvid jobs` reads only its rows, and merge checks every
// certificate on the data file read once. Known answers by construction:
//  - the window B:E of a record IS a file holding only those rows, so the
//    job on the record and the same run on that file certify the same thing
//    (certificates equal apart from the data reference);
//  - a cell outside the window is never read: a non-number there changes
//    nothing but the file's sha256;
//  - the exact check on a table read once gives the path form's verdicts,
//    and a table of other bytes (another sha256) is refused as changed data.
#include <gtest/gtest.h>

#include <sstream>

#include "data/data_reference.h"
#include "support/jobs_windows.h"
#include "verify/certificate/certificate_check.h"

namespace lpvid {
namespace {

struct JobsRows : gen::JobsMerge {
  /// `lpvid invalidate` of the true model at delta 0.45 on `data` (rows: "" or " --rows B:E"), certificate `name`.
  int window_job(const std::string& data, const std::string& rows, const std::string& name) {
    return run("invalidate", "--quiet --data " + data + rows + " --model " + file("true.json") + " --delta 0.45 --certificate " +
                                 file(name) + " --report " + file(name + ".report.json"));
  }
  /// The certificate at `name` without its data reference (file, sha256, rows).
  nlohmann::json without_data(const std::string& name) {
    nlohmann::json j = read_json(file(name));
    j.erase("data");
    return j;
  }
  /// Lines of d.csv: the header and then rows; `edit(k, line)` may change data row k.
  std::string rewritten(const std::function<std::string(int, const std::string&)>& edit) {
    std::istringstream in(read_text(file("d.csv")));
    std::string line, out;
    std::getline(in, line);
    out = line + "\n";
    for (int k = 0; std::getline(in, line); ++k) {
      const std::string edited = edit(k, line);
      if (!edited.empty()) out += edited + "\n";
    }
    return out;
  }
};

TEST_F(JobsRows, AWindowJobCertifiesItsRowsAsAFileOfOnlyThoseRowsAndReadsNoOtherCell) {
  make_data();
  // rows 0:60 as a file of their own; and the record with a non-number in row 100 (outside the window)
  write_text(file("window.csv"), rewritten([](int k, const std::string& l) { return k < 60 ? l : std::string(); }));
  write_text(file("bad.csv"), rewritten([](int k, const std::string& l) {
               return k == 100 ? l.substr(0, l.find(',')) + ",oops" + l.substr(l.find(',', l.find(',') + 1)) : l;
             }));
  ASSERT_EQ(window_job(file("d.csv"), " --rows 0:60", "record.cert.json"), 0) << output();
  ASSERT_EQ(window_job(file("window.csv"), "", "window.cert.json"), 0) << output();
  ASSERT_EQ(window_job(file("bad.csv"), " --rows 0:60", "bad.cert.json"), 0) << output();
  const nlohmann::json record = without_data("record.cert.json");
  EXPECT_EQ(record, without_data("window.cert.json"));
  EXPECT_EQ(record, without_data("bad.cert.json"));
  EXPECT_EQ(read_json(file("bad.cert.json"))["data"]["rows"], nlohmann::json::array({0, 60}));
  for (const char* lower : {"record.cert.lower.json", "window.cert.lower.json", "bad.cert.lower.json"})
    ASSERT_TRUE(std::filesystem::exists(file(lower))) << lower;
  EXPECT_EQ(without_data("record.cert.lower.json"), without_data("window.cert.lower.json"));
  EXPECT_EQ(without_data("record.cert.lower.json"), without_data("bad.cert.lower.json"));
  // the verifier, too, reads only the certified rows
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("bad.cert.json")), 0) << output();
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("bad.cert.lower.json")), 0) << output();
  // a window over the bad cell is refused, naming it
  EXPECT_EQ(window_job(file("bad.csv"), " --rows 60:120", "over.cert.json"), 2) << output();
  EXPECT_NE(output().find("oops"), std::string::npos) << output();
}

TEST_F(JobsRows, ACheckOnTheDataReadOnceGivesThePathFormsVerdictsAndRefusesOtherBytes) {
  plan_and_run("--delta 0.45 --dmax 0.05");  // window 0 consistent, window 1 invalidated
  const DataTable data = read_data_table(file("d.csv"));
  for (const char* name : {"J/w00000.cert.json", "J/w00001.cert.json"}) {
    const Certificate c = read_certificate(file(name));
    const CertificateVerdict once = check_certificate(c, data);
    const CertificateVerdict path = check_certificate_file(file(name), file("d.csv"));
    EXPECT_TRUE(once.holds) << name << ": " << once.reason;
    EXPECT_EQ(once.holds, path.holds) << name;
    EXPECT_EQ(once.claim_text, path.claim_text) << name;
    EXPECT_EQ(once.details, path.details) << name;
  }
  EXPECT_EQ(to_string(read_certificate(file("J/w00001.cert.json")).claim), std::string("invalidated"));
  // one byte more: another sha256, refused as changed data before any check
  write_text(file("d2.csv"), read_text(file("d.csv")) + "\n");
  const CertificateVerdict changed = check_certificate(read_certificate(file("J/w00000.cert.json")), read_data_table(file("d2.csv")));
  EXPECT_FALSE(changed.holds);
  EXPECT_NE(changed.reason.find("has changed"), std::string::npos) << changed.reason;
}

}  // namespace
}  // namespace lpvid
