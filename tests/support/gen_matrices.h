#pragma once
/// Generators for symmetric rational matrices whose PSD verdict is known by
/// construction (docs/design.md §13.8: no rejection sampling, sized by rapidcheck's size
/// so that shrinking finds small counterexamples).
///
///   psd_gram        BᵀB, B r×n: PSD; rank ≤ r, so exactly PSD (singular) when r < n
///   pd_gram_plus    BᵀB + εI, ε > 0 (as small as 1e-30): PD
///   singular_minus  BᵀB − εI with B r×n, r < n, ε > 0: NOT_PSD (u ∈ ker B gives
///                   uᵀMu = −ε‖u‖² < 0)
///   with_negative   BᵀB − c·vvᵀ with c = (‖Bv‖² + 1)/‖v‖⁴: vᵀMv = −1 exactly
///   permutation     a uniformly shrinking permutation of 0..n−1

#include <algorithm>
#include <numeric>
#include <utility>
#include <vector>

#include <rapidcheck.h>

#include "core/scalar.h"
#include "support/gen_numbers.h"

namespace lpvid::gen {

/// Matrix size for PSD tests: 1 … 2 + size/12 (at most 10 at rapidcheck's
/// default max size 100), so exact rational references stay fast.
inline rc::Gen<int> psd_dimension() {
  return rc::gen::withSize([](int size) { return rc::gen::inRange(1, 3 + std::min(size, 100) / 12); });
}

/// Positive rationals p/q, p, q in 1..9.
inline rc::Gen<Rational> positive_rational() {
  return rc::gen::map(rc::gen::pair(rc::gen::inRange(1, 10), rc::gen::inRange(1, 10)),
                      [](const std::pair<int, int>& pq) { return Rational(pq.first) / Rational(pq.second); });
}

/// Tiny positive ε: 10^-k for k in 1..30, times 1..9 (exact rationals).
inline rc::Gen<Rational> tiny_positive() {
  return rc::gen::map(rc::gen::pair(rc::gen::inRange(1, 31), rc::gen::inRange(1, 10)), [](const std::pair<int, int>& km) {
    Rational e(km.second);
    for (int i = 0; i < km.first; ++i) e = e / Rational(10);
    return e;
  });
}

struct KnownMatrix {
  Mat<Rational> M;
  Vec<Rational> v;  // for with_negative: vᵀMv = −1; empty otherwise
  int n = 0;
  int rank_bound = 0;  // rank(M) ≤ rank_bound (gram constructions)
};

inline Mat<Rational> gram(const Mat<Rational>& B) {
  Mat<Rational> G(B.cols(), B.cols());
  for (Eigen::Index i = 0; i < B.cols(); ++i)
    for (Eigen::Index j = i; j < B.cols(); ++j) {
      Rational s(0);
      for (Eigen::Index k = 0; k < B.rows(); ++k) s += B(k, i) * B(k, j);
      G(i, j) = G(j, i) = s;
    }
  return G;
}

/// BᵀB with B r×n, r in 0..n (r < n: singular), entries small rationals.
inline rc::Gen<KnownMatrix> psd_gram(bool force_singular) {
  return rc::gen::mapcat(psd_dimension(), [force_singular](int n) {
    const int rmax = force_singular ? n - 1 : n;
    return rc::gen::mapcat(rc::gen::inRange(0, rmax + 1), [n](int r) {
      return rc::gen::map(rational_matrix(r, n, small_rational()), [n, r](const Mat<Rational>& B) {
        KnownMatrix k;
        k.M = gram(B);
        k.n = n;
        k.rank_bound = r;
        return k;
      });
    });
  });
}

/// BᵀB + εI: PD.
inline rc::Gen<KnownMatrix> pd_gram_plus() {
  return rc::gen::map(rc::gen::pair(psd_gram(false), tiny_positive()), [](const std::pair<KnownMatrix, Rational>& p) {
    KnownMatrix k = p.first;
    for (int i = 0; i < k.n; ++i) k.M(i, i) += p.second;
    k.rank_bound = k.n;
    return k;
  });
}

/// BᵀB − εI with rank(B) < n: NOT_PSD.
inline rc::Gen<KnownMatrix> singular_minus() {
  return rc::gen::map(rc::gen::pair(psd_gram(true), tiny_positive()), [](const std::pair<KnownMatrix, Rational>& p) {
    KnownMatrix k = p.first;
    for (int i = 0; i < k.n; ++i) k.M(i, i) -= p.second;
    return k;
  });
}

/// BᵀB − c·vvᵀ with vᵀMv = −1 exactly (v ≠ 0 by construction: v_0 ≠ 0).
inline rc::Gen<KnownMatrix> with_negative() {
  return rc::gen::mapcat(psd_gram(false), [](KnownMatrix k) {
    const int n = k.n;
    return rc::gen::map(rc::gen::pair(rational_matrix(n, 1, small_integer()), rc::gen::inRange(1, 5)),
                        [k, n](const std::pair<Mat<Rational>, int>& p) {
                          KnownMatrix out = k;
                          Vec<Rational> v = p.first.col(0);
                          v(0) = Rational(p.second);  // v ≠ 0
                          Rational vv(0), vMv(0);
                          for (int i = 0; i < n; ++i) vv += v(i) * v(i);
                          for (int i = 0; i < n; ++i)
                            for (int j = 0; j < n; ++j) vMv += v(i) * out.M(i, j) * v(j);
                          const Rational c = (vMv + Rational(1)) / (vv * vv);
                          for (int i = 0; i < n; ++i)
                            for (int j = 0; j < n; ++j) out.M(i, j) -= c * v(i) * v(j);
                          out.v = v;
                          return out;
                        });
  });
}

/// A permutation of 0..n−1 (argsort of random keys; shrinks toward identity).
inline rc::Gen<std::vector<int>> permutation(int n) {
  return rc::gen::map(rc::gen::container<std::vector<int>>(static_cast<std::size_t>(n), rc::gen::inRange(0, 1000)),
                      [n](const std::vector<int>& keys) {
                        std::vector<int> p(static_cast<std::size_t>(n));
                        std::iota(p.begin(), p.end(), 0);
                        std::stable_sort(p.begin(), p.end(), [&](int a, int b) {
                          return keys[static_cast<std::size_t>(a)] < keys[static_cast<std::size_t>(b)];
                        });
                        return p;
                      });
}

/// P·M·Pᵀ with (PMPᵀ)_{ij} = M_{p_i p_j}.
inline Mat<Rational> permuted(const Mat<Rational>& M, const std::vector<int>& p) {
  Mat<Rational> out(M.rows(), M.cols());
  for (Eigen::Index i = 0; i < M.rows(); ++i)
    for (Eigen::Index j = 0; j < M.cols(); ++j)
      out(i, j) = M(p[static_cast<std::size_t>(i)], p[static_cast<std::size_t>(j)]);
  return out;
}

}  // namespace lpvid::gen
