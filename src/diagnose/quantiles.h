#pragma once
/// Quantiles of the normal and chi-square distributions for the residual
/// tests (whiteness band, portmanteau threshold). Implemented here so that
/// no statistics library is needed.
///
/// Errors: std::invalid_argument for p outside (0, 1) or dof <= 0.

namespace lpvid {

/// Standard normal distribution function Φ(x) = ½·erfc(−x/√2).
double normal_cdf(double x);

/// z with Φ(z) = p, by bisection on Φ (std::erfc) to full double precision.
double normal_quantile(double p);

/// Chi-square distribution function with k degrees of freedom:
/// P(k/2, x/2), the regularised lower incomplete gamma function, evaluated
/// by its power series for x < a + 1 and by its continued fraction (modified
/// Lentz) otherwise (Press et al., Numerical Recipes, 3rd ed., §6.2).
double chi_square_cdf(double x, double dof);

/// The Wilson–Hilferty approximation of the p-quantile of χ²(k):
/// k·(1 − 2/(9k) + z_p·√(2/(9k)))³ (Wilson & Hilferty, PNAS 17, 1931).
/// Relative error about 0.1 % for k ≥ 10 (χ²_0.99(10): 23.24 vs 23.209).
double chi_square_quantile_wilson_hilferty(double p, double dof);

/// The p-quantile of χ²(k): the Wilson–Hilferty value brackets the root of
/// chi_square_cdf(x, k) = p, which bisection then finds to a relative
/// 1e-13 (so it matches the printed tables, e.g. χ²_0.99(10) = 23.209,
/// χ²_0.95(25) = 37.652, to all their digits).
double chi_square_quantile(double p, double dof);

}  // namespace lpvid
