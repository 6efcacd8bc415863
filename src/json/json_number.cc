#include "json/json_number.h"

#include <cmath>
#include <cstdint>
#include <gmp.h>
#include <stdexcept>

#include "core/input_error.h"
#include "core/number_text.h"

namespace lpvid {

nlohmann::ordered_json rational_to_json(const Rational& q) {
  mpz_srcptr num = mpq_numref(q.mpq());
  if (mpz_cmp_ui(mpq_denref(q.mpq()), 1) == 0 && mpz_fits_slong_p(num))
    return nlohmann::ordered_json(static_cast<std::int64_t>(mpz_get_si(num)));
  return nlohmann::ordered_json(exact_decimal_or_fraction(q));
}

nlohmann::ordered_json double_to_json(double x) {
  if (!std::isfinite(x)) throw std::invalid_argument("cannot write a non-finite number to JSON");
  return nlohmann::ordered_json(x);
}

template <typename T>
T number_from_json(const JsonNode& node, const std::string& file, const std::string& path) {
  using Kind = JsonNode::Kind;
  if (node.kind != Kind::kNumber && node.kind != Kind::kString)
    throw_input_error(file, node.line, path,
                      std::string("expected a number (or a string holding a decimal or p/q), got ") +
                          article_kind(node.kind));
  try {
    return number_from_text<T>(node.text);
  } catch (const InputError& e) {
    throw_input_error(file, node.line, path, e.what());
  }
}

template double number_from_json<double>(const JsonNode&, const std::string&, const std::string&);
template Rational number_from_json<Rational>(const JsonNode&, const std::string&, const std::string&);

}  // namespace lpvid
