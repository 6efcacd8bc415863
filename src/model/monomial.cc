#include "model/monomial.h"

#include <numeric>

namespace lpvid {

int Monomial::degree() const { return std::accumulate(powers.begin(), powers.end(), 0); }

std::string Monomial::text(const std::vector<std::string>& names) const {
  std::string out;
  for (size_t k = 0; k < powers.size(); ++k) {
    if (powers[k] == 0) continue;
    if (!out.empty()) out += "*";
    out += k < names.size() ? names[k] : "rho" + std::to_string(k + 1);
    if (powers[k] > 1) out += "^" + std::to_string(powers[k]);
  }
  return out.empty() ? "1" : out;
}

Monomial constant_monomial(size_t n_rho) { return Monomial{std::vector<int>(n_rho, 0)}; }

}  // namespace lpvid
