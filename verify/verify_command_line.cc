// lpvid-verify: the exact verifier's command line (docs/design.md §10, §11), as a function
// (verify_command_line.h); verify_main.cc is the program.
//
//   lpvid-verify psd M.txt [--exact-only] [--threads N]
//       PD / PSD (exit 0), NOT_PSD (exit 1), bad input (exit 2), read failure (exit 6).
//   lpvid-verify certificate C.json
//       consistent (exit 0), invalid: <reason> (exit 1), malformed (exit 2), read failure (exit 6).
//   Limits on inputs (core/limits.h): --max-file-mb, --max-digits, --max-degree, --max-samples.
//   Limits on work (verify/psd/work_limits.h): --max-dual-order, --max-exact-work,
//   --max-total-work, --max-floating-work, --max-records; beyond them exit 8,
//   nothing decided.
//
// Each subcommand is registered by one add_*_subcommand function below and
// run by the dispatch in run_lpvid_verify(). Usage errors exit with 2 (like
// bad input).

#include "verify/verify_command_line.h"

#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/argv_words.h"
#include "core/eigen_blocking.h"
#include "core/limit_options.h"
#include "core/option_suggestion.h"
#include "verify/certificate/certificate_check.h"
#include "verify/psd/psd_command.h"
#include "verify/psd/work_limits.h"

namespace {

struct PsdArgs {
  std::string file;
  lpvid::PsdCommandOptions options;
};

CLI::App* add_psd_subcommand(CLI::App& app, PsdArgs& args) {
  CLI::App* psd = app.add_subcommand("psd", "Decide exactly whether a rational symmetric matrix is PD, PSD or not PSD");
  psd->add_option("file", args.file, "matrix file: one row per line, exact decimals or p/q, '#' comments")
      ->required();
  psd->add_flag("--exact-only", args.options.exact_only,
                "skip the floating-point filter; decide by exact LDL^T only");
  psd->add_option("--threads", args.options.threads, "threads for the exact elimination (0: all cores, max 8)")
      ->check(CLI::Range(0, 64));
  psd->footer("Exit status: 0 PD or PSD, 1 NOT_PSD, 2 missing/invalid/non-symmetric/too large input, 6 read failure, "
              "8 the exact path would exceed --max-exact-work or --max-total-work (not decided).");
  return psd;
}

struct CertificateArgs {
  std::string file, data;
};

CLI::App* add_certificate_subcommand(CLI::App& app, CertificateArgs& args) {
  CLI::App* c = app.add_subcommand("certificate", "Check an lpvid certificate exactly, from the data text to the PSD decision");
  c->add_option("file", args.file, "certificate (lpvid-certificate/1 JSON)")->required();
  c->add_option("--data", args.data,
                "the data file to read instead of the recorded path (its sha256 must still match); without it a "
                "missing recorded path falls back to the file of the same name beside the certificate");
  c->footer("Exit status: 0 the claim holds, 1 invalid (with the reason), 2 missing/malformed/too large input, 6 read "
            "failure, 8 the check would exceed --max-dual-order, --max-exact-work, --max-total-work, --max-floating-work or "
            "--max-records "
            "(not decided).");
  return c;
}

/// The work limits as options (given before or after the subcommand).
void add_work_limit_options(CLI::App& app) {
  lpvid::VerifyWorkLimits& l = lpvid::verify_work_limits();
  app.add_option("--max-dual-order", l.max_dual_order,
                 "largest order L*ny of the matrix U a compact dual certificate makes the verifier rebuild "
                 "(floating inversion, O(order^3); default " + std::to_string(lpvid::kDefaultMaxDualOrder) + ")")
      ->check(CLI::Range(1L, 1000000L));
  app.add_option("--max-exact-work", l.max_exact_work,
                 "most modular operations of one exact elimination, estimated before it starts (default " +
                     std::to_string(static_cast<long long>(lpvid::kDefaultMaxExactWork)) + ")")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-total-work", l.max_total_work,
                 "most operations of one whole check (the dual points' exact sums, records, data bytes, the exact "
                 "simulation with its digit growth, exact eliminations), estimated before the work starts (default " +
                     std::to_string(static_cast<long long>(lpvid::kDefaultMaxTotalWork)) + ")")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-floating-work", l.max_floating_work,
                 "most floating multiply-adds of one whole check's cubic steps, whose memory is bounded by their "
                 "order (compact dual points' rebuilds, class leaves, the (C1) proof in doubles on a long horizon), "
                 "estimated before the work starts (default " +
                     std::to_string(static_cast<long long>(lpvid::kDefaultMaxFloatingWork)) + ")")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-records", l.max_records,
                 "most records one certificate may name (default " + std::to_string(lpvid::kDefaultMaxRecords) + ")")
      ->check(CLI::Range(1L, 100000000L));
}

