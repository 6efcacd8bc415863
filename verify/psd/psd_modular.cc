/// Multi-modular symmetric elimination: the fast exact path of
/// decide_psd_exact (verify/psd/exact_psd.h).
///
/// The same elimination as Bareiss, carried out modulo many 31-bit primes and
/// lifted by the Chinese remainder theorem. Every quantity that is lifted is a
/// minor of the integer matrix A (or a determinant of a submatrix of it), so
/// its absolute value is at most Hadamard's bound H = Π_i max(1, ‖A_i‖₂); the
/// primes are taken until their product P > 4H, so the symmetric residue mod
/// P is the exact integer. Nothing here is probabilistic:
///   1. The pivot order π is chosen modulo the first prime p₀: at step k the
///      remaining row with the smallest original index whose Schur diagonal is
///      ≠ 0 mod p₀ (hence ≠ 0 exactly). It stops at r when all remaining Schur
///      diagonals are ≡ 0 mod p₀.
///   2. For every prime: eliminate r steps of A_π (a prime where a pivot
///      vanishes is discarded). Record the pivots (→ the leading principal
///      minors Δ_k of A_π) and which entries of the remaining Schur block are
///      ≠ 0 mod p.
///   3. Lift Δ_1..Δ_r (all ≠ 0 exactly by step 1). The first Δ_k < 0 gives
///      NOT_PSD. Otherwise a Schur entry is exactly 0 iff it is 0 mod every
///      prime (its bordered minor is below P/2). All zero: PSD of rank r (PD if
///      r = n). Zero diagonal but a nonzero entry: NOT_PSD by a 2×2 minor.
///      A remaining diagonal that is ≠ 0 exactly but ≡ 0 mod p₀ (p₀ divides
///      it: "unlucky") is not decided here: the caller falls back to Bareiss.
///   4. Witnesses: the integer vector Δ_K·[−A₁₁⁻¹A₁ₜ; e_t] (entries are K×K
///      determinants by Cramer's rule) is computed mod every prime by
///      back-substitution and lifted, then checked exactly as always.
///   5. Resources: H needs ⌈log₂ 4H / 30⌉ primes; there are about 7.8·10⁵
///      in (2^31 − 2^24, 2^31) (2^24 / ln 2^31), and a caller may set a lower
///      limit. When they do not suffice (or in the unlucky case of 3.) the
///      outcome is "undecided" with the reason, and decide_psd_exact decides
///      with Bareiss instead: the exact decision never gives up.

#include <gmp.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "core/parallel_for.h"
#include "core/stop_request.h"
#include "verify/psd/psd_internal.h"
#include "verify/psd/psd_modular_arith.h"

