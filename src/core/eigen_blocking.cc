#include "core/eigen_blocking.h"

#include <Eigen/Core>

namespace lpvid {

void pin_eigen_blocking() { Eigen::setCpuCacheSizes(kEigenL1Bytes, kEigenL2Bytes, kEigenL3Bytes); }

namespace {

/// A library user who never runs a command line gets the same blocking.
const bool kPinnedAtLoad = (pin_eigen_blocking(), true);

}  // namespace

}  // namespace lpvid
