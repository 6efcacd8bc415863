#pragma once
/// One blocking of Eigen's matrix products on every machine (docs/determinism.md).
///
/// Eigen cuts a product's inner dimension into blocks of kc terms and adds
/// the blocks' partial sums one after another; kc follows the cache sizes it
/// reads from the processor at run time (a 32 KiB first-level cache gives
/// kc = 504 for doubles, a 48 KiB one 760). A product with more inner terms
/// than kc (the normal equations of a fit on a record of 1 024 samples, the
/// barrier's solves on long records) therefore has other last bits on
/// another processor. lpvid sets the sizes Eigen works with to fixed values
/// (those of the machines its figures were measured on) before it computes.

#include <cstddef>

namespace lpvid {

inline constexpr std::ptrdiff_t kEigenL1Bytes = 48 * 1024;
inline constexpr std::ptrdiff_t kEigenL2Bytes = 2 * 1024 * 1024;
inline constexpr std::ptrdiff_t kEigenL3Bytes = 260 * 1024 * 1024;

/// Sets Eigen's cache sizes to the values above. Call before any thread
/// computes (the command lines do it first; so does loading the library).
void pin_eigen_blocking();

}  // namespace lpvid
