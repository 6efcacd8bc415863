#include "verify/exact_psd.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <cmath>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include <gmp.h>

#include "core/number_text.h"
#include "verify/psd_filter.h"

namespace lpvid {
namespace {

// ---------------------------------------------------------------------------
// RAII arrays of GMP integers / rationals (in-place arithmetic, no temporaries).

class MpzArray {
 public:
  explicit MpzArray(std::size_t count) : count_(count), z_(new __mpz_struct[count]) {
    for (std::size_t i = 0; i < count_; ++i) mpz_init(&z_[i]);
  }
  ~MpzArray() {
    for (std::size_t i = 0; i < count_; ++i) mpz_clear(&z_[i]);
  }
  MpzArray(const MpzArray&) = delete;
  MpzArray& operator=(const MpzArray&) = delete;
  mpz_ptr operator[](std::size_t i) { return &z_[i]; }
  mpz_srcptr operator[](std::size_t i) const { return &z_[i]; }
  std::size_t size() const { return count_; }

 private:
  std::size_t count_;
  std::unique_ptr<__mpz_struct[]> z_;
};

class MpqArray {
 public:
  explicit MpqArray(std::size_t count) : count_(count), q_(new __mpq_struct[count]) {
    for (std::size_t i = 0; i < count_; ++i) mpq_init(&q_[i]);
  }
  ~MpqArray() {
    for (std::size_t i = 0; i < count_; ++i) mpq_clear(&q_[i]);
  }
  MpqArray(const MpqArray&) = delete;
  MpqArray& operator=(const MpqArray&) = delete;
  mpq_ptr operator[](std::size_t i) { return &q_[i]; }

 private:
  std::size_t count_;
  std::unique_ptr<__mpq_struct[]> q_;
};

struct Mpz {
  mpz_t z;
  Mpz() { mpz_init(z); }
  ~Mpz() { mpz_clear(z); }
  Mpz(const Mpz&) = delete;
  Mpz& operator=(const Mpz&) = delete;
};

struct Mpq {
  mpq_t q;
  Mpq() { mpq_init(q); }
  ~Mpq() { mpq_clear(q); }
  Mpq(const Mpq&) = delete;
  Mpq& operator=(const Mpq&) = delete;
};

Rational mpz_to_rational(mpz_srcptr z) {
  Mpq t;
  mpq_set_z(t.q, z);
  return Rational(t.q);
}

// ---------------------------------------------------------------------------
// The integer matrix L·M (L = lcm of all denominators > 0): same verdict as M
// and vᵀ(L·M)v = L·vᵀMv, so witnesses carry over unchanged.

struct IntegerMatrix {
  std::size_t n;
  MpzArray a;  // n×n row-major; only the upper triangle (i ≤ j) is used
  explicit IntegerMatrix(std::size_t size) : n(size), a(size * size) {}
  mpz_ptr at(std::size_t i, std::size_t j) { return a[i * n + j]; }
  mpz_srcptr at(std::size_t i, std::size_t j) const { return a[i * n + j]; }
};

std::unique_ptr<IntegerMatrix> integer_matrix(const Mat<Rational>& M) {
  const std::size_t n = static_cast<std::size_t>(M.rows());
  auto out = std::make_unique<IntegerMatrix>(n);
  Mpz L, f;
  mpz_set_ui(L.z, 1);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j) {
      mpz_srcptr d = mpq_denref(M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)).mpq());
      if (!mpz_divisible_p(L.z, d)) mpz_lcm(L.z, L.z, d);
    }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j) {
      mpq_srcptr q = M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)).mpq();
      mpz_divexact(f.z, L.z, mpq_denref(q));
      mpz_mul(out->at(i, j), mpq_numref(q), f.z);
    }
  return out;
}

/// sign of wᵀAw for the symmetric integer A (upper triangle) and integer w.
int quadratic_form_sign(const IntegerMatrix& A, const std::vector<Mpz>& w) {
  const std::size_t n = A.n;
  Mpz q, row, t;
  for (std::size_t i = 0; i < n; ++i) {
    if (mpz_sgn(w[i].z) == 0) continue;
    mpz_set_ui(row.z, 0);  // Σ_{j>i} A_ij w_j
    for (std::size_t j = i + 1; j < n; ++j)
      if (mpz_sgn(w[j].z) != 0) mpz_addmul(row.z, A.at(i, j), w[j].z);
    mpz_mul_2exp(row.z, row.z, 1);
    mpz_addmul(row.z, A.at(i, i), w[i].z);  // A_ii w_i + 2 Σ_{j>i} A_ij w_j
    mpz_addmul(q.z, row.z, w[i].z);
  }
  return mpz_sgn(q.z);
}

/// Divides w by the gcd of its entries (w ≠ 0) and returns it as rationals.
Vec<Rational> reduced_witness(std::vector<Mpz>& w) {
  Mpz g;
  for (auto& x : w) mpz_gcd(g.z, g.z, x.z);
  Vec<Rational> v(static_cast<Eigen::Index>(w.size()));
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (mpz_sgn(g.z) != 0) mpz_divexact(w[i].z, w[i].z, g.z);
    v(static_cast<Eigen::Index>(i)) = mpz_to_rational(w[i].z);
  }
  return v;
}

/// Re-checks a witness exactly; a failure is a bug in this file, never an answer.
void check_witness(const Mat<Rational>& M, const std::vector<Mpz>& w) {
  auto A = integer_matrix(M);
  if (quadratic_form_sign(*A, w) >= 0)
    throw std::logic_error("exact_psd: internal error: witness does not satisfy v'Mv < 0");
}

int resolve_threads(int threads) {
  if (threads > 0) return std::min(threads, 64);
  unsigned hw = std::thread::hardware_concurrency();
  return static_cast<int>(std::clamp(hw, 1u, 8u));
}

