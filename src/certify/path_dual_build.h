#pragma once
/// The builder's half of the compact dual certificate (verify/certificate/path_dual.h,
/// docs/dual_certificates.md "The compact form"): from a barrier's central-path
/// point to a dual point whose exact value is known, with the margin that makes
/// it portable. Shared by the fixed model's lower end and invalidation
/// (certify/dual_certify.h) and the class bound's leaves (certify/class_dual.h).

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/scalar.h"
#include "certify/certify_types.h"
#include "lmi/delta_form_lmi.h"
#include "toeplitz/delta_form_dual.h"
#include "verify/certificate/certificate_file.h"
#include "verify/certificate/path_dual.h"

namespace lpvid {

/// The relative change of the compact dual's U (‖U' − U‖_F ≤ this·‖U‖_F) that
/// a compact certificate is built to survive: a verifier compiled elsewhere
/// (another compiler, SIMD width or BLAS) rebuilds U in floating point with
/// other last bits (docs/dual_certificates.md, "Portable acceptance").
inline constexpr double kPathDualRebuildTolerance = 0x1.0p-30;

/// The builder also rebuilds U from t moved by ± this many units in the last
/// place of its double and keeps x and the claimed bound good for those U too:
/// another machine's rounding of t·I − TTᵀ (its block sums in another order)
/// moves U mostly along its top eigenvector, as a change of t does, by more
/// than the Frobenius class covers when t·I − TTᵀ is nearly singular
/// (docs/dual_certificates.md, "Portable acceptance").
inline constexpr int kPathDualTMoveUlps = 4;

/// x on the decimal grid of `unit` (an exact power of ten), as a rational.
Rational on_grid(double x, double unit_d, const Rational& unit);

/// Which dual claim an objective makes.
DualClaim claim_of(const BoundObjective& obj);

/// The fixed values of the claim, exact (from the CLI text when given).
struct FixedValues {
  Rational delta2{0}, dmax2{0}, lambda{0};
};
FixedValues fixed_values(const CertifyOptions& o, DualClaim claim);

/// g on a 10⁻¹⁴ grid: entries of `column` (k·ny + i order) divided by
/// `scale`, exactly, and their doubles.
struct GridSignal {
  Mat<Rational> g;
  Mat<double> g_d;
};
GridSignal grid_signal(const Vec<double>& column, double scale, Eigen::Index n, Eigen::Index ny);

/// ‖g‖² and gᵀr in double (for choosing σ).
std::pair<double, double> g_norms(const Mat<double>& g_d, const Mat<Rational>& r);

/// σ chosen in double to maximise the bound for fixed tr U, tr V, ‖g‖², gᵀr, then rounded to 15 digits.
Rational chosen_sigma(double trU, double trV, const std::pair<double, double>& gg_gr, Eigen::Index N, DualClaim claim,
                      const FixedValues& f, double sigma0);

/// What a verifier's rebuild of U may change ("Portable acceptance").
/// For D = U' − U with ‖D‖_F ≤ η: E moves by ‖Proj Ω(DT)‖_F ≤ ‖DT‖_F ≤ η‖T‖₂,
/// tr U by |tr D| ≤ √P·η, and β by tr(TᵀDT) + 2⟨T, DT⟩ = 3⟨D, TTᵀ⟩ ≤ 3η‖T‖₂‖T‖_F.
struct RebuildMargin {
  double eta = 0;     ///< bound on ‖U' − U‖_F
  double t_norm = 0;  ///< an upper bound of ‖T‖₂
  double t_frob = 0;  ///< ‖T‖_F
  double E_shift() const { return eta * t_norm; }
  double beta_shift() const { return 3 * eta * t_norm * t_frob; }
};

/// The terms any rebuild within the margin still reaches: β lowered and tr U
/// raised by what the rebuild may move them (dual_bound is increasing in β
/// and non-increasing in tr U where it is positive).
DualTerms<Rational> rebuilt_terms(DualTerms<Rational> terms, const RebuildMargin& m, Eigen::Index P);

/// A compact dual point at exact (z, r) on the horizon L from the central-path
/// point s (its taps are padded with zero rows up to L). `effective_g` maps the
/// stored g (grid) to the g the verifier uses (the class bound's projection;
/// identity for a fixed model); `sigma_shift(g)` returns what is added to tr U
/// and tr V (doubles) when σ is chosen (the class bound's penalties).
/// `records`: stacked records of z and r (toeplitz/record_segments.h; empty: one).
struct PathDualBuild {
  std::string problem;           ///< why no point (empty when built)
  DualPoint point;               ///< horizon, the stored g, σ, the recipe
  Mat<Rational> g_effective;
  PathDualValue value;           ///< at σ, with the effective g
  RebuildMargin margin;
  /// The terms of the rebuilds from t moved by ±kPathDualTMoveUlps (at σ, the final x and floor).
  std::vector<DualTerms<Rational>> moved_terms;
  double scale = 1;
};

/// The least bound that every rebuild the builder covers still reaches: the
/// recipe's U and the moved ones, each with the Frobenius class's margins
/// (rebuilt_terms). `bound_of` maps terms to the claim's bound.
Rational portable_bound(const PathDualBuild& b, Eigen::Index P,
                        const std::function<Rational(const DualTerms<Rational>&)>& bound_of);
using GTransform = std::function<Mat<Rational>(const Mat<Rational>&)>;
using SigmaShift = std::function<std::pair<double, double>(const Mat<Rational>&)>;
PathDualBuild build_path_dual(const Mat<Rational>& z, const Mat<Rational>& r, Eigen::Index L, const DeltaFormSolution& s,
                              DualClaim claim, const FixedValues& fixed, const GTransform& effective_g = {},
                              const SigmaShift& sigma_shift = {}, const RecordLengths& records = {});

}  // namespace lpvid
