#include "verify/psd/psd_command.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <new>
#include <ostream>
#include <stdexcept>
#include <string>

#include "core/exit_codes.h"
#include "core/file_io.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "core/stop_request.h"
#include "verify/psd/exact_psd.h"
#include "verify/psd/rational_matrix_io.h"
#include "verify/psd/work_limits.h"

namespace lpvid {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f s", s);
  return buf;
}

const char* method_text(PsdMethod m) {
  switch (m) {
    case PsdMethod::kFloatingFilter:
      return "filter (verified floating-point Cholesky, Rump 2006)";
    case PsdMethod::kWitnessCheck:
      return "filter (floating candidate vector, checked in exact arithmetic)";
    case PsdMethod::kExactLdlt:
      return "exact (LDL^T in integer arithmetic, no floating point)";
  }
  return "exact";
}

/// Witnesses of up to this size are printed in full.
constexpr Eigen::Index kPrintWitnessMax = 20;
/// v'Mv is recomputed for the report up to this size (it was already checked).
constexpr Eigen::Index kPrintFormMax = 200;

int decide_and_print(const std::string& path, std::ostream& out, const PsdCommandOptions& options) {
  const auto t0 = Clock::now();
  Mat<Rational> M = read_rational_matrix_file(path);
  const double read_time = seconds_since(t0);

  const auto t1 = Clock::now();
  PsdOptions psd_options;
  psd_options.use_filter = !options.exact_only;
  psd_options.threads = options.threads;
  PsdResult r = decide_psd(M, psd_options);
  const double decide_time = seconds_since(t1);

  out << verdict_word(r.verdict) << ' ' << r.reason << '\n';
  out << "  n: " << M.rows() << '\n';
  out << "  decided by: " << method_text(r.method) << (options.exact_only ? " [--exact-only]" : "") << '\n';
  if (r.rank >= 0) out << "  rank: " << r.rank << '\n';
  if (r.pivot_index >= 0) out << "  pivot index: " << r.pivot_index << " (0-based row of M)\n";
  if (r.verdict == PsdVerdict::kNotPsd && r.witness.size() > 0) {
    out << "  witness: vector v of size " << r.witness.size() << " with v'Mv < 0 (checked exactly)";
    if (M.rows() <= kPrintFormMax) out << ", v'Mv = " << rational_to_text(quadratic_form(M, r.witness));
    out << '\n';
    if (r.witness.size() <= kPrintWitnessMax) {
      out << "  v:";
      for (Eigen::Index i = 0; i < r.witness.size(); ++i) out << ' ' << rational_to_text(r.witness(i));
      out << '\n';
    }
  }
  out << "  time: read " << seconds_text(read_time) << ", decide " << seconds_text(decide_time) << '\n';
  return r.verdict == PsdVerdict::kNotPsd ? kPsdExitNotPsd : kPsdExitPsd;
}

}  // namespace

int run_psd_command(const std::string& path, std::ostream& out, std::ostream& err,
                    const PsdCommandOptions& options) {
  try {
    return decide_and_print(path, out, options);
  } catch (const Interrupted&) {
    err << "lpvid-verify psd: interrupted\n";  // a requested stop (core/stop_request.h): nothing decided
    return kExitInterrupted;
  } catch (const InputError& e) {
    err << "lpvid-verify psd: error: " << e.what() << '\n';
  } catch (const IoError& e) {
    err << "lpvid-verify psd: error: " << e.what() << '\n';
    return kPsdExitIo;
  } catch (const WorkLimitError& e) {
    err << "lpvid-verify psd: not decided: " << path << ": " << e.what() << '\n';
    return kPsdExitWorkLimit;
  } catch (const std::invalid_argument& e) {
    err << "lpvid-verify psd: error: " << path << ": " << e.what() << '\n';
  } catch (const std::bad_alloc&) {
    err << "lpvid-verify psd: error: " << path << ": out of memory\n";
  } catch (const std::exception& e) {
    err << "lpvid-verify psd: error: " << path << ": " << e.what() << '\n';
  } catch (...) {
    err << "lpvid-verify psd: error: " << path << ": unknown error\n";
  }
  return kPsdExitBadInput;
}

}  // namespace lpvid
