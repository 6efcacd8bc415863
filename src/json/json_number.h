#pragma once
/// Exact numbers in JSON, read from an exact JSON tree (json_tree.h) and
/// written as nlohmann::ordered_json: shared by the model file
/// (model/model_file.h), the certificate file (verify/certificate/) and the
/// oracle's task and answer files (oracle/).
///
/// Reading: a JSON number or a string holding a decimal or `p/q` ("0.1",
/// "-1/3", "2.5e-3"), read from its *text* (core/number_text.h): exactly as a
/// rational (0.1 is 1/10), or as the nearest double of the same text.
///
/// Writing: a rational is a JSON integer when it is an integer that fits in
/// 64 bits, otherwise a string: a terminating decimal ("-0.3") when the
/// denominator is 2^a·5^b with at most 40 decimals, else "p/q". A double is a
/// JSON number in the shortest text that reads back as the same double.

#include <string>

#include <nlohmann/json.hpp>

#include "core/scalar.h"
#include "json/json_tree.h"

namespace lpvid {

/// The JSON value of a rational as described under "Writing".
nlohmann::ordered_json rational_to_json(const Rational& q);
/// The JSON value of a finite double (throws std::invalid_argument otherwise).
nlohmann::ordered_json double_to_json(double x);
/// rational_to_json or double_to_json.
inline nlohmann::ordered_json number_to_json(const Rational& q) { return rational_to_json(q); }
inline nlohmann::ordered_json number_to_json(double x) { return double_to_json(x); }

/// A JSON number or a string holding a number, read as T. Throws InputError
/// "file:line: path: reason".
template <typename T>
T number_from_json(const JsonNode& node, const std::string& file, const std::string& path);

extern template double number_from_json<double>(const JsonNode&, const std::string&, const std::string&);
extern template Rational number_from_json<Rational>(const JsonNode&, const std::string&, const std::string&);

}  // namespace lpvid
