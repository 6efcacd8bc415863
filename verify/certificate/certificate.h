#pragma once
/// What a certificate says (the claim, its form, the model, the data it
/// names and the point that proves the claim), as the file reader
/// (certificate_file.h) makes it and the checkers (certificate_check.h) take
/// it. The file format itself is described in certificate_file.h.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/scalar.h"
#include "data/data_reference.h"
#include "model/lpv_model.h"
#include "toeplitz/affine_residual.h"
#include "toeplitz/delta_form_dual.h"
#include "toeplitz/uncertainty_toeplitz.h"
#include "verify/certificate/path_dual.h"

namespace lpvid {

inline constexpr const char* kCertificateFormat = "lpvid-certificate/1";

/// How a claim is witnessed: a primal point (kDelta: Δ taps; kW: the signal
/// w), a dual point (kDualDelta: Y1 itself; kDualDeltaPath: its recipe), or
/// nothing beyond the data (closed form, verify/certificate/closed_form_check.h):
/// kZeroDelta, the exact answer at δ² = 0 (Δ = 0, so d = r), and
/// kNonnegative, a lower end ≤ 0 of an objective that is ≥ 0.
enum class CertificateForm { kDelta, kW, kDualDelta, kDualDeltaPath, kZeroDelta, kNonnegative };

/// "delta", "w", "dual_delta", "dual_delta_path", "zero_delta", "nonnegative".
const char* to_string(CertificateForm f);

/// Forms whose claim ("lower_bound", "invalidated") is decided without a dual point.
inline bool is_closed_form(CertificateForm f) {
  return f == CertificateForm::kZeroDelta || f == CertificateForm::kNonnegative;
}

/// What the certificate claims. kConsistent: the model is not invalidated at
/// (δ², d_max²) (a primal point). kInvalidated / kLowerBound: a dual point of
/// the full-horizon Δ form (toeplitz/delta_form_dual.h), or in closed form
/// (is_closed_form: no dual point). kNotAWitness: the
/// primal point the file carries (Δ taps or w, written by someone else and
/// judged by `lpvid oracle`) does NOT satisfy Theorem 2.1 at (δ², d_max²):
/// the same checks as kConsistent, and the claim holds iff one of the
/// mathematical conditions fails exactly — (C2), (C1) or, in form "delta",
/// a non-zero z before the Δ horizon. A malformed point (wrong sizes) is not
/// evidence of anything: it makes the claim fail like any other bad file.
/// kClassLowerBound / kClassInvalidated: the same about Theorem 3.1 over every
/// θ of a region of the model's correction class (ClassRegion below).
enum class CertificateClaim { kConsistent, kInvalidated, kLowerBound, kNotAWitness, kClassLowerBound, kClassInvalidated };

/// "consistent", "invalidated", "lower_bound", "not_a_witness".
const char* to_string(CertificateClaim c);

/// Claims carried by a dual point (form "dual_delta" / "dual_delta_path") or
/// decided in closed form (form "zero_delta" / "nonnegative").
inline bool is_dual_claim(CertificateClaim c) {
  return c == CertificateClaim::kInvalidated || c == CertificateClaim::kLowerBound;
}

/// Claims about the whole correction class (verify/certificate/class_check.h).
inline bool is_class_claim(CertificateClaim c) {
  return c == CertificateClaim::kClassLowerBound || c == CertificateClaim::kClassInvalidated;
}

/// The dual point Y1 ⪰ 0, Y2 = (1/σ)[σ; g][σ; g]ᵀ (toeplitz/delta_form_dual.h).
struct DualPoint {
  long horizon = 0;  ///< L
  Mat<Rational> Y1;  ///< L·(ny+nz) square, symmetric (form "dual_delta")
  PathDualRecipe path;  ///< form "dual_delta_path": Y1 is rebuilt from it (verify/certificate/path_dual.h)
  Mat<Rational> g;   ///< n × ny
  Rational sigma;    ///< σ > 0
};

/// One node of a class certificate's region tree, in preorder: a split halves
/// the current box in coordinate `split` (two subtrees follow, lower half
/// first); a leaf carries the dual point at its box's centre and ε > 0 of the
/// bilinear term's bound c·√t ≤ c·(t/(2ε) + ε/2).
struct ClassNode {
  long split = -1;  ///< ≥ 0: a split; −1: a leaf
  DualPoint dual;
  Rational epsilon;
  /// The point p_e the leaf's dual point was made at (empty: the box's
  /// centre). The penalties then use ρ'_i = |p_e,i − c_i| + ρ_i, so an
  /// ancestor's dual point keeps its bound on a child's box.
  Vec<Rational> expansion;
};

/// The region of θ a class claim covers (docs/class_lower_bound.md): the
/// parameters in `free` range over all reals, the others over
/// [center − radius, center + radius]; the tree's leaves cover that box.
struct ClassRegion {
  Unknowns unknowns;
  std::vector<std::string> parameters;
  std::vector<long> free;
  Vec<Rational> center, radius;
  long horizon = 0;
  std::vector<ClassNode> nodes;
};

/// One record of a certificate: where its rows come from (file as written,
/// sha256, names of a headerless file, rows [begin, end), end = -1: to the
/// last row) and, when the certificate names several records, its own
/// initial state.
struct CertificateRecord {
  DataReference data;
  Vec<Rational> x0;  ///< empty: the model's x0 (always, for one record)
};

struct Certificate {
  /// The records the claim is about, at least one: one record is written as
  /// "data", two or more as "records" (one Δ and one noise bound for all,
  /// each simulated from its own x0, Δ acting on each from rest;
  /// docs/several_records.md). A certificate made in memory names one record
  /// without a file.
  std::vector<CertificateRecord> records = std::vector<CertificateRecord>(1);
  LpvModel<Rational> model;
  ToeplitzMode mode = ToeplitzMode::kSignal;
  CertificateForm form = CertificateForm::kDelta;
  Rational delta2, dmax2;
  Mat<Rational> taps;  ///< K × (ny·nz), form kDelta (h_K … h_{L−1} = 0)
  long horizon = 0;    ///< L, form kDelta
  Mat<Rational> w;     ///< n × ny, form kW
  CertificateClaim claim = CertificateClaim::kConsistent;
  /// Dual claims: which bound (kInvalidated for "feasibility"), λ (weighted),
  /// the claimed lower end, and the dual point. delta2 / dmax2 above hold the
  /// fixed values (0 when not fixed).
  DualClaim objective = DualClaim::kInvalidated;
  Rational lambda;
  Rational lower_bound;
  DualPoint dual;
  ClassRegion region;  ///< class claims only
  nlohmann::ordered_json info = nlohmann::ordered_json::object();
};

}  // namespace lpvid
