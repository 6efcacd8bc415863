// The certificate reader and checker on corrupted certificates (the
// most exposed parser; these tests run in the ASan/UBSan build too, see
// scripts/test.sh --sanitize). A genuine certificate of the true Example-1
// model on its noise-free data is made once; then
//  - random byte edits (gen::files::corrupted) and
//  - a number field replaced by hostile number text
// must end in the documented outcomes of `lpvid-verify certificate`: 0
// (claim holds), 1 (claim does not hold) or 2 (malformed), never a crash or
// another exception, and a malformed file is never reported as "consistent".
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <string>

#include "data/csv_reader.h"
#include "data/experiment_builder.h"
#include "certify/certificate_files.h"
#include "certify/certify.h"
#include "data/data_reference.h"
#include "model/model_file.h"
#include "support/fixtures.h"
#include "support/gen_files.h"
#include "support/scratch_dir.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/certificate_file.h"
#include "solvers/solver_factory.h"

namespace lpvid {
namespace {

/// The genuine certificate's text and the data file it names (made once).
struct Genuine {
  gen::ScratchDir dir{"corruption"};
  std::string text;
  Genuine() {
    const std::string data = dir.file("data.csv"), cert = dir.file("c.json");
    {
      std::ifstream in(gen::kExample1Fixtures + "noise_free_n40.csv", std::ios::binary);
      std::ofstream(data, std::ios::binary) << in.rdbuf();
    }
    const LpvModel<Rational> model = read_model_file<Rational>(gen::kExample1Fixtures + "true_model.json");
    const Experiment<Rational> exp = make_experiment<Rational>(read_table(data), model.columns);
    CertifyOptions o;
    o.objective.kind = BoundObjective::Kind::kWeighted;
    o.records = {read_data_table(data).reference};
    o.lower_end = false;
    auto solver = make_solver("csdp");
    const CertifiedBounds b = certify_fixed_model(model, exp, o, *solver);
    write_certificates(b, cert);
    if (!b.verified()) throw std::runtime_error("the genuine certificate did not verify: " + b.reason);
    std::ifstream in(cert, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    text = s.str();
  }
  /// Runs `lpvid-verify certificate` on `text` written next to the data.
  int check(const std::string& t, std::string* out_text = nullptr) const {
    const std::string path = dir.file("t.json");
    std::ofstream(path, std::ios::binary) << t;
    std::ostringstream out, err;
    const int code = run_certificate_command(path, out, err);
    if (out_text) *out_text = out.str() + err.str();
    return code;
  }
};

const Genuine& genuine() {
  static const Genuine g;
  return g;
}

TEST(CertificateParse, TheGenuineCertificateHolds) {
  std::string out;
  EXPECT_EQ(genuine().check(genuine().text, &out), 0) << out;
}

RC_GTEST_PROP(CertificateParse, CorruptedBytesEndInADocumentedOutcome, ()) {
  const std::string bad = *gen::files::corrupted(genuine().text);
  std::string out;
  const int code = genuine().check(bad, &out);
  RC_LOG() << out;
  RC_ASSERT(code == 0 || code == 1 || code == 2);
  // A claim that holds comes from a file the reader accepts (an edit in the
  // free "info" part, or one that keeps the JSON and the numbers valid).
  if (code == 0) parse_certificate(bad, "corrupted");
}

// Every number of the certificate is a JSON string; replace one of them
// (chosen at random) by hostile text.
RC_GTEST_PROP(CertificateParse, HostileNumberTextIsRejectedOrJudged, ()) {
  const std::string& text = genuine().text;
  std::vector<size_t> starts;  // opening quotes of string values that start like a number
  const size_t info = text.find("\"info\"");  // the free part, never read by the verifier
  for (size_t i = 0; i + 1 < std::min(info, text.size()); ++i)
    if (text[i] == '"' && i > 0 && (text[i - 1] == ' ' || text[i - 1] == '[') &&
        (std::isdigit(static_cast<unsigned char>(text[i + 1])) || text[i + 1] == '-'))
      starts.push_back(i);
  RC_PRE(!starts.empty());
  const size_t open = starts[*rc::gen::inRange<size_t>(0, starts.size())];
  const size_t close = text.find('"', open + 1);
  const std::string hostile = *rc::gen::element<std::string>(
      "1e4001", "-1e-4001", "1/0", "nan", "inf", "0x10", "1e", "--1", "1/-0", "", " ", "1.2.3", "1/3/5",
      "9" + std::string(60000, '9'), "1/" + std::string(60000, '7'), "1e99999999999999999999");
  std::string bad = text;
  bad.replace(open + 1, close - open - 1, hostile);
  std::string out;
  const int code = genuine().check(bad, &out);
  RC_LOG() << "replaced " << text.substr(open, std::min<size_t>(close - open + 1, 40)) << " by '"
           << hostile.substr(0, 20) << "': " << out.substr(0, 300);
  RC_ASSERT(code == 1 || code == 2);
}

}  // namespace
}  // namespace lpvid
