#pragma once
/// Reading and writing the members of exact JSON trees (json_tree.h) with
/// errors that name the file, the line and the JSON path: shared by the
/// certificate file (verify/certificate/certificate_file.h) and the oracle's
/// task and answer files (oracle/).

#include <string>

#include <nlohmann/json.hpp>

#include "core/scalar.h"
#include "json/json_tree.h"

namespace lpvid {

/// Member `key` of `obj`; throws InputError "file:line: path.key: missing".
const JsonNode& member(const JsonNode& obj, const char* key, const std::string& file, const std::string& path);
/// A string member (throws when missing or not a string).
std::string string_member(const JsonNode& obj, const char* key, const std::string& file, const std::string& path);
/// A non-negative integer of at most 12 digits.
long integer_member(const JsonNode& n, const std::string& file, const std::string& path);
/// A list of rows of `cols` exact numbers each.
Mat<Rational> matrix_member(const JsonNode& n, const std::string& file, const std::string& path, Eigen::Index cols);
/// The rows of `m` as lists of exact numbers (json_number.h's rational_to_json).
nlohmann::ordered_json matrix_json(const Mat<Rational>& m);

}  // namespace lpvid