/// Runs f(lo, hi) on [begin, end) split into `threads` chunks of about equal
/// work, row i costing (n − i) entries.
template <typename F>
void for_rows_split(std::size_t begin, std::size_t end, std::size_t n, int threads, F&& f) {
  const std::size_t rows = end - begin;
  const double work = static_cast<double>(rows) * static_cast<double>(n - begin) / 2.0;
  if (threads <= 1 || rows < 8 || work < 4096) {
    f(begin, end);
    return;
  }
  // Chunk boundaries by cumulative work Σ (n − i).
  std::vector<std::size_t> cut{begin};
  double total = 0;
  for (std::size_t i = begin; i < end; ++i) total += static_cast<double>(n - i);
  double acc = 0;
  int part = 1;
  for (std::size_t i = begin; i < end && part < threads; ++i) {
    acc += static_cast<double>(n - i);
    if (acc >= total * part / threads) {
      cut.push_back(i + 1);
      ++part;
    }
  }
  cut.push_back(end);
  std::vector<std::thread> pool;
  for (std::size_t c = 1; c + 1 < cut.size(); ++c)
    if (cut[c] < cut[c + 1]) pool.emplace_back([&f, lo = cut[c], hi = cut[c + 1]] { f(lo, hi); });
  f(cut[0], cut[1]);
  for (auto& t : pool) t.join();
}

// ---------------------------------------------------------------------------
// Fraction-free symmetric elimination (Bareiss) with symmetric pivoting.
//
// U holds the upper triangle in LOGICAL order (perm[logical] = original row).
// After steps 0..k−1 with pivots P_0..P_{k−1} (logical rows 0..k−1):
//   U(i, j), k ≤ i ≤ j : det of the (k+1)×(k+1) submatrix of rows {0..k−1, i}
//                        and columns {0..k−1, j} (Sylvester's identity), i.e.
//                        Δ_k · S_ij with S the Schur complement and
//                        Δ_k = det(leading k×k) = U(k−1, k−1) (Δ_0 = 1) > 0;
//   U(m, j), m < k ≤ j  : row m as it was when it was the pivot row.
// The update U(i,j) ← (P·U(i,j) − U(k,i)·U(k,j)) / Δ_k is an exact division.

class Bareiss {
 public:
  Bareiss(std::unique_ptr<IntegerMatrix> A, int threads)
      : n_(A->n), U_(std::move(A)), perm_(n_), threads_(threads) {
    for (std::size_t i = 0; i < n_; ++i) perm_[i] = static_cast<long>(i);
    mpz_set_ui(delta_.z, 1);
  }

  PsdResult run(const Mat<Rational>& M) {
    for (std::size_t k = 0; k < n_; ++k) {
      // 1. Negative Schur diagonal (smallest original index) ⇒ NOT_PSD.
      std::size_t neg = n_, pos = n_;
      for (std::size_t i = k; i < n_; ++i) {
        const int s = mpz_sgn(U(i, i));
        if (s < 0 && (neg == n_ || perm_[i] < perm_[neg])) neg = i;
        if (s > 0 && (pos == n_ || perm_[i] < perm_[pos])) pos = i;
      }
      if (neg != n_) return not_psd_negative_pivot(M, k, neg);
      if (pos == n_) return zero_block(M, k);
      // 2. Pivot on the positive diagonal with the smallest original index.
      swap_logical(k, pos);
      eliminate(k);
    }
    PsdResult r;
    r.verdict = PsdVerdict::kPositiveDefinite;
    r.rank = static_cast<long>(n_);
    r.step = static_cast<long>(n_);
    r.reason = "exact LDL^T: all " + std::to_string(n_) + " pivots are positive";
    return r;
  }

 private:
  mpz_ptr U(std::size_t i, std::size_t j) { return U_->at(i, j); }

  /// Exchanges logical positions k < p of the symmetric matrix whose upper
  /// triangle is stored (rows < k are finished pivot rows; they are permuted
  /// along, which is what the back-substitution needs).
  void swap_logical(std::size_t k, std::size_t p) {
    if (k == p) return;
    for (std::size_t i = 0; i < k; ++i) mpz_swap(U(i, k), U(i, p));
    mpz_swap(U(k, k), U(p, p));
    for (std::size_t i = k + 1; i < p; ++i) mpz_swap(U(k, i), U(i, p));
    for (std::size_t j = p + 1; j < n_; ++j) mpz_swap(U(k, j), U(p, j));
    std::swap(perm_[k], perm_[p]);
  }

  void eliminate(std::size_t k) {
    mpz_srcptr P = U(k, k);
    const bool first = mpz_cmp_ui(delta_.z, 1) == 0;
    for_rows_split(k + 1, n_, n_, threads_, [&](std::size_t lo, std::size_t hi) {
      Mpz t;
      for (std::size_t i = lo; i < hi; ++i) {
        mpz_srcptr a_ki = U(k, i);
        const bool zero_ki = mpz_sgn(a_ki) == 0;
        for (std::size_t j = i; j < n_; ++j) {
          mpz_ptr a_ij = U(i, j);
          if (zero_ki) {
            if (mpz_sgn(a_ij) == 0) continue;
            mpz_mul(t.z, P, a_ij);
          } else {
            mpz_mul(t.z, P, a_ij);
            mpz_submul(t.z, a_ki, U(k, j));
          }
          if (first)
            mpz_swap(a_ij, t.z);
          else
            mpz_divexact(a_ij, t.z, delta_.z);
        }
      }
    });
    mpz_set(delta_.z, P);
  }

  /// v (logical order, integers) = Δ_k · [−M_PP⁻¹ M_P· x; x] by back-substitution
  /// with the stored pivot rows; every division is exact (Cramer: Δ_k·M_PP⁻¹
  /// is the adjugate, an integer matrix). x is given on logical rows ≥ k.
  std::vector<Mpz> witness_logical(std::size_t k, const std::vector<std::pair<std::size_t, long>>& x) {
    std::vector<Mpz> w(n_);
    for (const auto& [i, xi] : x) mpz_mul_si(w[i].z, delta_.z, xi);
    Mpz t;
    for (std::size_t m = k; m-- > 0;) {
      mpz_set_ui(t.z, 0);
      for (std::size_t j = m + 1; j < n_; ++j)
        if (mpz_sgn(w[j].z) != 0) mpz_addmul(t.z, U(m, j), w[j].z);
      mpz_neg(t.z, t.z);
      mpz_divexact(w[m].z, t.z, U(m, m));
    }
    return w;
  }

  /// Maps a logical witness to original order, re-checks it, reduces it.
  Vec<Rational> finish_witness(const Mat<Rational>& M, std::vector<Mpz> w_logical) {
    std::vector<Mpz> w(n_);
    for (std::size_t i = 0; i < n_; ++i) mpz_swap(w[static_cast<std::size_t>(perm_[i])].z, w_logical[i].z);
    check_witness(M, w);
    return reduced_witness(w);
  }

