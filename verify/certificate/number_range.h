#pragma once
/// Every number a certificate carries must lie in the range of a double,
/// |x| ≤ DBL_MAX ≈ 1.8·10³⁰⁸. The exact check never needs more, and the
/// verifier rounds numbers to doubles for its floating recipes and filters
/// (the compact dual's U, the filter's diagonal): a value beyond the range
/// would round to ±∞ there. Such a number is malformed input (exit 2), named
/// by its field, before any check runs. Free text (`info`, `data`, the
/// model's column names) is not looked at.

#include <string>
#include <string_view>

#include "json/json_tree.h"

namespace lpvid {

/// True when `text` is a decimal or p/q whose value has |x| > DBL_MAX
/// (false for texts that are no number).
bool number_text_overflows_double(std::string_view text);

/// Throws InputError "file:line: field: ..." for the first number (a JSON
/// number, or a string holding one) of the certificate tree `root` that
/// overflows a double.
void require_double_range(const JsonNode& root, const std::string& file);

}  // namespace lpvid
