#pragma once
/// A small SISO case for bound-window tests, known by
/// construction: G is x⁺ = 0.5x + u, y = x + 0.5u (x0 = 0, multiplicative
/// uncertainty), optionally with a constant output offset φ; data are
/// integers in micro-units written as exact decimals, so a file scaled by a
/// power of ten is exactly the same numbers moved by that power.

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "data/csv_reader.h"
#include "data/experiment_builder.h"
#include "model/model_file.h"

namespace lpvid::gen {

/// The JSON of G, with the offset φ (exact decimal text) when not empty.
inline std::string siso_window_model_json(const std::string& offset = "") {
  std::string j = R"({"format": "lpvid-model/1", "states": 1, "inputs": 1, "outputs": 1, "scheduling": [],
    "columns": {"u": ["u1"], "y": ["y1"], "rho": []},
    "initial": {"A": [{"basis": "1", "value": [[0.5]]}], "B": [{"basis": "1", "value": [[1]]}],
                "C": [{"basis": "1", "value": [[1]]}], "D": [{"basis": "1", "value": [[0.5]]}]})";
  if (!offset.empty()) j += R"(, "offset": {"basis": ["1"], "values": [[)" + offset + "]]}";
  return j + "}";
}

/// v · 10^(−decimals) as exact decimal text.
inline std::string micro_text(long v, int decimals) {
  std::string digits = std::to_string(v < 0 ? -v : v);
  if (digits.size() <= static_cast<size_t>(decimals)) digits.insert(0, static_cast<size_t>(decimals) + 1 - digits.size(), '0');
  digits.insert(digits.size() - static_cast<size_t>(decimals), ".");
  return (v < 0 ? "-" : "") + digits;
}

/// Writes columns u1, y1 of integers (units of 10^(−decimals)).
inline void write_siso_csv(const std::string& path, const std::vector<long>& u, const std::vector<long>& y, int decimals) {
  std::ofstream out(path);
  out << "u1,y1\n";
  for (size_t k = 0; k < u.size(); ++k) out << micro_text(u[k], decimals) << "," << micro_text(y[k], decimals) << "\n";
}

template <typename T>
Experiment<T> read_siso_csv(const std::string& path, const LpvModel<T>& m) {
  return make_experiment<T>(read_table(path), m.columns);
}

/// A deterministic pseudo-random integer in [−range, range] (LCG).
struct SmallLcg {
  unsigned long long s = 12345;
  long next(long range) {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<long>((s >> 33) % static_cast<unsigned long long>(2 * range + 1)) - range;
  }
};

/// u in micro-units (±1) and y = G u + e with |e| ≤ noise micro-units plus
/// the rounding of G u to micro-units (≤ 0.5 unit).
inline void siso_generated(long n, long noise, std::vector<long>& u, std::vector<long>& y) {
  SmallLcg g;
  u.assign(static_cast<size_t>(n), 0);
  y.assign(static_cast<size_t>(n), 0);
  double x = 0;
  for (long k = 0; k < n; ++k) {
    u[static_cast<size_t>(k)] = g.next(1000000);
    const double uk = static_cast<double>(u[static_cast<size_t>(k)]);
    y[static_cast<size_t>(k)] = std::lround(x + 0.5 * uk) + g.next(noise);
    x = 0.5 * x + uk;
  }
}

}  // namespace lpvid::gen
