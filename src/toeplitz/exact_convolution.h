#pragma once
/// The exact (Rational) FIR convolution w = Δ ∗ z and its adjoint
/// C_l(g) = Σ_j g_j z_{j−l}ᵀ of toeplitz/record_segments.h, summed in
/// integers over one common denominator per matrix and reduced once per
/// result entry, instead of one gcd per product and per addition. The same
/// rational numbers (a sum of rationals is exact whichever way it is formed),
/// so every verdict and certificate is unchanged; the verifier's (C2) and the
/// compact dual's check spend most of their time here.
///
/// Common denominators can be far larger than any single one when the
/// denominators are unrelated (lcm of 2, 3, 5, 7, …). Then these functions
/// return false and the caller sums rational by rational as before.

#include <vector>

#include "core/scalar.h"

namespace lpvid {

/// w (n × ny) = Δ ∗ z record by record, as apply_fir_records; false (w untouched) when the
/// common denominators would be much larger than the largest single one.
bool apply_fir_records_exact(const Mat<Rational>& taps, const Mat<Rational>& z, Eigen::Index ny, Eigen::Index horizon,
                             const std::vector<Eigen::Index>& lengths, Mat<Rational>& w);

/// c (L × ny·nz) as fir_adjoint_records; false (c untouched) as above.
bool fir_adjoint_records_exact(const Mat<Rational>& g, const Mat<Rational>& z, Eigen::Index horizon,
                               const std::vector<Eigen::Index>& lengths, Mat<Rational>& c);

}  // namespace lpvid
