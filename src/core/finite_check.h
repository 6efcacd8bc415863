#pragma once
/// The guard between a computed signal and a solver: NaN or infinity (or a
/// signal whose size overflows in double precision) is stopped where the
/// signal is made, with the stage named, instead of reaching an SDP backend
/// as a "cost -nan" with no hint of where it came from. Typical cause: a
/// model whose free run diverges along the data (unstable along the
/// trajectory), so its simulated z or residual r overflows.

#include <cmath>
#include <string>

#include <Eigen/Core>

#include "core/input_error.h"
#include "core/rms.h"

namespace lpvid {

/// Throws InputError "<stage>: <what> is not finite at sample k (row k,
/// column j) ..." unless every entry of m is finite and its RMS is finite.
/// Rows are samples.
template <typename Derived>
void check_finite_signal(const Eigen::MatrixBase<Derived>& m, const std::string& stage, const std::string& what) {
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      if (!std::isfinite(static_cast<double>(m(i, j))))
        throw InputError(stage + ": " + what + " is not finite at sample " + std::to_string(i) + " (column " +
                         std::to_string(j + 1) + " of " + std::to_string(m.cols()) +
                         "): the model's free run diverges or overflows along the data; no solver was called");
  if (!std::isfinite(rms(m)))
    throw InputError(stage + ": " + what + " is too large for double precision (its RMS overflows): the model's free "
                     "run diverges along the data; no solver was called");
}

}  // namespace lpvid