  std::string schur_value_text(mpz_srcptr numerator) {
    // S = numerator / Δ_k; print only when short.
    if (mpz_sizeinbase(numerator, 2) + mpz_sizeinbase(delta_.z, 2) > 256) return {};
    Mpq s;
    mpq_set_num(s.q, numerator);
    mpq_set_den(s.q, delta_.z);
    mpq_canonicalize(s.q);
    return rational_to_text(Rational(s.q));
  }

  PsdResult not_psd_negative_pivot(const Mat<Rational>& M, std::size_t k, std::size_t i) {
    PsdResult r;
    r.verdict = PsdVerdict::kNotPsd;
    r.pivot_index = perm_[i];
    r.step = static_cast<long>(k);
    std::string value = schur_value_text(U(i, i));
    r.reason = "exact LDL^T: after " + std::to_string(k) + " positive pivot(s) the pivot of row " +
               std::to_string(perm_[i]) + " is negative" + (value.empty() ? "" : " (" + value + ")");
    r.witness = finish_witness(M, witness_logical(k, {{i, 1}}));
    return r;
  }

  PsdResult zero_block(const Mat<Rational>& M, std::size_t k) {
    // Every remaining diagonal is 0. Find the nonzero off-diagonal entry with
    // the smallest (original row, original column).
    std::size_t bi = n_, bj = n_;
    std::pair<long, long> best{-1, -1};
    for (std::size_t i = k; i < n_; ++i)
      for (std::size_t j = i + 1; j < n_; ++j)
        if (mpz_sgn(U(i, j)) != 0) {
          std::pair<long, long> key{std::min(perm_[i], perm_[j]), std::max(perm_[i], perm_[j])};
          if (bi == n_ || key < best) {
            best = key;
            bi = i;
            bj = j;
          }
        }
    PsdResult r;
    r.step = static_cast<long>(k);
    if (bi == n_) {
      r.verdict = PsdVerdict::kPositiveSemidefinite;
      r.rank = static_cast<long>(k);
      long first = n_ > k ? perm_[k] : -1;
      for (std::size_t i = k; i < n_; ++i) first = std::min(first, perm_[i]);
      r.pivot_index = first;
      r.reason = "exact LDL^T: " + std::to_string(k) + " positive pivot(s), then the remaining " +
                 std::to_string(n_ - k) + "x" + std::to_string(n_ - k) +
                 " Schur complement is exactly zero (rank " + std::to_string(k) + " < n = " +
                 std::to_string(n_) + ")";
      return r;
    }
    // x = e_i − sign(b)·e_j: xᵀSx = S_ii + S_jj − 2|S_ij| = −2|b| < 0.
    r.verdict = PsdVerdict::kNotPsd;
    const std::size_t i = perm_[bi] < perm_[bj] ? bi : bj, j = i == bi ? bj : bi;
    r.pivot_index = perm_[i];
    r.reason = "exact LDL^T: after " + std::to_string(k) + " positive pivot(s) the pivot of row " +
               std::to_string(perm_[i]) + " is 0 but its row is not (entry with row " + std::to_string(perm_[j]) +
               "): the 2x2 principal minor [[0,b],[b,0]] with b != 0 is indefinite";
    const long sj = -mpz_sgn(U(bi, bj));
    r.witness = finish_witness(M, witness_logical(k, {{i, 1}, {j, sj}}));
    return r;
  }

  std::size_t n_;
  std::unique_ptr<IntegerMatrix> U_;
  std::vector<long> perm_;
  int threads_;
  Mpz delta_;  // Δ_k, the previous pivot (1 before the first step)
};

// ---------------------------------------------------------------------------
// Multi-modular symmetric elimination (the fast exact path).
//
// The same elimination as Bareiss, carried out modulo many 31-bit primes and
// lifted by the Chinese remainder theorem. Every quantity that is lifted is a
// minor of the integer matrix A (or a determinant of a submatrix of it), so
// its absolute value is at most Hadamard's bound H = Π_i max(1, ‖A_i‖₂); the
// primes are taken until their product P > 4H, so the symmetric residue mod
// P is the exact integer. Nothing here is probabilistic:
//   1. The pivot order π is chosen modulo the first prime p₀: at step k the
//      remaining row with the smallest original index whose Schur diagonal is
//      ≠ 0 mod p₀ (hence ≠ 0 exactly). It stops at r when all remaining Schur
//      diagonals are ≡ 0 mod p₀.
//   2. For every prime: eliminate r steps of A_π (a prime where a pivot
//      vanishes is discarded). Record the pivots (→ the leading principal
//      minors Δ_k of A_π) and which entries of the remaining Schur block are
//      ≠ 0 mod p.
//   3. Lift Δ_1..Δ_r (all ≠ 0 exactly by step 1). The first Δ_k < 0 gives
//      NOT_PSD. Otherwise a Schur entry is exactly 0 iff it is 0 mod every
//      prime (its bordered minor is below P/2). All zero: PSD of rank r (PD if
//      r = n). Zero diagonal but a nonzero entry: NOT_PSD by a 2×2 minor.
//      A remaining diagonal that is ≠ 0 exactly but ≡ 0 mod p₀ (p₀ divides
//      it: "unlucky") is not decided here: the caller falls back to Bareiss.
//   4. Witnesses: the integer vector Δ_K·[−A₁₁⁻¹A₁ₜ; e_t] (entries are K×K
//      determinants by Cramer's rule) is computed mod every prime by
//      back-substitution and lifted, then checked exactly as always.

__extension__ typedef unsigned __int128 u128;

/// Residues live in 32-bit words: p < 2^31, so l·x < 2^62 and the Shoup
/// remainder l·x − q·p lies in [0, 2p) ⊂ [0, 2^32): exact in uint32.
using Word = std::uint32_t;

inline Word mul_mod(Word a, Word b, Word p) {
  return static_cast<Word>(static_cast<std::uint64_t>(a) * b % p);
}
/// Shoup's precomputation ⌊w·2^32/p⌋ for multiplying by the fixed w < p.
inline Word shoup(Word w, Word p) { return static_cast<Word>((static_cast<std::uint64_t>(w) << 32) / p); }

