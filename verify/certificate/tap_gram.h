#pragma once
/// The Schur complement on which (C1) of form "delta" is decided
/// (verify/certificate/c1_delta_form.cc, step 3): with T the block
/// lower-triangular Toeplitz matrix of the taps Δ_0 … Δ_{K−1} (ny × nz each)
/// on L samples,
///   d2·I − T Tᵀ   (ny ≤ nz, blocks ny × ny)   or   d2·I − TᵀT   (ny > nz, blocks nz × nz),
/// exactly, in O(L·K) block entries instead of the O(L·K²) of one dot
/// product per block.
///
/// The displacement recurrence (proof, for c ≥ a and c − a = o):
///   T Tᵀ block (a, c) = Σ_{b ≤ a, c − b < K} Δ_{a−b} Δ_{c−b}ᵀ. The same sum
///   for (a − 1, c − 1), re-indexed by b + 1, covers every b ≥ 1 of it; the
///   b = 0 term Δ_a Δ_cᵀ is present iff c < K. So
///     G(a, c) = G(a − 1, c − 1) + [c < K] Δ_a Δ_cᵀ,   G(−1, ·) = 0.
///   TᵀT block (a, c) = Σ_{c ≤ r ≤ L−1, r − a < K} Δ_{r−a}ᵀ Δ_{r−c}: the sum
///   for (a + 1, c + 1), re-indexed by r − 1, covers every r ≤ L − 2 of it;
///   the r = L − 1 term Δ_{L−1−a}ᵀ Δ_{L−1−c} is present iff L − 1 − a < K. So
///     G(a, c) = G(a + 1, c + 1) + [L−1−a < K] Δ_{L−1−a}ᵀ Δ_{L−1−c},   G(L, ·) = 0.
/// Walking one block diagonal o from its first block (step s = 0: (0, o), or
/// (L−1−o, L−1) for TᵀT), the term at step s is present iff s + o < K in both
/// cases: it is Δ_s Δ_{s+o}ᵀ, or Δ_{s+o}ᵀ Δ_s. Past s = K − 1 − o the diagonal
/// is constant (the Gram of a Toeplitz matrix is Toeplitz away from its
/// start). The taps are held as integers over one common denominator D, so
/// the running sums are exact integer sums over D².

#include "core/scalar.h"

namespace lpvid {

/// d2·I − T Tᵀ (ny ≤ nz) or d2·I − TᵀT (ny > nz), of size L·min(ny, nz);
/// `taps` K × (ny·nz), row t = Δ_t row-major (entry (i, j) at column i·nz + j).
Mat<Rational> tap_gram_complement(const Mat<Rational>& taps, Eigen::Index L, Eigen::Index ny, Eigen::Index nz,
                                  const Rational& d2);

}  // namespace lpvid
