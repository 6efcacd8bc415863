#pragma once
/// Exact powers of two: the constants of the floating filter
/// (verify/psd/psd_filter.cc) and the balancing of the (C1) matrices of
/// Theorem 2.1 before the PSD decision (verify/certificate/c1_check.h). Multiplying a
/// matrix by 2^k > 0, or a congruence by diag(I, 2^k I), is exact in
/// rationals and keeps the inertia, so the PSD verdict is unchanged; it only
/// brings the entries into the range where the floating filter can decide.

#include <optional>
#include <vector>

#include "core/scalar.h"

namespace lpvid {

/// 2^e as an exact rational (any e, far beyond the double range).
Rational power_of_two(long e);

/// bitlength(|numerator|) − bitlength(denominator) of q ≠ 0, so that
/// 2^(e−1) < |q| < 2^(e+1); empty for q = 0. Exact and cheap for any size of q.
std::optional<long> binary_magnitude(const Rational& q);

/// A power of two s with s² within a factor 4 of q > 0 (1 for q ≤ 0).
Rational sqrt_scale(const Rational& q);

/// Exponents k_i of a diagonal congruence D = diag(2^k_i) that brings every
/// positive diagonal entry of the symmetric M to within a factor 4 of 1
/// (k_i = 0 where M_ii ≤ 0). Empty when the positive diagonal already spans
/// fewer than `min_range_bits` binary orders: then balancing buys nothing.
std::vector<long> diagonal_balance_exponents(const Mat<Rational>& M, long min_range_bits = 40);

/// D·M·D for D = diag(2^k_i): exact, and D is nonsingular, so D·M·D has the
/// inertia of M (PD, PSD or not PSD alike); v'(DMD)v = (Dv)'M(Dv).
Mat<Rational> diagonal_congruence(const Mat<Rational>& M, const std::vector<long>& k);

}  // namespace lpvid
