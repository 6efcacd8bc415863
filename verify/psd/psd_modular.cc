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

class ModularElimination {
 public:
  ModularElimination(const Mat<Rational>& M, int threads, std::size_t max_primes)
      : M_(M), A_(integer_matrix(M)), threads_(threads), max_primes_(max_primes) {}

  ModularOutcome run() {
    const std::size_t n = A_->n;
    const std::size_t need_bits = hadamard_bits(*A_) + 3;  // P > 2H with margin
    std::size_t count = need_bits / kPrimeBits + 1;
    if (!take_primes(count, need_bits, &primes_)) return undecided();
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
      if (first_unused + missing > count + 64) {
        why_ = "more than 64 primes divide a pivot";  // absurd: let Bareiss decide
        return undecided();
      }
      std::vector<Word> batch;
      if (!take_primes(first_unused + missing, need_bits, &batch)) return undecided();
      batch.erase(batch.begin(), batch.begin() + static_cast<std::ptrdiff_t>(first_unused));
      first_unused += missing;
      std::vector<std::vector<Word>> batch_pivots(batch.size());
      std::vector<char> batch_ok(batch.size(), 0);
      std::vector<std::size_t> all(n);
      for (std::size_t i = 0; i < n; ++i) all[i] = i;
      parallel_for_with_scratch<std::vector<Word>>(batch.size(), workers(), [&](std::size_t b, std::vector<Word>& a) {
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
    if (!crt.ok()) {
      why_ = "the CRT moduli are not coprime";  // never for distinct primes
      return undecided();
    }

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
        if (!witness(k, {k}, &res)) return undecided();
        return {true, res, {}};
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
      return {true, res, {}};
    }
    if (any_diag) {
      why_ = "the first prime divides a nonzero Schur diagonal";  // let Bareiss decide
      return undecided();
    }
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
    if (!witness(r, {std::min(li, lj), std::max(li, lj)}, &res, li)) return undecided();
    return {true, res, {}};
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
    parallel_for_with_scratch<std::vector<Word>>(primes_.size(), workers(), [&](std::size_t pi, std::vector<Word>& a) {
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
      if (!c) {
        why_ = "a prime divides a pivot of the witness";
        return false;
      }
    Crt crt(primes_);
    // Integer witness on logical rows: Σ_t coef_t · w(t).
    std::vector<Mpz> w_logical(A_->n);
    Mpz val;
    std::vector<long> coef(T, 1);
    if (T == 2) {
      crt.lift([&](std::size_t i) { return wres[i][T * (K + 1)]; }, val.z);
      const long s = mpz_sgn(val.z);
      if (s == 0) {
        why_ = "the off-diagonal Schur entry of the witness lifted to 0";
        return false;
      }
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