/// row_i[j] ← row_i[j] − l·row_k[j] mod p, j < len (Shoup multiplication by
/// l with lp = shoup(l, p)). Compiled for AVX-512, AVX2 and baseline x86-64
/// and chosen at load time (target_clones); all are the same exact integer
/// code (only the vector width differs).
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
void subtract_multiple(Word* __restrict row_i, const Word* __restrict row_k, std::size_t len, Word l, Word lp,
                       Word p) {
  for (std::size_t j = 0; j < len; ++j) {
    const Word x = row_k[j];
    const Word q = static_cast<Word>((static_cast<std::uint64_t>(lp) * x) >> 32);
    Word t = l * x - q * p;  // in [0, 2p)
    t = t >= p ? t - p : t;
    const Word a = row_i[j];
    row_i[j] = a >= t ? a - t : a + (p - t);
  }
}

/// x·w mod p with wp = shoup(w, p) (no division).
inline Word mul_shoup(Word x, Word w, Word wp, Word p) {
  const Word q = static_cast<Word>((static_cast<std::uint64_t>(wp) * x) >> 32);
  const Word t = w * x - q * p;  // in [0, 2p)
  return t >= p ? t - p : t;
}

/// a⁻¹ mod p, or false if gcd(a, p) ≠ 1.
bool inv_mod(Word a, Word p, Word* out) {
  std::int64_t t = 0, new_t = 1;
  std::int64_t r = p, new_r = a;
  while (new_r != 0) {
    const std::int64_t q = r / new_r;
    const std::int64_t tt = t - q * new_t;
    t = new_t;
    new_t = tt;
    const std::int64_t rr = r - q * new_r;
    r = new_r;
    new_r = rr;
  }
  if (r != 1) return false;
  *out = static_cast<Word>(t < 0 ? t + p : t);
  return true;
}

/// Bits credited to each prime (all primes lie in (2^31 − 2^24, 2^31)).
constexpr unsigned kPrimeBits = 30;

/// The first `count` primes above 2^31 − 2^24 (cached; thread-safe).
std::vector<Word> modular_primes(std::size_t count) {
  static std::mutex mutex;
  static std::vector<Word> cache;
  std::lock_guard<std::mutex> lock(mutex);
  if (cache.size() < count) {
    Mpz z;
    mpz_set_ui(z.z, (1ul << 31) - (1ul << 24));
    if (!cache.empty()) mpz_set_ui(z.z, cache.back());
    while (cache.size() < count) {
      mpz_nextprime(z.z, z.z);
      if (mpz_cmp_ui(z.z, 1ul << 31) >= 0) throw std::runtime_error("exact_psd: out of 31-bit primes");
      cache.push_back(static_cast<Word>(mpz_get_ui(z.z)));
    }
  }
  return std::vector<Word>(cache.begin(), cache.begin() + static_cast<std::ptrdiff_t>(count));
}

/// A_π's upper triangle in logical order, ready to be reduced mod p.
struct LogicalInts {
  std::size_t n = 0;
  std::vector<std::int64_t> small;  // value when it fits in 63 bits
  std::vector<mpz_srcptr> big;      // else the integer (nullptr when small)

  LogicalInts(const IntegerMatrix& A, const std::vector<long>& perm) : n(A.n), small(n * n, 0), big(n * n, nullptr) {
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a; b < n; ++b) {
        const auto i = static_cast<std::size_t>(perm[a]), j = static_cast<std::size_t>(perm[b]);
        mpz_srcptr z = A.at(std::min(i, j), std::max(i, j));
        if (mpz_fits_slong_p(z))
          small[a * n + b] = mpz_get_si(z);
        else
          big[a * n + b] = z;
      }
  }
  /// Entry (a, b) mod p; `m` = ⌊2^64/p⌋ (Barrett: q = ⌊|x|·m/2^64⌋ ≤ ⌊|x|/p⌋
  /// and |x| − q·p < 2p).
  Word mod(std::size_t a, std::size_t b, Word p, std::uint64_t m) const {
    const std::size_t idx = a * n + b;
    if (big[idx]) return static_cast<Word>(mpz_fdiv_ui(big[idx], p));
    const std::int64_t v = small[idx];
    const std::uint64_t x = v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
    const std::uint64_t q = static_cast<std::uint64_t>((static_cast<u128>(x) * m) >> 64);
    std::uint64_t r = x - q * p;
    if (r >= p) r -= p;
    return static_cast<Word>(v < 0 && r != 0 ? p - r : r);
  }
  /// The m×m upper triangle of rows/columns `rows` (logical, increasing) mod p.
  void fill(const std::vector<std::size_t>& rows, Word p, std::vector<Word>& out) const {
    const std::size_t m = rows.size();
    const std::uint64_t barrett = ~std::uint64_t{0} / p;  // = ⌊2^64/p⌋ (p is not a power of 2)
    out.assign(m * m, 0);
    for (std::size_t a = 0; a < m; ++a)
      for (std::size_t b = a; b < m; ++b) out[a * m + b] = mod(rows[a], rows[b], p, barrett);
  }
};

/// One elimination step k on the m×m upper triangle `a` mod p with the pivot
/// inverse `inv`: row i ← row i − (a_ki/a_kk)·row k for i > k, columns ≥ i.
void modular_step(Word* a, std::size_t m, std::size_t k, Word inv, Word p) {
  const Word* row_k = a + k * m;
  const Word inv_shoup = shoup(inv, p);
  for (std::size_t i = k + 1; i < m; ++i) {
    const Word a_ki = row_k[i];
    if (a_ki == 0) continue;
    const Word l = mul_shoup(a_ki, inv, inv_shoup, p);
    subtract_multiple(a + i * m + i, row_k + i, m - i, l, shoup(l, p), p);
  }
}

/// Step 1: pivot order and rank modulo p₀ (see the section comment).
void choose_pivots_mod(const IntegerMatrix& A, Word p, std::vector<long>* perm, std::size_t* rank) {
  const std::size_t n = A.n;
  perm->resize(n);
  for (std::size_t i = 0; i < n; ++i) (*perm)[i] = static_cast<long>(i);
  LogicalInts ints(A, *perm);
  std::vector<std::size_t> all(n);
  for (std::size_t i = 0; i < n; ++i) all[i] = i;
  std::vector<Word> a;
  ints.fill(all, p, a);
  auto at = [&](std::size_t i, std::size_t j) -> Word& { return a[i * n + j]; };
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t pos = n;
    for (std::size_t i = k; i < n; ++i)
      if (at(i, i) != 0 && (pos == n || (*perm)[i] < (*perm)[pos])) pos = i;
    if (pos == n) {
      *rank = k;
      return;
    }
    if (pos != k) {  // symmetric exchange of logical k and pos (as Bareiss::swap_logical)
      for (std::size_t i = 0; i < k; ++i) std::swap(at(i, k), at(i, pos));
      std::swap(at(k, k), at(pos, pos));
      for (std::size_t i = k + 1; i < pos; ++i) std::swap(at(k, i), at(i, pos));
      for (std::size_t j = pos + 1; j < n; ++j) std::swap(at(k, j), at(pos, j));
      std::swap((*perm)[k], (*perm)[pos]);
    }
    Word inv = 0;
    if (!inv_mod(at(k, k), p, &inv)) {  // p not prime: impossible for nextprime output
      *rank = k;
      return;
    }
    modular_step(a.data(), n, k, inv, p);
  }
  *rank = n;
}

