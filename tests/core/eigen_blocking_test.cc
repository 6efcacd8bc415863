// Eigen's product blocking pinned (core/eigen_blocking.h): a product with more
// inner terms than a block holds has other last bits under another
// processor's cache sizes, and the same bits once the sizes are pinned.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Dense>

#include "core/eigen_blocking.h"
#include "support/same_bits.h"

namespace lpvid {
namespace {

using Dense = Eigen::MatrixXd;

/// Entries over six decades with both signs: partial sums whose rounding shows their grouping.
Dense spread_matrix(Eigen::Index rows, Eigen::Index cols, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> mantissa(1.0, 2.0), decade(-3.0, 3.0);
  std::bernoulli_distribution negative(0.5);
  Dense m(rows, cols);
  for (Eigen::Index i = 0; i < m.size(); ++i) m.data()[i] = (negative(rng) ? -1.0 : 1.0) * mantissa(rng) * std::pow(10.0, decade(rng));
  return m;
}

/// A·B computed with Eigen's blocking under the given cache sizes (bytes).
Dense product_under(std::ptrdiff_t l1, std::ptrdiff_t l2, std::ptrdiff_t l3, bool pin, const Dense& a, const Dense& b) {
  Eigen::setCpuCacheSizes(l1, l2, l3);
  if (pin) pin_eigen_blocking();
  Dense c(a.rows(), b.cols());
  c.noalias() = a * b;
  return c;
}

TEST(EigenBlocking, AProductIsTheSameWhateverCachesTheProcessorReports) {
  std::mt19937_64 rng(47);
  const Dense a = spread_matrix(64, 1500, rng), b = spread_matrix(1500, 64, rng);
  // a 32 KiB / 256 KiB / 8 MiB processor and a 64 KiB / 1 MiB / 32 MiB one
  const Dense small_unpinned = product_under(32 << 10, 256 << 10, 8 << 20, false, a, b);
  const Dense large_unpinned = product_under(64 << 10, 1 << 20, 32 << 20, false, a, b);
  EXPECT_FALSE(test::same_bits(small_unpinned, large_unpinned)) << "the hazard the pin removes";
  const Dense small_pinned = product_under(32 << 10, 256 << 10, 8 << 20, true, a, b);
  const Dense large_pinned = product_under(64 << 10, 1 << 20, 32 << 20, true, a, b);
  EXPECT_TRUE(test::same_bits(small_pinned, large_pinned));
  EXPECT_EQ(Eigen::l1CacheSize(), kEigenL1Bytes);
  EXPECT_EQ(Eigen::l2CacheSize(), kEigenL2Bytes);
  EXPECT_EQ(Eigen::l3CacheSize(), kEigenL3Bytes);
}

}  // namespace
}  // namespace lpvid
