#pragma once
/// Data of a known model plus known noise, for the closed form at δ = 0
/// (docs/dual_certificates.md, "The δ = 0 lower end"): the model is diagonal
/// LTI, x⁺ = diag(a)·x + u, y = x (B = C = I, x0 = 0, nx = nu = ny = p),
/// additive uncertainty z = u/10; the data are y = ŷ + e with e known, so the
/// residual r = y − ŷ is e exactly and ‖r‖² = Σ e² by construction. With
/// a_i = ±1/2 and u on the grid 1/4 every ŷ is dyadic, written as an exact
/// decimal. Nothing here calls lpvid's simulation or certification.

#include <algorithm>
#include <string>
#include <vector>

#include "core/number_text.h"
#include "core/scalar.h"

namespace lpvid::gen {

/// The model file (lpvid-model/1) of the diagonal model with entries `a` (text, e.g. "1/2").
inline std::string diagonal_model_json(const std::vector<std::string>& a) {
  const size_t p = a.size();
  const auto matrix = [p](const std::vector<std::string>& diag) {
    std::string m = "[";
    for (size_t i = 0; i < p; ++i) {
      m += i ? ", [" : "[";
      for (size_t j = 0; j < p; ++j) m += (j ? ", \"" : "\"") + (i == j ? diag[i] : std::string("0")) + "\"";
      m += "]";
    }
    return m + "]";
  };
  std::string u, y;
  for (size_t i = 0; i < p; ++i) {
    u += std::string(i ? ", " : "") + "\"u" + std::to_string(i + 1) + "\"";
    y += std::string(i ? ", " : "") + "\"y" + std::to_string(i + 1) + "\"";
  }
  const std::vector<std::string> ones(p, "1");
  return "{\"format\": \"lpvid-model/1\", \"states\": " + std::to_string(p) + ", \"inputs\": " + std::to_string(p) +
         ", \"outputs\": " + std::to_string(p) + ", \"scheduling\": [], \"columns\": {\"u\": [" + u + "], \"y\": [" + y +
         "]}, \"initial\": {\"A\": [{\"basis\": \"1\", \"value\": " + matrix(a) + "}], \"B\": [{\"basis\": \"1\", \"value\": " +
         matrix(ones) + "}], \"C\": [{\"basis\": \"1\", \"value\": " + matrix(ones) +
         "}]}, \"uncertainty\": {\"structure\": \"additive\", \"weight\": \"1/10\"}}\n";
}

/// One record: its CSV text (u1 … up, y1 … yp) and ‖e‖² by construction.
struct NoiseOnlyRecord {
  std::string csv;
  Rational energy{0};
  long samples = 0;
};

/// n samples: u from an integer recurrence seeded by `seed` (values k/4,
/// 1 ≤ |k| ≤ 9), y = ŷ + e with e_{k,i} = ±(1 + (k + i) mod 3)/1000 (sign by
/// the recurrence), or e = 0 when `noise` is false.
inline NoiseOnlyRecord noise_only_record(const std::vector<Rational>& a, long n, long seed, bool noise = true) {
  const size_t p = a.size();
  NoiseOnlyRecord r;
  r.samples = n;
  for (size_t i = 0; i < p; ++i) r.csv += std::string(i ? "," : "") + "u" + std::to_string(i + 1);
  for (size_t i = 0; i < p; ++i) r.csv += ",y" + std::to_string(i + 1);
  r.csv += "\n";
  std::vector<Rational> x(p, Rational(0));
  long s = seed;
  for (long k = 0; k < n; ++k) {
    std::string us, ys;
    for (size_t i = 0; i < p; ++i) {
      s = (s * 1103515245 + 12345) % 2147483648;
      const long v = (s / 65536) % 19 - 9;
      const Rational u = Rational(v == 0 ? 5 : v) / Rational(4);
      const Rational e = noise ? Rational((s / 7) % 2 == 0 ? 1 : -1) * Rational(1 + (k + static_cast<long>(i)) % 3) / Rational(1000)
                               : Rational(0);
      r.energy += e * e;
      us += std::string(i ? "," : "") + exact_decimal_or_fraction(u);
      ys += "," + exact_decimal_or_fraction(x[i] + e);  // ŷ = x (C = I)
      x[i] = a[i] * x[i] + u;                            // x⁺ = a·x + u (B = I)
    }
    r.csv += us + ys + "\n";
  }
  return r;
}

/// ‖y − ŷ‖² from the CSV text alone: every cell read as an exact decimal,
/// the diagonal model simulated here from x0 = 0.
inline Rational residual_energy_of_text(const std::string& csv, const std::vector<Rational>& a) {
  const size_t p = a.size();
  std::vector<Rational> x(p, Rational(0));
  Rational energy(0);
  size_t at = csv.find('\n') + 1;  // after the header
  while (at < csv.size()) {
    const size_t end = csv.find('\n', at);
    std::vector<Rational> cells;
    for (size_t from = at; from <= end;) {
      const size_t comma = std::min(csv.find(',', from), end);
      cells.push_back(rational_from_text(csv.substr(from, comma - from)));
      from = comma + 1;
    }
    for (size_t i = 0; i < p; ++i) {
      const Rational r = cells[p + i] - x[i];
      energy += r * r;
      x[i] = a[i] * x[i] + cells[i];
    }
    at = end + 1;
  }
  return energy;
}

}  // namespace lpvid::gen