/// Puts the caller's work limits back when a run ends (the Python module
/// runs lpvid-verify and lpvid in one process; the library runs unlimited).
class WorkLimitsRestorer {
 public:
  WorkLimitsRestorer() : saved_(lpvid::verify_work_limits()) {
    lpvid::verify_work_limits() = lpvid::default_verify_work_limits();
    lpvid::start_total_work();
  }
  ~WorkLimitsRestorer() { lpvid::verify_work_limits() = saved_; }
  WorkLimitsRestorer(const WorkLimitsRestorer&) = delete;
  WorkLimitsRestorer& operator=(const WorkLimitsRestorer&) = delete;

 private:
  lpvid::VerifyWorkLimits saved_;
};

/// The whole command line: the app with its two subcommands and the limit
/// options, and the arguments they fill. Built in place: the options hold
/// pointers to its members.
struct VerifyCommandLine {
  CLI::App app{"lpvid-verify: exact verifier for lpvid (no floating-point answer is trusted)"};
  PsdArgs psd_args;
  CertificateArgs certificate_args;
  CLI::App* psd = nullptr;
  CLI::App* certificate = nullptr;

  VerifyCommandLine() {
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("lpvid-verify ") + LPVID_VERSION);
    lpvid::add_limit_options(app);
    add_work_limit_options(app);
    psd = add_psd_subcommand(app, psd_args);
    certificate = add_certificate_subcommand(app, certificate_args);
  }
  VerifyCommandLine(const VerifyCommandLine&) = delete;
  VerifyCommandLine& operator=(const VerifyCommandLine&) = delete;
};

}  // namespace

namespace lpvid {

OptionTable lpvid_verify_option_table() {
  const VerifyCommandLine line;
  OptionTable table;
  add_option_table(line.app, "lpvid-verify", table);
  return table;
}

int run_lpvid_verify(const std::vector<std::string>& args, const std::string& program) {
  pin_eigen_blocking();  // its floating-point screens as lpvid's (core/eigen_blocking.h)
  // A previous call in the same process may have changed the limits.
  input_limits() = InputLimits{};
  const WorkLimitsRestorer work_limits;  // lpvid-verify's defaults for this run
  VerifyCommandLine line;
  CLI::App& app = line.app;

  ArgvWords argv(program, args);  // parsed as main()'s argv is
  try {
    app.parse(argv.argc(), argv.argv());
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help or the usage error
    if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr)  // a misspelt option: "did you mean --x?"
      print_option_suggestions(app, lpvid_verify_option_table(), "lpvid-verify", args, std::cerr);
    return code == 0 ? 0 : kPsdExitBadInput;
  }

  // Dispatch: one branch per subcommand.
  if (line.psd->parsed()) return run_psd_command(line.psd_args.file, std::cout, std::cerr, line.psd_args.options);
  if (line.certificate->parsed())
    return run_certificate_command(line.certificate_args.file, std::cout, std::cerr, line.certificate_args.data);

  std::cerr << "lpvid-verify: no subcommand\n";
  return kPsdExitBadInput;
}

}  // namespace lpvid
