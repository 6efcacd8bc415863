#pragma once
/// Basis functions of the scheduling parameter (docs/design.md §5, §11; paper eq. 10 and
/// the Appendix): products of non-negative integer powers of the scheduling
/// variables, written `1`, `rho1`, `rho1*rho2`, `rho2^2`, `rho1^2*rho2`.

#include <string>
#include <string_view>
#include <vector>

#include "core/scalar.h"

namespace lpvid {

/// f(ρ) = Π_k ρ_k^{powers[k]}; powers.size() == number of scheduling variables.
struct Monomial {
  std::vector<int> powers;

  /// Total degree (0 for the constant `1`).
  int degree() const;
  bool is_constant() const { return degree() == 0; }

  /// Canonical text with the given scheduling names, e.g. "rho1^2*rho2", "1".
  std::string text(const std::vector<std::string>& names) const;

  /// f(ρ) for one sample ρ (length == powers.size()).
  template <typename T>
  T eval(const Vec<T>& rho) const {
    T v(1);
    for (size_t k = 0; k < powers.size(); ++k)
      for (int p = 0; p < powers[k]; ++p) v = v * rho(static_cast<Eigen::Index>(k));
    return v;
  }

  friend bool operator==(const Monomial& a, const Monomial& b) { return a.powers == b.powers; }
};

/// The constant basis function `1` for `n_rho` scheduling variables.
Monomial constant_monomial(size_t n_rho);

/// Largest exponent accepted in a basis text (guards against `rho1^99999`).
constexpr int kMaxMonomialPower = 16;

/// Parses a basis text against the scheduling names. Accepts `1`, names,
/// `name^k` (k integer in 1..kMaxMonomialPower) joined by `*`, spaces
/// allowed around tokens; repeated factors multiply (`rho1*rho1` = `rho1^2`).
/// Throws InputError (no location; the caller adds it) naming the bad token:
/// unknown scheduling name, bad or out-of-range exponent, empty factor.
Monomial parse_monomial(std::string_view text, const std::vector<std::string>& names);

}  // namespace lpvid
