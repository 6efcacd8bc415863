#include "dense/rank_update_kernels.h"

#include <cstring>

#if defined(__x86_64__) && !defined(__FMA__)
#define LPVID_RANK_UPDATE_KERNELS 1
#endif

namespace lpvid::rank_update_kernel {

#ifdef LPVID_RANK_UPDATE_KERNELS

// AVX-512F has fused multiply-adds and GCC contracts a·b + c into one by
// default: not here (a fused sum is rounded once, Eigen's twice).
#pragma GCC push_options
#pragma GCC optimize("fp-contract=off")

bool available() { return __builtin_cpu_supports("avx2"); }
bool wide_available() { return __builtin_cpu_supports("avx512f"); }

namespace {

/// GCC's vector types: 4 doubles (one row group, AVX2) and 8 (two, AVX-512F).
using Vec4 = double __attribute__((vector_size(32)));
using Vec8 = double __attribute__((vector_size(64)));

/// Row groups of 4 in one vector (1 or 2).
template <class V>
constexpr Index kGroups = static_cast<Index>(sizeof(V) / sizeof(double) / 4);

/// The packed rows of kGroups<V> consecutive row groups at step k (group g's panel at a + g·4·depth).
/// (Passed by reference: a vector returned by value changes the ABI with the target.)
template <class V>
[[gnu::always_inline]] inline void rows_at(V& v, const double* a, Index depth, Index k) {
  Vec4 low;
  std::memcpy(&low, a + 4 * k, sizeof(Vec4));
  if constexpr (kGroups<V> == 1) {
    v = low;
  } else {
    Vec4 high;
    std::memcpy(&high, a + 4 * depth + 4 * k, sizeof(Vec4));
    v = __builtin_shufflevector(low, high, 0, 1, 2, 3, 4, 5, 6, 7);
  }
}

/// res[c·stride + i] −= s_c (c < 4) for the vector's rows at `res`.
template <class V>
[[gnu::always_inline]] inline void subtract(double* res, Index stride, const V& s0, const V& s1, const V& s2, const V& s3) {
  const V* s[4] = {&s0, &s1, &s2, &s3};
  for (Index c = 0; c < 4; ++c) {
    V r;
    std::memcpy(&r, res + c * stride, sizeof(V));
    r -= *s[c];
    std::memcpy(res + c * stride, &r, sizeof(V));
  }
}

/// Three vectors of rows (3·kGroups<V> row groups at a) times one column
/// panel of 4 (b): twelve sums, each lane s += a·b in k order (a product
/// rounded, then the sum rounded), named so that they stay in registers.
template <class V>
[[gnu::always_inline]] inline void block_3x4(const double* a, const double* b, Index depth, double* res, Index stride) {
  const Index next = kGroups<V> * 4 * depth;
  V s00 = {}, s01 = {}, s02 = {}, s03 = {}, s10 = {}, s11 = {}, s12 = {}, s13 = {}, s20 = {}, s21 = {}, s22 = {}, s23 = {};
  for (Index k = 0; k < depth; ++k) {
    V l0, l1, l2;
    rows_at(l0, a, depth, k);
    rows_at(l1, a + next, depth, k);
    rows_at(l2, a + 2 * next, depth, k);
    const auto column = [&](V& x0, V& x1, V& x2, double w) [[gnu::always_inline]] {
      x0 += l0 * w;
      x1 += l1 * w;
      x2 += l2 * w;
    };
    const double* w = b + 4 * k;
    column(s00, s10, s20, w[0]);
    column(s01, s11, s21, w[1]);
    column(s02, s12, s22, w[2]);
    column(s03, s13, s23, w[3]);
  }
  constexpr Index rows = 4 * kGroups<V>;
  subtract(res, stride, s00, s01, s02, s03);
  subtract(res + rows, stride, s10, s11, s12, s13);
  subtract(res + 2 * rows, stride, s20, s21, s22, s23);
}

/// One row group of 4 times one column panel of 4.
__attribute__((target("avx2"))) void block_4x4(const double* a, const double* b, Index depth, double* res, Index stride) {
  Vec4 s0 = {}, s1 = {}, s2 = {}, s3 = {};
  for (Index k = 0; k < depth; ++k) {
    Vec4 l;
    rows_at(l, a, depth, k);
    const double* w = b + 4 * k;
    s0 += l * w[0];
    s1 += l * w[1];
    s2 += l * w[2];
    s3 += l * w[3];
  }
  subtract(res, stride, s0, s1, s2, s3);
}

__attribute__((target("avx2"))) void block_12x4(const double* a, const double* b, Index depth, double* res, Index stride) {
  block_3x4<Vec4>(a, b, depth, res, stride);
}

__attribute__((target("avx512f"))) void block_24x4(const double* a, const double* b, Index depth, double* res,
                                                   Index stride) {
  block_3x4<Vec8>(a, b, depth, res, stride);
}

const bool kWide = wide_available();

}  // namespace

void minus_products(const double* blockA, const double* blockB, Index depth, Index rows, Index panels, double* res,
                    Index stride) {
  minus_products_at(kWide ? 8 : 4, blockA, blockB, depth, rows, panels, res, stride);
}

void minus_products_at(int width, const double* blockA, const double* blockB, Index depth, Index rows, Index panels,
                       double* res, Index stride) {
  const Index groups = rows / 4;
  for (Index p = 0; p < panels; ++p) {
    const double* b = blockB + p * 4 * depth;
    double* out = res + p * 4 * stride;
    Index g = 0;
    if (width == 8)
      for (; g + 6 <= groups; g += 6) block_24x4(blockA + g * 4 * depth, b, depth, out + 4 * g, stride);
    for (; g + 3 <= groups; g += 3) block_12x4(blockA + g * 4 * depth, b, depth, out + 4 * g, stride);
    for (; g < groups; ++g) block_4x4(blockA + g * 4 * depth, b, depth, out + 4 * g, stride);
  }
}

#pragma GCC pop_options

#else

bool available() { return false; }
bool wide_available() { return false; }
void minus_products(const double*, const double*, Index, Index, Index, double*, Index) {}
void minus_products_at(int, const double*, const double*, Index, Index, Index, double*, Index) {}

#endif

}  // namespace lpvid::rank_update_kernel
