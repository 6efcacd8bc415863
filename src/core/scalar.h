#pragma once
/// Scalar types shared by the double and the exact-rational paths (docs/design.md §13.4).
///
/// Everything that builds Toeplitz matrices or LMIs is written once as
/// `template <typename T>` and instantiated for `double` and `Rational`.
/// Templated code uses only +, -, *, / and comparisons: no tolerance, no sqrt.

#include <CGAL/Gmpq.h>  // also specialises Eigen::NumTraits<CGAL::Gmpq>
#include <Eigen/Dense>

namespace lpvid {

/// The exact rational type of the project (GMP rationals through CGAL).
using Rational = CGAL::Gmpq;

template <typename T>
using Mat = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
template <typename T>
using Vec = Eigen::Matrix<T, Eigen::Dynamic, 1>;

/// A zero matrix for any scalar (Eigen's Zero() works for Gmpq too, this is
/// only a readable name).
template <typename T>
Mat<T> zeros(Eigen::Index rows, Eigen::Index cols) {
  return Mat<T>::Zero(rows, cols);
}

}  // namespace lpvid
