#pragma once
/// JSON with exact number text (docs/design.md §11.1: numbers "the exact reader
/// reads from their text"). nlohmann::json's DOM stores numbers as double/int64; this tree
/// keeps each number as the text written in the file, so that the exact path
/// never goes through double. Built with nlohmann's SAX interface.
///
/// Also: a pretty printer for nlohmann::ordered_json that keeps matrices and
/// short objects on one line (used by the model and certificate writers).
///
/// The floor src/json (the exact JSON layer, on src/core only): this tree,
/// exact numbers (json_number.h) and members read with located errors
/// (json_members.h). The model file (model/model_file.h), the certificate
/// files (verify/certificate/) and the oracle's files (oracle/) sit above it.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace lpvid {

/// One JSON value. Numbers keep their source text (`text`): integers as
/// decimal digits, other numbers exactly as the token in the file.
struct JsonNode {
  enum class Kind { kNull, kBool, kNumber, kString, kArray, kObject };
  Kind kind = Kind::kNull;
  bool boolean = false;
  std::string text;  ///< kNumber: number text; kString: the (unescaped) string
  std::vector<JsonNode> items;                              ///< kArray
  std::vector<std::pair<std::string, JsonNode>> members;    ///< kObject, in file order
  long line = 0;  ///< 1-based line where the value starts (0 if unknown)

  bool is_object() const { return kind == Kind::kObject; }
  bool is_array() const { return kind == Kind::kArray; }
  bool is_string() const { return kind == Kind::kString; }
  bool is_number() const { return kind == Kind::kNumber; }
  /// Member `key` of an object, or nullptr (also for non-objects).
  const JsonNode* find(std::string_view key) const;
};

/// The kind with its article, for messages: "an object", "an array",
/// "a string", "a number", "a boolean", "null".
const char* article_kind(JsonNode::Kind kind);

/// Largest nesting depth accepted (a model file needs 5).
constexpr int kMaxJsonDepth = 64;

/// Parses JSON text into a JsonNode tree. `//` and `/* */` comments are
/// allowed and ignored (the example of docs/design.md §11.1 carries them). Throws InputError
/// "name:line: JSON syntax error (column c): reason" for malformed JSON
/// (including invalid UTF-8, trailing text and numbers that overflow a
/// double: write those as strings), and for duplicate object keys or nesting
/// deeper than kMaxJsonDepth.
JsonNode parse_exact_json(std::string_view text, const std::string& name);

/// Indented JSON text in which arrays and objects whose one-line form is
/// short (≤ `width` characters, e.g. a matrix row or a small term) stay on
/// one line. Ends with a newline.
std::string pretty_json(const nlohmann::ordered_json& j, int width = 100);

}  // namespace lpvid
