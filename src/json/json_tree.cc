#include "json/json_tree.h"

#include <iterator>
#include <unordered_set>

#include "core/input_error.h"

namespace lpvid {
namespace {

using nlohmann::json;

/// A char iterator that records how far nlohmann's lexer has read, so that
/// SAX callbacks know the line of the value they receive.
struct CountingIterator {
  using iterator_category = std::forward_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  const char* p = nullptr;
  const char** progress = nullptr;

  reference operator*() const { return *p; }
  CountingIterator& operator++() {
    ++p;
    if (progress) *progress = p;
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator old = *this;
    ++*this;
    return old;
  }
  bool operator==(const CountingIterator& o) const { return p == o.p; }
  bool operator!=(const CountingIterator& o) const { return p != o.p; }
};

bool is_number_char(char c) { return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == 'e' || c == 'E' || c == '.'; }

class ExactTreeBuilder final : public nlohmann::json_sax<json> {
 public:
  ExactTreeBuilder(std::string_view text, const char* const* progress) : text_(text), progress_(progress) {}

  bool null() override { return add(leaf(JsonNode::Kind::kNull, false)); }
  bool boolean(bool val) override {
    JsonNode n = leaf(JsonNode::Kind::kBool, false);
    n.boolean = val;
    return add(std::move(n));
  }
  bool number_integer(number_integer_t val) override { return number(std::to_string(val)); }
  bool number_unsigned(number_unsigned_t val) override { return number(std::to_string(val)); }
  bool number_float(number_float_t, const string_t& s) override {
    // The lexer writes the locale's decimal point into its buffer; put '.' back.
    std::string t = s;
    for (char& c : t)
      if (!is_number_char(c)) c = '.';
    return number(std::move(t));
  }
  bool string(string_t& val) override {
    JsonNode n = leaf(JsonNode::Kind::kString, false);
    n.text = std::move(val);
    return add(std::move(n));
  }
  bool binary(binary_t&) override { return fail("binary values are not JSON"); }
  bool start_object(std::size_t) override { return open(JsonNode::Kind::kObject); }
  bool key(string_t& val) override {
    if (!keys_.back().insert(val).second) return fail("duplicate key \"" + val + "\"");
    pending_key_ = std::move(val);
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(JsonNode::Kind::kArray); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& ex) override {
    std::string reason = ex.what();
    // Drop "[json.exception.parse_error.101] " and "parse error at line L, column C: ".
    if (size_t b = reason.find("] "); b != std::string::npos && reason.rfind("[json.exception", 0) == 0)
      reason.erase(0, b + 2);
    if (reason.rfind("parse error", 0) == 0)
      if (size_t c = reason.find(": "); c != std::string::npos) reason.erase(0, c + 2);
    // `position` counts the characters read, the offending one included.
    const size_t pos = std::min(position > 0 ? position - 1 : 0, text_.size());
    long line = 1;
    size_t line_start = 0;
    for (size_t i = 0; i < pos; ++i)
      if (text_[i] == '\n') {
        ++line;
        line_start = i + 1;
      }
    error_line_ = line;
    error_ = "JSON syntax error (column " + std::to_string(pos - line_start + 1) + "): " + reason;
    return false;
  }

  JsonNode take_root() { return std::move(root_); }
  const std::string& error() const { return error_; }
  long error_line() const { return error_line_; }

 private:
  /// Line of the value just scanned. For numbers the lexer has read one
  /// character past the token.
  long current_line(bool is_number) {
    size_t pos = static_cast<size_t>(*progress_ - text_.data());
    if (pos > 0) --pos;  // last character read
    if (is_number && pos > 0 && pos < text_.size() && !is_number_char(text_[pos])) --pos;
    pos = std::min(pos, text_.size());
    while (scanned_ < pos) {
      if (text_[scanned_] == '\n') ++line_;
      ++scanned_;
    }
    return line_;
  }

  JsonNode leaf(JsonNode::Kind kind, bool is_number) {
    JsonNode n;
    n.kind = kind;
    n.line = current_line(is_number);
    return n;
  }

  bool number(std::string text) {
    JsonNode n = leaf(JsonNode::Kind::kNumber, true);
    n.text = std::move(text);
    return add(std::move(n));
  }

  bool fail(std::string message) {
    error_line_ = current_line(false);
    error_ = std::move(message);
    return false;
  }

