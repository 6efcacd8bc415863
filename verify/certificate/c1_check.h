#pragma once
/// (C1) of Theorem 2.1 (docs/design.md §7.1) for a certificate, decided exactly
/// (docs/design.md §10.2). Both forms end in the exact PSD decision of verify/psd/exact_psd.h
/// on a matrix with the same PSD verdict as (C1); the text names that matrix.
///
///  - form "w" (verify/certificate/c1_w_form.cc): (C1) is
///      M = [T_zᵀT_z, T_wᵀ; T_w, δ²I] ⪰ 0     (size n + n·ny),
///    decided on the n × n Schur complement δ²·T_zᵀT_z − T_wᵀT_w (proof there);
///  - form "delta" (verify/certificate/c1_delta_form.cc): [δ²I, T_Δ; T_Δᵀ, I] ⪰ 0, i.e.
///    ‖T_Δ‖ ≤ δ, which implies (C1) for w = Δ ∗ z (certificate_check.h),
///    decided on the L·min(ny, nz) Schur complement δ²I − T_ΔT_Δᵀ (or
///    δ²I − T_ΔᵀT_Δ) after balancing.

#include <functional>
#include <string>
#include <utility>

#include "core/scalar.h"

namespace lpvid {

/// The decision on (C1), made once by one of the two named constructors.
struct C1Outcome {
  enum class Status { kFails, kHolds };
  Status status = Status::kFails;
  /// "(C1) holds: <matrix> (size N) is PSD (…)" or "(C1) fails: <why>".
  std::string text;
  static C1Outcome holding(std::string text) { return {Status::kHolds, std::move(text)}; }
  static C1Outcome failing(std::string text) { return {Status::kFails, std::move(text)}; }
  bool holds() const { return status == Status::kHolds; }
};

/// Form "w": `gram_z` = T_zᵀT_z (n × n, exact; taken by value to reuse its
/// storage), `w` the n × ny signal (T_w = signal_toeplitz(w)), δ² ≥ 0.
C1Outcome check_c1_w_form(Mat<Rational> gram_z, const Mat<Rational>& w, const Rational& delta2);
/// The same with T_zᵀT_z made by `make_gram` only when it is needed (w ≠ 0
/// and δ² > 0): the exact Gram of a long record is most of the check's work.
C1Outcome check_c1_w_form(const std::function<Mat<Rational>()>& make_gram, const Mat<Rational>& w, const Rational& delta2);

/// Form "delta": `taps` K × (ny·nz), row t = vec of the tap Δ_t (row-major
/// ny × nz, entry (i, j) at column i·nz + j), T_Δ the block lower-triangular
/// Toeplitz matrix of the taps on `horizon` samples, δ² ≥ 0.
C1Outcome check_c1_delta_form(const Mat<Rational>& taps, Eigen::Index horizon, Eigen::Index ny, Eigen::Index nz,
                              const Rational& delta2);

}  // namespace lpvid
