#pragma once
/// The Lagrange dual of Theorem 2.1 in the full-horizon Δ form (docs/design.md §7.5): it
/// certifies "invalidated" and lower bounds (the mathematics is written out
/// in docs/dual_certificates.md).
/// Templated on the scalar: the certificate builder evaluates it in doubles
/// and rationals, the verifier in exact rationals only.
///
/// Primal (horizon L = n − m, m = leading zero samples of z; taps h_0 … h_{L−1},
/// each ny × nz; t = δ², s = d_max², N = n·ny):
///   M1(H, t) = [ t·I_{L·ny}   T_Δ      ]  ⪰ 0         (C1')
///              [ T_Δᵀ         I_{L·nz} ]
///   M2(H, s) = [ N·s   dᵀ ]  ⪰ 0,   d = r − Δ∗z        (C2)
///              [ d     I  ]
/// Dual multipliers
///   Y1 = [ U   W ]  ⪰ 0  (U: L·ny, V: L·nz, W: L·ny × L·nz),
///        [ Wᵀ  V ]
///   Y2 = [ σ   gᵀ     ]  = (1/σ)·[σ; g][σ; g]ᵀ ⪰ 0  (σ > 0, g ∈ R^N),
///        [ g   g gᵀ/σ ]
/// For every (H, t, s):
///   ⟨M1, Y1⟩ + ⟨M2, Y2⟩ = t·tr U + tr V + N·s·σ + ‖g‖²/σ + 2 gᵀr
///                          + 2 Σ_l ⟨h_l, Ω_l(W) − C_l(g)⟩
/// with Ω_l(W) = Σ_b W_{(b+l), b} (ny × nz blocks on the l-th block
/// subdiagonal) and C_l(g) = Σ_{k ≥ m+l} g_k z_{k−l}ᵀ (the adjoint of Δ∗z).
/// If Ω_l(W) = C_l(g) for every l (the dual equality), the H terms vanish,
/// and since both inner products are ≥ 0 at a feasible point:
///   t·tr U + N·s·σ ≥ β := −(tr V + ‖g‖²/σ + 2 gᵀr)    for every feasible (t, s).
/// That one inequality gives both certificate kinds (weak duality):
///   invalidated at (δ², d_max²):   δ²·tr U + N·d_max²·σ < β;
///   lower bounds: δ² ≥ (β − N·d_max²·σ)/tr U,  d_max² ≥ (β − δ²·tr U)/(N·σ),
///                 λδ² + (1−λ)d_max² ≥ μ·β,  μ = min(λ/tr U, (1−λ)/(N·σ))  (β > 0).

#include <algorithm>

#include "core/scalar.h"
#include "toeplitz/record_segments.h"