/// Lifts residues (one per prime) to the integer in (−P/2, P/2].
class Crt {
 public:
  explicit Crt(const std::vector<Word>& primes) : primes_(primes), basis_(primes.size()) {
    mpz_set_ui(P_.z, 1);
    for (Word p : primes_) mpz_mul_ui(P_.z, P_.z, p);
    Mpz q, inv, pz;
    for (std::size_t i = 0; i < primes_.size(); ++i) {
      mpz_divexact_ui(q.z, P_.z, primes_[i]);
      mpz_set_ui(pz.z, primes_[i]);
      if (!mpz_invert(inv.z, q.z, pz.z)) ok_ = false;  // moduli not coprime: never for distinct primes
      mpz_mul(basis_[i].z, q.z, inv.z);
    }
    mpz_fdiv_q_2exp(half_.z, P_.z, 1);
  }
  bool ok() const { return ok_; }
  std::size_t bits() const { return mpz_sizeinbase(P_.z, 2); }
  /// residue(i) for prime i.
  template <typename R>
  void lift(R&& residue, mpz_ptr out) const {
    mpz_set_ui(out, 0);
    for (std::size_t i = 0; i < primes_.size(); ++i) {
      const Word r = residue(i);
      if (r) mpz_addmul_ui(out, basis_[i].z, r);
    }
    mpz_mod(out, out, P_.z);
    if (mpz_cmp(out, half_.z) > 0) mpz_sub(out, out, P_.z);
  }

 private:
  std::vector<Word> primes_;
  std::vector<Mpz> basis_;
  Mpz P_, half_;
  bool ok_ = true;
};

/// log₂ of Hadamard's bound, rounded up: Σ_i ⌈log₂ max(1, ‖A_i‖₂)⌉.
std::size_t hadamard_bits(const IntegerMatrix& A) {
  Mpz s;
  std::size_t bits = 0;
  for (std::size_t i = 0; i < A.n; ++i) {
    mpz_set_ui(s.z, 0);
    for (std::size_t j = 0; j < A.n; ++j) {
      mpz_srcptr z = A.at(std::min(i, j), std::max(i, j));
      mpz_addmul(s.z, z, z);
    }
    if (mpz_sgn(s.z) != 0) bits += (mpz_sizeinbase(s.z, 2) + 1) / 2;  // ‖A_i‖ < 2^⌈bitlen/2⌉
  }
  return bits;
}

/// Runs f(i, scratch) for i in [0, count) on `threads` workers.
template <typename F>
void parallel_for(std::size_t count, int threads, F&& f) {
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    std::vector<Word> scratch;
    for (std::size_t i = next++; i < count; i = next++) f(i, scratch);
  };
  const int workers = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), count));
  std::vector<std::thread> pool;
  for (int t = 1; t < workers; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
}

/// Outcome of the multi-modular path: a result, or "undecided" (unlucky p₀).
struct ModularOutcome {
  bool decided = false;
  PsdResult result;
};

class ModularElimination {
 public:
  ModularElimination(const Mat<Rational>& M, int threads) : M_(M), A_(integer_matrix(M)), threads_(threads) {}

