#include "data/csv_writer.h"

#include <fstream>
#include <stdexcept>

#include "core/number_text.h"

namespace lpvid {

std::string csv_text(const std::vector<TextColumn>& columns) {
  std::string out;
  size_t rows = columns.empty() ? 0 : columns[0].cells.size();
  for (size_t c = 0; c < columns.size(); ++c) {
    if (columns[c].cells.size() != rows) throw std::runtime_error("write_csv: column '" + columns[c].name + "' has a different length");
    out += (c ? "," : "") + columns[c].name;
  }
  out += "\n";
  for (size_t r = 0; r < rows; ++r) {
    for (size_t c = 0; c < columns.size(); ++c) out += (c ? "," : "") + columns[c].cells[r];
    out += "\n";
  }
  return out;
}

void write_csv(const std::string& path, const std::vector<TextColumn>& columns) {
  std::string text = csv_text(columns);
  std::ofstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot write '" + path + "'");
  f << text;
  if (!f) throw std::runtime_error("error while writing '" + path + "'");
}

std::string rational_to_decimal_text(const Rational& q) {
  mpz_t den, num, pow;
  mpz_init_set(den, mpq_denref(q.mpq()));
  long twos = 0, fives = 0;
  while (mpz_divisible_ui_p(den, 2)) { mpz_divexact_ui(den, den, 2); ++twos; }
  while (mpz_divisible_ui_p(den, 5)) { mpz_divexact_ui(den, den, 5); ++fives; }
  bool terminating = mpz_cmp_ui(den, 1) == 0;
  std::string out;
  if (!terminating) {
    out = rational_to_text(q);
  } else {
    long digits = std::max(twos, fives);
    // value = num * 10^digits / den_full, an integer scaled by 10^-digits.
    mpz_init(num);
    mpz_init(pow);
    mpz_ui_pow_ui(pow, 10, static_cast<unsigned long>(digits));
    mpz_mul(num, mpq_numref(q.mpq()), pow);
    mpz_divexact(num, num, mpq_denref(q.mpq()));
    bool neg = mpz_sgn(num) < 0;
    mpz_abs(num, num);
    char* s = mpz_get_str(nullptr, 10, num);
    std::string d(s);
    void (*freefunc)(void*, size_t);
    mp_get_memory_functions(nullptr, nullptr, &freefunc);
    freefunc(s, d.size() + 1);
    if (digits > 0) {
      if (static_cast<long>(d.size()) <= digits) d = std::string(static_cast<size_t>(digits - static_cast<long>(d.size()) + 1), '0') + d;
      d.insert(d.size() - static_cast<size_t>(digits), ".");
    }
    out = (neg ? "-" : "") + d;
    mpz_clear(num);
    mpz_clear(pow);
  }
  mpz_clear(den);
  return out;
}

std::vector<std::string> column_text(const Mat<Rational>& m, Eigen::Index j) {
  std::vector<std::string> out;
  out.reserve(static_cast<size_t>(m.rows()));
  for (Eigen::Index i = 0; i < m.rows(); ++i) out.push_back(rational_to_decimal_text(m(i, j)));
  return out;
}

std::vector<std::string> column_text(const Mat<double>& m, Eigen::Index j) {
  std::vector<std::string> out;
  out.reserve(static_cast<size_t>(m.rows()));
  for (Eigen::Index i = 0; i < m.rows(); ++i) out.push_back(double_to_text(m(i, j)));
  return out;
}

}  // namespace lpvid