namespace lpvid {

/// C_l(g) = Σ_{k=m+l}^{n−1} g_k z_{k−l}ᵀ for l = 0 … L−1, m = n − L: the
/// adjoint of apply_fir (⟨g, Δ∗z⟩ = Σ_l ⟨h_l, C_l(g)⟩). g is n × ny, z is
/// n × nz. Returns L × (ny·nz), row l = C_l row-major.
template <typename T>
Mat<T> fir_adjoint(const Mat<T>& g, const Mat<T>& z, Eigen::Index horizon) {
  return fir_adjoint_records(g, z, horizon, RecordLengths{});
}

/// Ω_l(W) = Σ_{b=0}^{L−1−l} W_{(b+l), b} for l = 0 … L−1, W the upper-right
/// L·ny × L·nz block of Y1 (rows a·ny + i, columns L·ny + b·nz + j of Y1).
/// Returns L × (ny·nz), row l = Ω_l row-major: ⟨T_Δ, W⟩ = Σ_l ⟨h_l, Ω_l⟩.
template <typename T>
Mat<T> block_diagonal_sums(const Mat<T>& Y1, Eigen::Index horizon, Eigen::Index ny, Eigen::Index nz) {
  const Eigen::Index L = horizon, off = L * ny;
  Mat<T> o = Mat<T>::Zero(L, ny * nz);
  for (Eigen::Index l = 0; l < L; ++l)
    for (Eigen::Index b = 0; b + l < L; ++b)
      for (Eigen::Index i = 0; i < ny; ++i)
        for (Eigen::Index j = 0; j < nz; ++j) o(l, i * nz + j) += Y1((b + l) * ny + i, off + b * nz + j);
  return o;
}

/// The scalars of the dual functional (see the file comment).
template <typename T>
struct DualTerms {
  T trace_U{0};   ///< tr U (coefficient of t = δ²)
  T N_sigma{0};   ///< N·σ (coefficient of s = d_max²)
  T beta{0};      ///< β = −(tr V + ‖g‖²/σ + 2 gᵀr)
};

/// tr U, N·σ and β for Y1 (L·(ny+nz) square), g, σ > 0 and the residual r
/// (n × ny). Does not check the dual equality or Y1 ⪰ 0.
template <typename T>
DualTerms<T> dual_terms(const Mat<T>& Y1, const Mat<T>& g, const T& sigma, const Mat<T>& r, Eigen::Index horizon) {
  const Eigen::Index ny = g.cols(), off = horizon * ny, n = g.rows();
  DualTerms<T> d;
  T trV(0), gg(0), gr(0);
  for (Eigen::Index i = 0; i < off; ++i) d.trace_U += Y1(i, i);
  for (Eigen::Index i = off; i < Y1.rows(); ++i) trV += Y1(i, i);
  for (Eigen::Index k = 0; k < n; ++k)
    for (Eigen::Index i = 0; i < ny; ++i) {
      gg += g(k, i) * g(k, i);
      gr += g(k, i) * r(k, i);
    }
  d.N_sigma = T(static_cast<long>(n * ny)) * sigma;
  d.beta = -(trV + gg / sigma + T(2) * gr);
  return d;
}

/// What a dual certificate claims about the objective of Theorem 2.1.
enum class DualClaim {
  kInvalidated,  ///< fixed δ², d_max²: no feasible point (margin > 0)
  kMinDelta2,    ///< fixed d_max²: δ² ≥ bound
  kMinDmax2,     ///< fixed δ²: d_max² ≥ bound
  kWeighted,     ///< λδ² + (1−λ)d_max² ≥ bound
};

/// The certified number of a dual certificate (file comment):
///  - kInvalidated: the margin β − δ²·tr U − N·d_max²·σ; > 0 proves that no
///    (H, δ², d_max²) at the fixed values is feasible;
///  - kMinDelta2: max(0, (β − N·d_max²·σ)/tr U)   (0 when tr U = 0);
///  - kMinDmax2:  max(0, (β − δ²·tr U)/(N·σ))     (0 when N·σ = 0);
///  - kWeighted:  μ·β with μ = min(λ/tr U, (1−λ)/(N·σ)) when β > 0, else 0
///    (a zero coefficient counts as +∞ in the min: λ = 0 with tr U = 0).
/// Every case uses t ≥ 0 and s ≥ 0, which any feasible point satisfies
/// (diagonals of M1 and M2).
template <typename T>
T dual_bound(const DualTerms<T>& d, DualClaim claim, const T& delta2, const T& dmax2, const T& lambda) {
  const T zero(0);
  switch (claim) {
    case DualClaim::kInvalidated:
      return d.beta - delta2 * d.trace_U - dmax2 * d.N_sigma;
    case DualClaim::kMinDelta2: {
      if (!(d.trace_U > zero)) return zero;
      const T b = (d.beta - dmax2 * d.N_sigma) / d.trace_U;
      return b > zero ? b : zero;
    }
    case DualClaim::kMinDmax2: {
      if (!(d.N_sigma > zero)) return zero;
      const T b = (d.beta - delta2 * d.trace_U) / d.N_sigma;
      return b > zero ? b : zero;
    }
    case DualClaim::kWeighted: {
      if (!(d.beta > zero)) return zero;
      // μ·(t·trU + s·Nσ) ≤ λt + (1−λ)s needs μ·trU ≤ λ and μ·Nσ ≤ 1 − λ.
      const bool has_u = d.trace_U > zero, has_s = d.N_sigma > zero;
      if (!has_u && !has_s) return zero;
      T mu = has_u ? lambda / d.trace_U : (T(1) - lambda) / d.N_sigma;
      if (has_u && has_s) {
        const T other = (T(1) - lambda) / d.N_sigma;
        if (other < mu) mu = other;
      }
      return mu * d.beta;
    }
  }
  return zero;
}

}  // namespace lpvid