  ModularOutcome run() {
    const std::size_t n = A_->n;
    const std::size_t need_bits = hadamard_bits(*A_) + 3;  // P > 2H with margin
    std::size_t count = need_bits / kPrimeBits + 1;
    primes_ = modular_primes(count);
    choose_pivots_mod(*A_, primes_[0], &perm_, &rank_);
    ints_ = std::make_unique<LogicalInts>(*A_, perm_);
    const std::size_t r = rank_, rest = n - r;

    // Step 2 over all primes (more primes if some were discarded).
    std::vector<std::vector<Word>> pivots;  // per good prime
    std::vector<Word> good;
    std::vector<char> nonzero(rest * rest, 0);  // Schur block entry ≠ 0 mod some prime
    std::mutex merge;
    std::size_t first_unused = 0;
    while (good.size() * kPrimeBits < need_bits) {
      const std::size_t missing = (need_bits - good.size() * kPrimeBits + kPrimeBits - 1) / kPrimeBits;
      std::vector<Word> batch = modular_primes(first_unused + missing);
      batch.erase(batch.begin(), batch.begin() + static_cast<std::ptrdiff_t>(first_unused));
      first_unused += missing;
      if (first_unused > count + 64) return {};  // absurdly many bad primes: let Bareiss decide
      std::vector<std::vector<Word>> batch_pivots(batch.size());
      std::vector<char> batch_ok(batch.size(), 0);
      std::vector<std::size_t> all(n);
      for (std::size_t i = 0; i < n; ++i) all[i] = i;
      parallel_for(batch.size(), threads_, [&](std::size_t b, std::vector<Word>& a) {
        const Word p = batch[b];
        ints_->fill(all, p, a);
        std::vector<Word> piv(r);
        for (std::size_t k = 0; k < r; ++k) {
          Word inv = 0;
          if (a[k * n + k] == 0 || !inv_mod(a[k * n + k], p, &inv)) return;  // discard this prime
          piv[k] = a[k * n + k];
          modular_step(a.data(), n, k, inv, p);
        }
        std::vector<char> local(rest * rest, 0);
        bool any = false;
        for (std::size_t i = r; i < n; ++i)
          for (std::size_t j = i; j < n; ++j)
            if (a[i * n + j] != 0) local[(i - r) * rest + (j - r)] = any = true;
        if (any) {
          std::lock_guard<std::mutex> lock(merge);
          for (std::size_t x = 0; x < local.size(); ++x) nonzero[x] |= local[x];
        }
        batch_pivots[b] = std::move(piv);
        batch_ok[b] = 1;
      });
      for (std::size_t b = 0; b < batch.size(); ++b)
        if (batch_ok[b]) {
          good.push_back(batch[b]);
          pivots.push_back(std::move(batch_pivots[b]));
        }
    }
    primes_ = good;
    Crt crt(primes_);
    if (!crt.ok()) return {};

    // Step 3: leading principal minors Δ_k = Π_{t<k} pivot_t.
    std::vector<Word> delta(primes_.size(), 1);
    Mpz value;
    PsdResult res;
    res.method = PsdMethod::kExactLdlt;
    for (std::size_t k = 0; k < r; ++k) {
      for (std::size_t i = 0; i < primes_.size(); ++i) delta[i] = mul_mod(delta[i], pivots[i][k], primes_[i]);
      crt.lift([&](std::size_t i) { return delta[i]; }, value.z);
      if (mpz_sgn(value.z) < 0) {
        // S_kk = Δ_{k+1}/Δ_k < 0 after k positive pivots.
        res.verdict = PsdVerdict::kNotPsd;
        res.step = static_cast<long>(k);
        res.pivot_index = perm_[k];
        res.reason = "exact LDL^T: after " + std::to_string(k) + " positive pivot(s) the pivot of row " +
                     std::to_string(perm_[k]) + " is negative";
        if (!witness(k, {k}, &res)) return {};
        return {true, res};
      }
    }
    const std::string how = " (multi-modular: " + std::to_string(primes_.size()) + " primes of 31 bits, CRT)";
    // Remaining Schur block.
    bool any = false, any_diag = false;
    for (std::size_t i = 0; i < rest; ++i) {
      any_diag = any_diag || nonzero[i * rest + i];
      for (std::size_t j = i; j < rest; ++j) any = any || nonzero[i * rest + j];
    }
    res.step = static_cast<long>(r);
    if (!any) {
      res.rank = static_cast<long>(r);
      if (r == n) {
        res.verdict = PsdVerdict::kPositiveDefinite;
        res.reason = "exact LDL^T: all " + std::to_string(n) + " pivots are positive" + how;
      } else {
        res.verdict = PsdVerdict::kPositiveSemidefinite;
        long first = perm_[r];
        for (std::size_t i = r; i < n; ++i) first = std::min(first, perm_[i]);
        res.pivot_index = first;
        res.reason = "exact LDL^T: " + std::to_string(r) + " positive pivot(s), then the remaining " +
                     std::to_string(rest) + "x" + std::to_string(rest) + " Schur complement is exactly zero (rank " +
                     std::to_string(r) + " < n = " + std::to_string(n) + ")" + how;
      }
      return {true, res};
    }
    if (any_diag) return {};  // p₀ divides a nonzero Schur diagonal: let Bareiss decide
    // Zero diagonal, nonzero entry: smallest (original row, original column).
    std::size_t bi = rest, bj = rest;
    std::pair<long, long> best{-1, -1};
    for (std::size_t i = 0; i < rest; ++i)
      for (std::size_t j = i + 1; j < rest; ++j)
        if (nonzero[i * rest + j]) {
          std::pair<long, long> key{std::min(perm_[r + i], perm_[r + j]), std::max(perm_[r + i], perm_[r + j])};
          if (bi == rest || key < best) {
            best = key;
            bi = i;
            bj = j;
          }
        }
    const std::size_t li = r + (perm_[r + bi] < perm_[r + bj] ? bi : bj);
    const std::size_t lj = li == r + bi ? r + bj : r + bi;
    res.verdict = PsdVerdict::kNotPsd;
    res.pivot_index = perm_[li];
    res.reason = "exact LDL^T: after " + std::to_string(r) + " positive pivot(s) the pivot of row " +
                 std::to_string(perm_[li]) + " is 0 but its row is not (entry with row " + std::to_string(perm_[lj]) +
                 "): the 2x2 principal minor [[0,b],[b,0]] with b != 0 is indefinite";
    if (!witness(r, {std::min(li, lj), std::max(li, lj)}, &res, li)) return {};
    return {true, res};
  }

 private:
  /// Step 4. K leading pivots; targets t (logical ≥ K, increasing). For one
  /// target: w = Δ_K·[−A₁₁⁻¹A₁ₜ; 1]. For two targets i = `first` and j:
  /// w = w(i) − sign(S_ij)·w(j). Fills res->witness (checked exactly).
  bool witness(std::size_t K, const std::vector<std::size_t>& targets, PsdResult* res, std::size_t first = 0) {
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < K; ++i) rows.push_back(i);
    for (std::size_t t : targets) rows.push_back(t);
    const std::size_t m = rows.size(), T = targets.size();
    // residues[prime][target][0..K]: w entries 0..K−1 and Δ_K; plus S_ij·Δ_K.
    std::vector<std::vector<Word>> wres(primes_.size(), std::vector<Word>(T * (K + 1) + 1, 0));
    std::vector<char> ok(primes_.size(), 0);
    parallel_for(primes_.size(), threads_, [&](std::size_t pi, std::vector<Word>& a) {
      const Word p = primes_[pi];
      ints_->fill(rows, p, a);
      std::vector<Word> inv(K);
      Word delta = 1;
      for (std::size_t k = 0; k < K; ++k) {
        if (a[k * m + k] == 0 || !inv_mod(a[k * m + k], p, &inv[k])) return;
        delta = mul_mod(delta, a[k * m + k], p);
        modular_step(a.data(), m, k, inv[k], p);
      }
      std::vector<Word> w(m);
      for (std::size_t t = 0; t < T; ++t) {
        std::fill(w.begin(), w.end(), 0);
        w[K + t] = delta;
        for (std::size_t mm = K; mm-- > 0;) {
          u128 s = 0;  // < m·2^62: cannot overflow
          for (std::size_t j = mm + 1; j < m; ++j) s += static_cast<std::uint64_t>(a[mm * m + j]) * w[j];
          const Word sp = static_cast<Word>(s % p);
          w[mm] = mul_mod(sp == 0 ? 0 : p - sp, inv[mm], p);
        }
        for (std::size_t x = 0; x < K; ++x) wres[pi][t * (K + 1) + x] = w[x];
        wres[pi][t * (K + 1) + K] = delta;
      }
      if (T == 2) wres[pi][T * (K + 1)] = mul_mod(a[K * m + K + 1], delta, p);
      ok[pi] = 1;
    });
    for (char c : ok)
      if (!c) return false;
    Crt crt(primes_);
    // Integer witness on logical rows: Σ_t coef_t · w(t).
    std::vector<Mpz> w_logical(A_->n);
    Mpz val;
    std::vector<long> coef(T, 1);
    if (T == 2) {
      crt.lift([&](std::size_t i) { return wres[i][T * (K + 1)]; }, val.z);
      const long s = mpz_sgn(val.z);
      if (s == 0) return false;
      // x = e_first − sign(S_ij)·e_other
      coef[targets[0] == first ? 1 : 0] = -s;
    }
    for (std::size_t t = 0; t < T; ++t) {
      for (std::size_t x = 0; x <= K; ++x) {
        crt.lift([&](std::size_t i) { return wres[i][t * (K + 1) + x]; }, val.z);
        const std::size_t logical = x < K ? x : targets[t];
        if (coef[t] > 0)
          mpz_add(w_logical[logical].z, w_logical[logical].z, val.z);
        else
          mpz_sub(w_logical[logical].z, w_logical[logical].z, val.z);
      }
    }
    std::vector<Mpz> w(A_->n);
    for (std::size_t i = 0; i < A_->n; ++i) mpz_swap(w[static_cast<std::size_t>(perm_[i])].z, w_logical[i].z);
    check_witness(M_, w);
    res->witness = reduced_witness(w);
    return true;
  }

  const Mat<Rational>& M_;
  std::unique_ptr<IntegerMatrix> A_;
  int threads_;
  std::vector<Word> primes_;
  std::vector<long> perm_;
  std::size_t rank_ = 0;
  std::unique_ptr<LogicalInts> ints_;
};

