// Uses only lpvid::verify (no solver): reads Example 1's model and data
// exactly, decides positive (semi)definiteness of small rational matrices, and
// re-checks a certificate given on the command line.
//   exact_check FIXTURE_DIR [CERTIFICATE]
// Exit 0 when every result is the expected one, 1 otherwise, 2 on bad input.
#include <iostream>
#include <string>

#include "core/input_error.h"
#include "data/csv_reader.h"
#include "data/experiment_builder.h"
#include "model/model_file.h"
#include "verify/certificate/certificate_check.h"
#include "verify/psd/exact_psd.h"

namespace {

using lpvid::Mat;
using lpvid::PsdVerdict;
using lpvid::Rational;

bool expect(bool ok, const std::string& what) {
  std::cout << (ok ? "ok:       " : "FAILED:   ") << what << "\n";
  return ok;
}

bool check_psd(const Mat<Rational>& m, PsdVerdict expected, const std::string& name) {
  const lpvid::PsdResult r = lpvid::decide_psd(m);
  bool ok = r.verdict == expected;
  // A NOT_PSD verdict comes with v such that vᵀMv < 0 exactly.
  if (r.verdict == PsdVerdict::kNotPsd) ok = ok && lpvid::quadratic_form(m, r.witness) < 0;
  return expect(ok, name + ": " + lpvid::verdict_word(r.verdict) + " (" + r.reason + ")");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::cerr << "usage: exact_check FIXTURE_DIR [CERTIFICATE]\n";
    return 2;
  }
  const std::string dir = argv[1];
  try {
    bool ok = true;
    const auto model = lpvid::read_model_file<Rational>(dir + "/initial_model.json");
    const auto table = lpvid::read_csv(dir + "/noise_free_n40.csv");
    const auto exp = lpvid::make_experiment<Rational>(table, model.columns);
    ok &= expect(exp.n() == 40 && exp.nu() == 2 && exp.ny() == 2 && exp.n_rho() == 2,
                 "data: n = " + std::to_string(exp.n()) + " samples of u (2), y (2), rho (2), read exactly");

    // The inputs' Gram matrix UᵀU: positive definite (the two inputs are not
    // collinear); with u1 twice it is singular, and only an exact test says PSD.
    const Mat<Rational> u = exp.u;
    ok &= check_psd(u.transpose() * u, PsdVerdict::kPositiveDefinite, "U^T U");
    Mat<Rational> u11(u.rows(), 2);
    u11 << u.col(0), u.col(0);
    ok &= check_psd(u11.transpose() * u11, PsdVerdict::kPositiveSemidefinite, "[u1 u1]^T [u1 u1]");
    Mat<Rational> m(2, 2);
    m << Rational(1), Rational(2), Rational(2), Rational(1);
    ok &= check_psd(m, PsdVerdict::kNotPsd, "[1 2; 2 1]");

    if (argc == 3) {
      const lpvid::CertificateVerdict v = lpvid::check_certificate_file(argv[2]);
      ok &= expect(v.holds, std::string("certificate ") + argv[2] + ": " + (v.holds ? v.claim_text : "invalid: " + v.reason));
    }
    std::cout << (ok ? "all results as expected\n" : "some result is not the expected one\n");
    return ok ? 0 : 1;
  } catch (const lpvid::InputError& e) {
    std::cerr << "input error: " << e.what() << "\n";
    return 2;
  }
}
