#pragma once
/// TᵀT of a rational matrix, exactly, for the paper-mode T_z of (C1)
/// (Theorem 2.1; verify/certificate/c1_check.h). Column j of T is held as integers over
/// its own denominator D_j (the lcm of the column's denominators), so
///   (TᵀT)_ij = (N_iᵀ N_j) / (D_i·D_j)
/// is one integer dot product and one canonicalisation per entry, instead of
/// a rational product and sum (a gcd each) per term as in a dense rational
/// matrix product. Rows above a column's first non-zero entry are skipped.

#include "core/scalar.h"

namespace lpvid {

/// TᵀT (T.cols() square, symmetric), exact.
Mat<Rational> column_gram(const Mat<Rational>& T);

}  // namespace lpvid
