#pragma once
/// Multi-output ARX least squares (Ljung, System Identification, 2nd ed.,
/// 1999, §4.2 eq. 4.7 and §7.3, written for vector signals) and its block
/// observer realisation: the LTI models of part 1 of the paper's Example 2
/// (Section 4.2: "identifying LTI models to construct a first LPV model").
///
///   y_k = Σ_{i=1..n} P_i y_{k−i} + Σ_{i=1..n} Q_i u_{k−i} + c      (no direct term)
///
/// fitted by linear least squares over k = n … N−1 (all outputs at once; the
/// regressor is shared). Its state-space form, with the state's first block
/// equal to the output, is
///
///   A = [P_1 I 0 … 0; P_2 0 I … 0; …; P_n 0 … 0],  B = [Q_1; …; Q_n],
///   C = [I 0 … 0],  D = 0
///
/// which is linear in (P, Q) apart from the identity blocks, so models of
/// this form at different operating points can be interpolated entrywise.

#include <vector>

#include "core/scalar.h"

namespace lpvid {

struct MimoArx {
  std::vector<Mat<double>> P;  ///< n matrices, ny × ny
  std::vector<Mat<double>> Q;  ///< n matrices, ny × nu
  Vec<double> c;               ///< constant (ny)
  int order() const { return static_cast<int>(P.size()); }
};

/// Least-squares fit of order n ≥ 1 to u (N × nu), y (N × ny) with a
/// constant term. Throws InputError when N − n is smaller than the number of
/// regressors n·(ny + nu) + 1.
MimoArx fit_mimo_arx(const Mat<double>& u, const Mat<double>& y, int order);

/// The block observer realisation above; `identity` false leaves the
/// identity blocks out (the ρ-dependent terms of an interpolated model).
void arx_realisation(const MimoArx& m, bool identity, Mat<double>& A, Mat<double>& B);

}  // namespace lpvid