/// Integer vector proportional (positive factor) to a finite double vector.
std::vector<Mpz> integer_vector_of_doubles(const Vec<double>& v) {
  const std::size_t n = static_cast<std::size_t>(v.size());
  std::vector<Mpz> w(n);
  long emin = 0;
  bool any = false;
  std::vector<long long> mant(n, 0);
  std::vector<long> expo(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = v(static_cast<Eigen::Index>(i));
    if (x == 0) continue;
    int e = 0;
    const double f = std::frexp(x, &e);  // x = f·2^e, 0.5 ≤ |f| < 1
    mant[i] = static_cast<long long>(std::ldexp(f, 53));  // exact
    expo[i] = e - 53;
    emin = any ? std::min(emin, expo[i]) : expo[i];
    any = true;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (mant[i] == 0) continue;
    mpz_set_si(w[i].z, static_cast<long>(mant[i]));
    mpz_mul_2exp(w[i].z, w[i].z, static_cast<mp_bitcnt_t>(expo[i] - emin));
  }
  return w;
}

}  // namespace

const char* verdict_word(PsdVerdict v) {
  switch (v) {
    case PsdVerdict::kPositiveDefinite:
      return "PD";
    case PsdVerdict::kPositiveSemidefinite:
      return "PSD";
    case PsdVerdict::kNotPsd:
      return "NOT_PSD";
  }
  return "NOT_PSD";
}

void require_symmetric(const Mat<Rational>& M) {
  if (M.rows() != M.cols())
    throw std::invalid_argument("matrix is not square: " + std::to_string(M.rows()) + " rows, " +
                                std::to_string(M.cols()) + " columns");
  for (Eigen::Index i = 0; i < M.rows(); ++i)
    for (Eigen::Index j = i + 1; j < M.cols(); ++j)
      if (!mpq_equal(M(i, j).mpq(), M(j, i).mpq()))
        throw std::invalid_argument("matrix is not symmetric: entry (" + std::to_string(i) + "," +
                                    std::to_string(j) + ") = " + rational_to_text(M(i, j)) + " but (" +
                                    std::to_string(j) + "," + std::to_string(i) + ") = " +
                                    rational_to_text(M(j, i)) + " (0-based)");
}

PsdResult decide_psd_exact(const Mat<Rational>& M, int threads) {
  require_symmetric(M);
  ModularElimination modular(M, resolve_threads(threads));
  ModularOutcome outcome = modular.run();
  if (outcome.decided) return outcome.result;
  return decide_psd_bareiss(M, threads);  // p₀ was unlucky (see the section comment)
}

PsdResult decide_psd_bareiss(const Mat<Rational>& M, int threads) {
  require_symmetric(M);
  Bareiss elimination(integer_matrix(M), resolve_threads(threads));
  PsdResult r = elimination.run(M);
  r.method = PsdMethod::kExactLdlt;
  return r;
}

