#pragma once
/// Resource limits on untrusted input: every reader checks them
/// and names the limit and how to raise it, so that a hostile or mistaken
/// input ends quickly with exit code 2 instead of exhausting memory or time.
///
/// The defaults live here, once. They are process-wide because the readers
/// sit deep below the commands; `lpvid` and `lpvid-verify` bind their
/// top-level options (--max-file-mb, --max-digits, --max-degree,
/// --max-samples) to this struct before running a command.
///
/// Sizes of real inputs, for scale: the cascaded-tanks CSV is 60 KB; a dual
/// ("lower bound") certificate of a 400-sample window is 220 MB with entries
/// of 16 000 digits; polynomial degrees of diagnose's effects (docs/design.md §9.2) are ≤ 5.

#include <cstdint>
#include <string>

namespace lpvid {

struct InputLimits {
  /// Largest input file read (data, model, certificate, matrix, SDPA), bytes.
  std::uintmax_t max_file_bytes = std::uintmax_t{1} << 30;  // 1 GiB
  /// Most decimal digits in one number's text ("p/q": p and q together;
  /// a decimal exponent counts as that many digits: 1e4000 has 4001).
  long max_number_digits = 50000;
  /// Highest exponent of one variable in a monomial and highest degree of a
  /// static polynomial map.
  int max_degree = 64;
  /// Most samples (rows) in a data record or horizon of a certificate.
  long max_samples = 1000000;
};

/// The process-wide limits (defaults above until a CLI changes them).
InputLimits& input_limits();

/// " (limit L; raise it with OPTION)" for messages.
std::string limit_hint(long double limit, const std::string& option);

}  // namespace lpvid
