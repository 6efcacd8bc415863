// The rank update's vector micro-kernel (dense/rank_update_kernels.h) against
// Eigen's own general block-panel kernel on the same packed panels: every
// entry bit for bit, in 4-wide and (where the processor has it) 8-wide
// vectors; and the data are such that another summation order or a fused
// multiply-add would show.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Dense>

#include "dense/rank_update_kernels.h"
#include "support/same_bits.h"

namespace lpvid {
namespace {

namespace ei = Eigen::internal;
using Index = Eigen::Index;
using Dense = Eigen::MatrixXd;
using Traits = ei::gebp_traits<double, double>;
using Mapper = ei::blas_data_mapper<double, Index, Eigen::ColMajor, Eigen::Unaligned, 1>;

/// Values over eight decades with both signs: sums whose rounding depends on their order.
std::vector<double> spread_values(Index count, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> mantissa(1.0, 2.0), decade(-4.0, 4.0);
  std::bernoulli_distribution negative(0.5);
  std::vector<double> v(static_cast<size_t>(count));
  for (double& x : v) x = (negative(rng) ? -1.0 : 1.0) * mantissa(rng) * std::pow(10.0, decade(rng));
  return v;
}

struct PackedProduct {
  Index rows, depth, panels;
  std::vector<double> a, b;
  Dense start;

  PackedProduct(Index r, Index d, Index p, std::mt19937_64& rng)
      : rows(r), depth(d), panels(p), a(spread_values(r * d, rng)), b(spread_values(4 * p * d, rng)), start(r, 4 * p) {
    const std::vector<double> s = spread_values(start.size(), rng);
    std::copy(s.begin(), s.end(), start.data());
  }

  /// Eigen's gebp_kernel<4, 4> with alpha = −1 (the rank update's call).
  Dense eigen() const {
    Dense res = start;
    ei::gebp_kernel<double, double, Index, Mapper, Traits::mr, Traits::nr, false, false> gebp;
    gebp(Mapper(res.data(), res.outerStride(), 1), a.data(), b.data(), rows, depth, 4 * panels, -1.0, -1, -1, 0, 0);
    return res;
  }

  Dense kernel(int width) const {
    Dense res = start;
    rank_update_kernel::minus_products_at(width, a.data(), b.data(), depth, rows, panels, res.data(), res.outerStride());
    return res;
  }

  /// The same sums with fused multiply-adds, for the test's power to see a difference.
  Dense fused() const {
    Dense res = start;
    for (Index p = 0; p < panels; ++p)
      for (Index c = 0; c < 4; ++c)
        for (Index i = 0; i < rows; ++i) {
          double s = 0;
          for (Index k = 0; k < depth; ++k)
            s = std::fma(a[static_cast<size_t>(i / 4 * 4 * depth + 4 * k + i % 4)], b[static_cast<size_t>(p * 4 * depth + 4 * k + c)], s);
          res(i, 4 * p + c) -= s;
        }
    return res;
  }
};

TEST(RankUpdateKernel, EveryEntryIsEigensBitForBit) {
  if (!rank_update_kernel::available()) GTEST_SKIP() << "no AVX2 on this processor (Eigen's kernel is used)";
  std::mt19937_64 rng(41);
  for (const Index rows : {4, 8, 12, 20, 24, 28, 48, 52, 100})
    for (const Index depth : {1, 3, 8, 9, 128, 301})
      for (const Index panels : {1, 3}) {
        SCOPED_TRACE(::testing::Message() << rows << " rows, depth " << depth << ", " << panels << " panels");
        const PackedProduct product(rows, depth, panels, rng);
        const Dense reference = product.eigen();
        EXPECT_TRUE(test::same_bits(product.kernel(4), reference));
        if (rank_update_kernel::wide_available()) {
          EXPECT_TRUE(test::same_bits(product.kernel(8), reference));
        }
      }
}

// The comparison above can fail: with a fused multiply-add (one rounding
// instead of two) the same data give other bits.
TEST(RankUpdateKernel, AFusedMultiplyAddWouldBeSeen) {
  std::mt19937_64 rng(43);
  const PackedProduct product(24, 128, 1, rng);
  EXPECT_FALSE(test::same_bits(product.fused(), product.eigen()));
}

}  // namespace
}  // namespace lpvid