PsdResult decide_psd_rational_ldlt(const Mat<Rational>& M) {
  require_symmetric(M);
  const std::size_t n = static_cast<std::size_t>(M.rows());
  // S: upper triangle by ORIGINAL index (no physical permutation).
  MpqArray S(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j)
      mpq_set(S[i * n + j], M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)).mpq());
  auto at = [&](std::size_t i, std::size_t j) { return i <= j ? S[i * n + j] : S[j * n + i]; };

  std::vector<std::size_t> rem(n), piv;  // rem stays sorted by original index
  for (std::size_t i = 0; i < n; ++i) rem[i] = i;

  PsdResult r;
  r.method = PsdMethod::kExactLdlt;
  // Witness: x on remaining rows, then v_p = −(Σ_{j≠p} S_pj v_j)/S_pp for the
  // pivots in reverse order (S_p· is row p as it was when p was pivoted).
  auto make_witness = [&](const std::vector<std::pair<std::size_t, long>>& x) {
    MpqArray v(n);
    for (const auto& [i, xi] : x) mpq_set_si(v[i], xi, 1);
    Mpq t, prod;
    for (std::size_t m = piv.size(); m-- > 0;) {
      const std::size_t p = piv[m];
      mpq_set_ui(t.q, 0, 1);
      for (std::size_t j = 0; j < n; ++j)
        if (j != p && mpq_sgn(v[j]) != 0) {
          mpq_mul(prod.q, at(p, j), v[j]);
          mpq_add(t.q, t.q, prod.q);
        }
      mpq_div(v[p], t.q, at(p, p));
      mpq_neg(v[p], v[p]);
    }
    Vec<Rational> out(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) out(static_cast<Eigen::Index>(i)) = Rational(v[i]);
    return out;
  };

  Mpq l, prod;
  for (std::size_t k = 0;; ++k) {
    r.step = static_cast<long>(k);
    if (rem.empty()) {
      r.verdict = PsdVerdict::kPositiveDefinite;
      r.rank = static_cast<long>(n);
      r.reason = "rational LDL^T: all " + std::to_string(n) + " pivots are positive";
      return r;
    }
    std::size_t neg = n, pos = n;
    for (std::size_t i : rem) {
      const int s = mpq_sgn(at(i, i));
      if (s < 0 && neg == n) neg = i;
      if (s > 0 && pos == n) pos = i;
    }
    if (neg != n) {
      r.verdict = PsdVerdict::kNotPsd;
      r.pivot_index = static_cast<long>(neg);
      r.reason = "rational LDL^T: after " + std::to_string(k) + " positive pivot(s) the pivot of row " +
                 std::to_string(neg) + " is negative (" + rational_to_text(Rational(at(neg, neg))) + ")";
      r.witness = make_witness({{neg, 1}});
      return r;
    }
    if (pos == n) {
      for (std::size_t a = 0; a < rem.size(); ++a)
        for (std::size_t b = a + 1; b < rem.size(); ++b)
          if (mpq_sgn(at(rem[a], rem[b])) != 0) {
            r.verdict = PsdVerdict::kNotPsd;
            r.pivot_index = static_cast<long>(rem[a]);
            r.reason = "rational LDL^T: after " + std::to_string(k) + " positive pivot(s) the pivot of row " +
                       std::to_string(rem[a]) + " is 0 but its row is not (entry with row " +
                       std::to_string(rem[b]) + ")";
            r.witness = make_witness({{rem[a], 1}, {rem[b], -mpq_sgn(at(rem[a], rem[b]))}});
            return r;
          }
      r.verdict = PsdVerdict::kPositiveSemidefinite;
      r.rank = static_cast<long>(k);
      r.pivot_index = static_cast<long>(rem.front());
      r.reason = "rational LDL^T: " + std::to_string(k) + " positive pivot(s), then the remaining Schur complement is zero";
      return r;
    }
    rem.erase(std::find(rem.begin(), rem.end(), pos));
    piv.push_back(pos);
    for (std::size_t a = 0; a < rem.size(); ++a) {
      const std::size_t i = rem[a];
      if (mpq_sgn(at(pos, i)) == 0) continue;
      mpq_div(l.q, at(pos, i), at(pos, pos));
      for (std::size_t b = a; b < rem.size(); ++b) {
        const std::size_t j = rem[b];
        if (mpq_sgn(at(pos, j)) == 0) continue;
        mpq_mul(prod.q, l.q, at(pos, j));
        mpq_sub(at(i, j), at(i, j), prod.q);
      }
    }
  }
}

PsdResult decide_psd(const Mat<Rational>& M, const PsdOptions& options) {
  require_symmetric(M);
  const Eigen::Index n = M.rows();
  if (options.use_filter && n > 0) {
    // Rows (and, by symmetry, columns) that are exactly zero do not change
    // PSD-ness: M is PSD iff M without them is. The filter sees the rest.
    std::vector<Eigen::Index> keep;
    Eigen::Index first_zero = -1;
    for (Eigen::Index i = 0; i < n; ++i) {
      bool zero = true;
      for (Eigen::Index j = 0; j < n && zero; ++j) zero = CGAL::is_zero(M(i, j));
      if (!zero)
        keep.push_back(i);
      else if (first_zero < 0)
        first_zero = i;
    }
    const auto m = static_cast<Eigen::Index>(keep.size());
    Mat<Rational> reduced;
    if (m < n) {
      reduced.resize(m, m);
      for (Eigen::Index a = 0; a < m; ++a)
        for (Eigen::Index b = 0; b < m; ++b) reduced(a, b) = M(keep[static_cast<std::size_t>(a)], keep[static_cast<std::size_t>(b)]);
    }
    const Mat<Rational>& R = m < n ? reduced : M;
    const std::string zero_note =
        m < n ? " (after removing " + std::to_string(n - m) + " zero row(s)/column(s), the first at row " +
                    std::to_string(first_zero) + ")"
              : std::string();

    PsdFilterResult f = run_psd_filter(R);
    if (f.proved_pd) {
      PsdResult r;
      r.verdict = m < n ? PsdVerdict::kPositiveSemidefinite : PsdVerdict::kPositiveDefinite;
      r.decided_by_filter = true;
      r.method = PsdMethod::kFloatingFilter;
      r.rank = m;
      r.pivot_index = m < n ? first_zero : -1;
      r.reason = f.reason + zero_note;
      return r;
    }
    if (f.negative_direction.size() == m && m > 0) {
      auto A = integer_matrix(M);
      // Try short integer roundings of the candidate first (readable
      // witnesses), then its exact binary value.
      std::vector<Mpz> w;
      bool found = false;
      const double vmax = f.negative_direction.cwiseAbs().maxCoeff();
      for (int bits : {3, 10, 24, 0}) {
        std::vector<Mpz> w_reduced =
            bits == 0 ? integer_vector_of_doubles(f.negative_direction)
                      : integer_vector_of_doubles(
                            (f.negative_direction * (std::ldexp(1.0, bits) / vmax)).array().round().matrix().eval());
        w = std::vector<Mpz>(static_cast<std::size_t>(n));
        for (std::size_t a = 0; a < keep.size(); ++a) mpz_swap(w[static_cast<std::size_t>(keep[a])].z, w_reduced[a].z);
        if (quadratic_form_sign(*A, w) < 0) {
          found = true;
          break;
        }
      }
      if (found) {
        PsdResult r;
        r.verdict = PsdVerdict::kNotPsd;
        r.decided_by_filter = true;
        r.method = PsdMethod::kWitnessCheck;
        r.pivot_index = keep[static_cast<std::size_t>(f.failed_row)];
        r.witness = reduced_witness(w);
        r.reason = f.candidate_reason + " at row " + std::to_string(r.pivot_index) +
                   "; its direction v satisfies v'Mv < 0, checked in exact integer arithmetic";
        return r;
      }
    }
  }
  return decide_psd_exact(M, options.threads);
}

Rational quadratic_form(const Mat<Rational>& M, const Vec<Rational>& v) {
  if (M.rows() != M.cols() || M.rows() != v.size())
    throw std::invalid_argument("quadratic_form: size mismatch");
  Rational q(0);
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    if (CGAL::is_zero(v(i))) continue;
    Rational row(0);
    for (Eigen::Index j = 0; j < M.cols(); ++j)
      if (!CGAL::is_zero(v(j))) row += M(i, j) * v(j);
    q += v(i) * row;
  }
  return q;
}

}  // namespace lpvid
