// Uses the whole library (lpvid::lib): Theorem 2.1 for the true model of the
// paper's Example 1 on its data, solved by CSDP and written as a certificate;
// then the certificate is checked exactly with the verifier's API, and a
// tampered copy (δ² = d_max² = 0) must be rejected.
//   certify_and_check FIXTURE_DIR CERTIFICATE_OUT
// Exit 0 when every result is the expected one, 1 otherwise, 2 on bad input.
#include <filesystem>
#include <iostream>
#include <string>

#include "core/input_error.h"
#include "data/csv_reader.h"
#include "data/experiment_builder.h"
#include "certify/certificate_files.h"
#include "certify/certify.h"
#include "data/data_reference.h"
#include "model/model_file.h"
#include "solvers/solver_factory.h"
#include "verify/certificate/certificate_check.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: certify_and_check FIXTURE_DIR CERTIFICATE_OUT\n";
    return 2;
  }
  const std::string dir = argv[1], out = argv[2];
  try {
    using lpvid::Rational;
    const auto model = lpvid::read_model_file<Rational>(dir + "/true_model.json");
    lpvid::CertifyOptions options;  // minimise 0.5·δ² + 0.5·d_max²
    const lpvid::DataTable data = lpvid::read_data_table(dir + "/noise_free_n40.csv");
    options.records = {data.reference};  // the certificate names this file and its sha256 (one record)
    options.lower_end = false;  // only the primal certificate
    const auto exp = lpvid::make_experiment<Rational>(data.table, model.columns);
    const auto solver = lpvid::make_solver("csdp");
    const lpvid::CertifiedBounds b = lpvid::certify_fixed_model(model, exp, options, *solver);
    lpvid::write_certificates(b, out);  // certification computes in memory; the files are the caller's
    std::cout << "certify_fixed_model: " << (b.verified() ? "verified" : "not verified: " + b.reason) << ", delta <= "
              << b.delta << ", dmax <= " << b.dmax << "\n";

    // The program's own check, independent of what certify_fixed_model said.
    const lpvid::CertificateVerdict v = lpvid::check_certificate_file(out);
    std::cout << "verifier: " << (v.holds ? v.claim_text : "invalid: " + v.reason) << "\n";

    lpvid::Certificate tampered = lpvid::read_certificate(out);
    tampered.delta2 = 0;
    tampered.dmax2 = 0;
    std::string folder = std::filesystem::path(out).parent_path().string();
    const lpvid::CertificateVerdict t = lpvid::check_certificate(tampered, folder.empty() ? "." : folder);
    std::cout << "tampered (delta2 = dmax2 = 0): " << (t.holds ? "holds (WRONG)" : "rejected: " + t.reason) << "\n";

    const bool ok = b.verified() && v.holds && v.claim_text == "consistent" && !t.holds;
    std::cout << (ok ? "all results as expected\n" : "some result is not the expected one\n");
    return ok ? 0 : 1;
  } catch (const lpvid::InputError& e) {
    std::cerr << "input error: " << e.what() << "\n";
    return 2;
  }
}