  JsonNode* insert(JsonNode&& n) {
    if (stack_.empty()) {
      root_ = std::move(n);
      return &root_;
    }
    JsonNode* top = stack_.back();
    if (top->kind == JsonNode::Kind::kArray) {
      top->items.push_back(std::move(n));
      return &top->items.back();
    }
    top->members.emplace_back(std::move(pending_key_), std::move(n));
    pending_key_.clear();
    return &top->members.back().second;
  }

  bool add(JsonNode&& n) {
    insert(std::move(n));
    return true;
  }

  bool open(JsonNode::Kind kind) {
    if (stack_.size() >= static_cast<size_t>(kMaxJsonDepth))
      return fail("nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    JsonNode* node = insert(leaf(kind, false));
    stack_.push_back(node);
    if (kind == JsonNode::Kind::kObject) keys_.emplace_back();
    return true;
  }

  bool close() {
    if (stack_.back()->kind == JsonNode::Kind::kObject) keys_.pop_back();
    stack_.pop_back();
    return true;
  }

  std::string_view text_;
  const char* const* progress_;
  size_t scanned_ = 0;
  long line_ = 1;
  JsonNode root_;
  std::vector<JsonNode*> stack_;  // open containers (each lives in its parent, which is not modified meanwhile)
  std::vector<std::unordered_set<std::string>> keys_;  // keys seen per open object
  std::string pending_key_;
  std::string error_;
  long error_line_ = 0;
};

std::string one_line(const nlohmann::ordered_json& j) {
  if (j.is_array()) {
    std::string out = "[";
    bool first = true;
    for (const auto& item : j) {
      if (!first) out += ", ";
      first = false;
      out += one_line(item);
    }
    return out + "]";
  }
  if (j.is_object()) {
    std::string out = "{";
    bool first = true;
    for (const auto& [key, value] : j.items()) {
      if (!first) out += ", ";
      first = false;
      out += nlohmann::ordered_json(key).dump(-1, ' ', false, json::error_handler_t::replace) + ": " + one_line(value);
    }
    return out + "}";
  }
  return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

void pretty(const nlohmann::ordered_json& j, size_t column, size_t indent, size_t width, std::string& out) {
  std::string line = one_line(j);
  if (!j.is_structured() || column + line.size() <= width || j.empty()) {
    out += line;
    return;
  }
  const std::string pad(indent + 2, ' ');
  out += j.is_array() ? "[\n" : "{\n";
  size_t k = 0;
  if (j.is_array()) {
    for (const auto& item : j) {
      out += pad;
      pretty(item, indent + 2, indent + 2, width, out);
      out += ++k < j.size() ? ",\n" : "\n";
    }
  } else {
    for (const auto& [key, value] : j.items()) {
      std::string prefix = nlohmann::ordered_json(key).dump(-1, ' ', false, json::error_handler_t::replace) + ": ";
      out += pad + prefix;
      pretty(value, indent + 2 + prefix.size(), indent + 2, width, out);
      out += ++k < j.size() ? ",\n" : "\n";
    }
  }
  out += std::string(indent, ' ') + (j.is_array() ? "]" : "}");
}

}  // namespace

const JsonNode* JsonNode::find(std::string_view key) const {
  if (kind != Kind::kObject) return nullptr;
  for (const auto& [k, v] : members)
    if (k == key) return &v;
  return nullptr;
}

const char* article_kind(JsonNode::Kind kind) {
  using Kind = JsonNode::Kind;
  switch (kind) {
    case Kind::kObject: return "an object";
    case Kind::kArray: return "an array";
    case Kind::kString: return "a string";
    case Kind::kNumber: return "a number";
    case Kind::kBool: return "a boolean";
    case Kind::kNull: return "null";
  }
  return "a value";
}

JsonNode parse_exact_json(std::string_view text, const std::string& name) {
  const char* progress = text.data();
  ExactTreeBuilder builder(text, &progress);
  CountingIterator first{text.data(), &progress};
  CountingIterator last{text.data() + text.size(), nullptr};
  bool ok = json::sax_parse(first, last, &builder, nlohmann::json::input_format_t::json, /*strict=*/true,
                            /*ignore_comments=*/true);
  if (!ok) {
    throw_input_error(name, builder.error_line(), "",
                      builder.error().empty() ? std::string("JSON syntax error") : builder.error());
  }
  return builder.take_root();
}

std::string pretty_json(const nlohmann::ordered_json& j, int width) {
  std::string out;
  pretty(j, 0, 0, static_cast<size_t>(width < 20 ? 20 : width), out);
  return out + "\n";
}

}  // namespace lpvid