namespace lpvid::psd_detail {
namespace {

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

/// The first K elimination steps on the m×m upper triangle `a` mod p, in
/// logical order (no pivoting): the pivots into piv[0..K) and their inverses
/// into inv[0..K). False when a pivot vanishes mod p (the prime is of no use).
bool eliminate_leading_mod(std::vector<Word>& a, std::size_t m, std::size_t K, Word p, std::vector<Word>& piv,
                           std::vector<Word>& inv) {
  piv.assign(K, 0);
  inv.assign(K, 0);
  for (std::size_t k = 0; k < K; ++k) {
    check_stop();  // a requested stop, between pivots
    if (a[k * m + k] == 0 || !inv_mod(a[k * m + k], p, &inv[k])) return false;
    piv[k] = a[k * m + k];
    modular_step(a.data(), m, k, inv[k], p);
  }
  return true;
}

/// 0, 1, …, count − 1.
std::vector<std::size_t> leading_rows(std::size_t count) {
  std::vector<std::size_t> rows(count);
  for (std::size_t i = 0; i < count; ++i) rows[i] = i;
  return rows;
}

/// Step 1: pivot order and rank modulo p₀ (see the section comment).
void choose_pivots_mod(const IntegerMatrix& A, Word p, std::vector<long>* perm, std::size_t* rank) {
  const std::size_t n = A.n;
  perm->resize(n);
  for (std::size_t i = 0; i < n; ++i) (*perm)[i] = static_cast<long>(i);
  LogicalInts ints(A, *perm);
  std::vector<Word> a;
  ints.fill(leading_rows(n), p, a);
  auto at = [&](std::size_t i, std::size_t j) -> Word& { return a[i * n + j]; };
  for (std::size_t k = 0; k < n; ++k) {
    check_stop();
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

}  // namespace

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

namespace {

/// Step 4 for one target t mod p, on the m×m triangle `a` after K
/// elimination steps (pivot inverses `inv`, Δ_K = `delta`): w[K + t] = Δ_K,
/// w[0..K) = Δ_K·(−A₁₁⁻¹A₁ₜ) by back-substitution, the other entries 0.
void back_substitute_mod(const std::vector<Word>& a, std::size_t m, std::size_t K, std::size_t t,
                         const std::vector<Word>& inv, Word delta, Word p, std::vector<Word>& w) {
  std::fill(w.begin(), w.end(), 0);
  w[K + t] = delta;
  for (std::size_t mm = K; mm-- > 0;) {
    u128 s = 0;  // < m·2^62: cannot overflow
    for (std::size_t j = mm + 1; j < m; ++j) s += static_cast<std::uint64_t>(a[mm * m + j]) * w[j];
    const Word sp = static_cast<Word>(s % p);
    w[mm] = mul_mod(sp == 0 ? 0 : p - sp, inv[mm], p);
  }
}

/// The outcome of step 2 over all primes: the good primes (no pivot vanishes
/// mod them), their pivots, and which entries of the remaining Schur block
/// are ≠ 0 mod some good prime.
struct PrimeEliminations {
  std::vector<Word> primes;
  std::vector<std::vector<Word>> pivots;  // per good prime
  std::vector<char> nonzero;              // rest×rest, row-major
};

class ModularElimination {
 public:
  ModularElimination(const Mat<Rational>& M, int threads, std::size_t max_primes)
      : M_(M), A_(integer_matrix(M)), threads_(threads), max_primes_(max_primes) {}

  /// Steps 1–3 of the section comment (step 4 when a witness is due).
  ModularOutcome run() {
    const std::size_t need_bits = hadamard_bits(*A_) + 3;  // P > 2H with margin
    const std::size_t count = need_bits / kPrimeBits + 1;
    if (!take_primes(count, need_bits, &primes_)) return undecided();
    choose_pivots_mod(*A_, primes_[0], &perm_, &rank_);
    ints_ = std::make_unique<LogicalInts>(*A_, perm_);
    PrimeEliminations runs;
    if (!eliminate_mod_primes(need_bits, count, &runs)) return undecided();
    primes_ = runs.primes;
    Crt crt(primes_);
    if (!crt.ok()) {
      why_ = "the CRT moduli are not coprime";  // never for distinct primes
      return undecided();
    }
    const std::size_t k = first_negative_minor(crt, runs.pivots);
    if (k < rank_) return negative_pivot(k);
    return decide_schur_block(runs.nonzero);
  }

 private:
  ModularOutcome undecided() const {
    ModularOutcome out;
    out.why = why_;
    return out;
  }

  /// The worker count of the parallel loops over primes (core/parallel_for.h).
  unsigned workers() const { return static_cast<unsigned>(std::max(threads_, 1)); }

  /// The first `count` primes into *out; false (with why_) when they exceed
  /// max_primes_ or the primes in (2^31 − 2^24, 2^31): a Hadamard bound of
  /// `need_bits` bits can then not be certified by this path.
  bool take_primes(std::size_t count, std::size_t need_bits, std::vector<Word>* out) {
    if (count <= max_primes_) {
      *out = modular_primes(count);
      if (out->size() == count) return true;
    }
    const std::size_t have = count <= max_primes_ ? out->size() : max_primes_;
    why_ = "out of 31-bit primes: Hadamard's bound of 2^" + std::to_string(need_bits) + " needs " +
           std::to_string(count) + " primes, " + (count <= max_primes_ ? "only " : "the limit is ") +
           std::to_string(have) + (count <= max_primes_ ? " lie in (2^31 - 2^24, 2^31)" : "");
    return false;
  }

  /// For every prime of `primes`, in parallel with one residue matrix per
  /// worker (core/parallel_for.h): the upper triangle of the logical `rows`
  /// mod p after K elimination steps, with its pivots and their inverses, to
  /// use(index of the prime, triangle, pivots, inverses). A prime where one of
  /// the K pivots vanishes is skipped (use is not called).
  template <typename Use>
  void eliminate_mod_each(const std::vector<Word>& primes, const std::vector<std::size_t>& rows, std::size_t K,
                          Use&& use) const {
    parallel_for_with_scratch<std::vector<Word>>(primes.size(), workers(), [&](std::size_t b, std::vector<Word>& a) {
      const Word p = primes[b];
      ints_->fill(rows, p, a);
      std::vector<Word> piv, inv;
      if (eliminate_leading_mod(a, rows.size(), K, p, piv, inv)) use(b, a, piv, inv);
    });
  }

  /// Step 2 over all primes (more primes if some were discarded, in batches
  /// of the primes still missing) until the good ones carry `need_bits`
  /// bits. False (with why_) when the primes run out.
  bool eliminate_mod_primes(std::size_t need_bits, std::size_t count, PrimeEliminations* runs) {
    const std::size_t rest = A_->n - rank_;
    runs->nonzero.assign(rest * rest, 0);
    std::size_t first_unused = 0;
    while (runs->primes.size() * kPrimeBits < need_bits) {
      const std::size_t missing = (need_bits - runs->primes.size() * kPrimeBits + kPrimeBits - 1) / kPrimeBits;
      if (first_unused + missing > count + 64) {
        why_ = "more than 64 primes divide a pivot";  // absurd: let Bareiss decide
        return false;
      }
      std::vector<Word> batch;
      if (!take_primes(first_unused + missing, need_bits, &batch)) return false;
      batch.erase(batch.begin(), batch.begin() + static_cast<std::ptrdiff_t>(first_unused));
      first_unused += missing;
      eliminate_batch(batch, runs);
    }
    return true;
  }

  /// Step 2 for one batch of primes, in parallel with one residue matrix per
  /// worker: eliminate rank_ steps of A_π mod p (a prime where a pivot
  /// vanishes is discarded), record the pivots and the Schur block entries
  /// ≠ 0 mod p. The good primes are appended in the batch's order.
  void eliminate_batch(const std::vector<Word>& batch, PrimeEliminations* runs) {
    const std::size_t n = A_->n, r = rank_, rest = n - r;
    std::vector<std::vector<Word>> batch_pivots(batch.size());
    std::vector<char> batch_ok(batch.size(), 0);  // stays 0 for a discarded prime
    std::mutex merge;
    eliminate_mod_each(batch, leading_rows(n), r, [&](std::size_t b, const std::vector<Word>& a, std::vector<Word>& piv,
                                                      const std::vector<Word>&) {
      std::vector<char> local(rest * rest, 0);
      bool any = false;
      for (std::size_t i = r; i < n; ++i)
        for (std::size_t j = i; j < n; ++j)
          if (a[i * n + j] != 0) local[(i - r) * rest + (j - r)] = any = true;
      if (any) {
        std::lock_guard<std::mutex> lock(merge);
        for (std::size_t x = 0; x < local.size(); ++x) runs->nonzero[x] |= local[x];
      }
      batch_pivots[b] = std::move(piv);
      batch_ok[b] = 1;
    });
    for (std::size_t b = 0; b < batch.size(); ++b)
      if (batch_ok[b]) {
        runs->primes.push_back(batch[b]);
        runs->pivots.push_back(std::move(batch_pivots[b]));
      }
  }

  /// Step 3, the pivots: the first k < rank_ whose leading principal minor
  /// Δ_{k+1} = Π_{t≤k} pivot_t, lifted, is negative; rank_ when none is.
  std::size_t first_negative_minor(const Crt& crt, const std::vector<std::vector<Word>>& pivots) const {
    std::vector<Word> delta(primes_.size(), 1);
    Mpz value;
    for (std::size_t k = 0; k < rank_; ++k) {
      for (std::size_t i = 0; i < primes_.size(); ++i) delta[i] = mul_mod(delta[i], pivots[i][k], primes_[i]);
      crt.lift([&](std::size_t i) { return delta[i]; }, value.z);
      if (mpz_sgn(value.z) < 0) return k;
    }
    return rank_;
  }

  /// NOT_PSD at step k: S_kk = Δ_{k+1}/Δ_k < 0 after k positive pivots.
  ModularOutcome negative_pivot(std::size_t k) {
    PsdResult res;
    res.method = PsdMethod::kExactLdlt;
    res.verdict = PsdVerdict::kNotPsd;
    res.step = static_cast<long>(k);
    res.pivot_index = perm_[k];
    res.reason = "exact LDL^T: after " + std::to_string(k) + " positive pivot(s) the pivot of row " +
                 std::to_string(perm_[k]) + " is negative";
    if (!witness(k, {k}, &res)) return undecided();
    return {true, res, {}};
  }

  /// Step 3, the remaining Schur block after rank_ positive pivots: an entry
  /// is exactly 0 iff it is 0 mod every prime (`nonzero` says which are not).
  ModularOutcome decide_schur_block(const std::vector<char>& nonzero) {
    const std::size_t rest = A_->n - rank_;
    bool any = false, any_diag = false;
    for (std::size_t i = 0; i < rest; ++i) {
      any_diag = any_diag || nonzero[i * rest + i];
      for (std::size_t j = i; j < rest; ++j) any = any || nonzero[i * rest + j];
    }
    if (!any) return {true, zero_schur_block(), {}};
    if (any_diag) {
      why_ = "the first prime divides a nonzero Schur diagonal";  // let Bareiss decide
      return undecided();
    }
    return indefinite_pair(nonzero);
  }

  /// The Schur block is exactly zero: PD when rank_ = n, else PSD of rank rank_.
  PsdResult zero_schur_block() const {
    const std::size_t n = A_->n, r = rank_;
    const std::string how = " (multi-modular: " + std::to_string(primes_.size()) + " primes of 31 bits, CRT)";
    PsdResult res;
    res.method = PsdMethod::kExactLdlt;
    res.step = static_cast<long>(r);
    res.rank = static_cast<long>(r);
    if (r == n) {
      res.verdict = PsdVerdict::kPositiveDefinite;
      res.reason = "exact LDL^T: all " + std::to_string(n) + " pivots are positive" + how;
      return res;
    }
    res.verdict = PsdVerdict::kPositiveSemidefinite;
    long first = perm_[r];
    for (std::size_t i = r; i < n; ++i) first = std::min(first, perm_[i]);
    res.pivot_index = first;
    res.reason = "exact LDL^T: " + std::to_string(r) + " positive pivot(s), then the remaining " +
                 std::to_string(n - r) + "x" + std::to_string(n - r) + " Schur complement is exactly zero (rank " +
                 std::to_string(r) + " < n = " + std::to_string(n) + ")" + how;
    return res;
  }

  /// Zero Schur diagonal but a nonzero entry: NOT_PSD by the 2×2 minor of the
  /// nonzero entry with the smallest (original row, original column).
  ModularOutcome indefinite_pair(const std::vector<char>& nonzero) {
    const std::size_t r = rank_, rest = A_->n - r;
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
    PsdResult res;
    res.method = PsdMethod::kExactLdlt;
    res.step = static_cast<long>(r);
    res.verdict = PsdVerdict::kNotPsd;
    res.pivot_index = perm_[li];
    res.reason = "exact LDL^T: after " + std::to_string(r) + " positive pivot(s) the pivot of row " +
                 std::to_string(perm_[li]) + " is 0 but its row is not (entry with row " + std::to_string(perm_[lj]) +
                 "): the 2x2 principal minor [[0,b],[b,0]] with b != 0 is indefinite";
    if (!witness(r, {std::min(li, lj), std::max(li, lj)}, &res, li)) return undecided();
    return {true, res, {}};
  }

  /// Step 4. K leading pivots; targets t (logical ≥ K, increasing). For one
  /// target: w = Δ_K·[−A₁₁⁻¹A₁ₜ; 1]. For two targets i = `first` and j:
  /// w = w(i) − sign(S_ij)·w(j). Fills res->witness (checked exactly).
  bool witness(std::size_t K, const std::vector<std::size_t>& targets, PsdResult* res, std::size_t first = 0) {
    std::vector<std::vector<Word>> wres;
    if (!witness_residues(K, targets, &wres)) return false;
    Crt crt(primes_);
    std::vector<long> coef(targets.size(), 1);
    if (targets.size() == 2) {
      // x = e_first − sign(S_ij)·e_other
      const long s = lifted_sign(crt, wres, 2 * (K + 1));
      if (s == 0) {
        why_ = "the off-diagonal Schur entry of the witness lifted to 0";
        return false;
      }
      coef[targets[0] == first ? 1 : 0] = -s;
    }
    std::vector<Mpz> w = lifted_witness(crt, K, targets, wres, coef);
    check_witness(M_, w);
    res->witness = reduced_witness(w);
    return true;
  }

  /// Step 4 mod every prime, in parallel with one residue matrix per worker:
  /// (*wres)[prime][target·(K+1) + x] holds w entries x < K of that target's
  /// vector and Δ_K at x = K; for two targets, S_ij·Δ_K follows at the end.
  /// False (with why_) when a prime divides a pivot of the witness.
  bool witness_residues(std::size_t K, const std::vector<std::size_t>& targets,
                        std::vector<std::vector<Word>>* wres) {
    std::vector<std::size_t> rows = leading_rows(K);
    rows.insert(rows.end(), targets.begin(), targets.end());
    const std::size_t m = rows.size(), T = targets.size();
    wres->assign(primes_.size(), std::vector<Word>(T * (K + 1) + 1, 0));
    std::vector<char> ok(primes_.size(), 0);
    eliminate_mod_each(primes_, rows, K, [&](std::size_t pi, const std::vector<Word>& a, std::vector<Word>& piv,
                                             const std::vector<Word>& inv) {
      const Word p = primes_[pi];
      Word delta = 1;
      for (const Word d : piv) delta = mul_mod(delta, d, p);
      std::vector<Word> w(m);
      std::vector<Word>& out = (*wres)[pi];
      for (std::size_t t = 0; t < T; ++t) {
        back_substitute_mod(a, m, K, t, inv, delta, p, w);
        std::copy_n(w.begin(), K, out.begin() + static_cast<std::ptrdiff_t>(t * (K + 1)));
        out[t * (K + 1) + K] = delta;
      }
      if (T == 2) out[T * (K + 1)] = mul_mod(a[K * m + K + 1], delta, p);
      ok[pi] = 1;
    });
    for (char c : ok)
      if (!c) {
        why_ = "a prime divides a pivot of the witness";
        return false;
      }
    return true;
  }

  /// Sign of the integer whose residues stand at `index` of each prime's row.
  static long lifted_sign(const Crt& crt, const std::vector<std::vector<Word>>& wres, std::size_t index) {
    Mpz val;
    crt.lift([&](std::size_t i) { return wres[i][index]; }, val.z);
    return mpz_sgn(val.z);
  }

  /// The integer witness Σ_t coef_t · w(t), lifted on logical rows and
  /// mapped back to the original order.
  std::vector<Mpz> lifted_witness(const Crt& crt, std::size_t K, const std::vector<std::size_t>& targets,
                                  const std::vector<std::vector<Word>>& wres, const std::vector<long>& coef) const {
    std::vector<Mpz> w_logical(A_->n);
    Mpz val;
    for (std::size_t t = 0; t < targets.size(); ++t) {
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
    return w;
  }

  const Mat<Rational>& M_;
  std::unique_ptr<IntegerMatrix> A_;
  int threads_;
  std::size_t max_primes_;
  std::string why_;  // why the path is undecided
  std::vector<Word> primes_;
  std::vector<long> perm_;
  std::size_t rank_ = 0;
  std::unique_ptr<LogicalInts> ints_;
};

}  // namespace

ModularOutcome decide_psd_modular(const Mat<Rational>& M, int threads, std::size_t max_primes) {
  ModularElimination modular(M, threads, max_primes);
  return modular.run();
}

}  // namespace lpvid::psd_detail
