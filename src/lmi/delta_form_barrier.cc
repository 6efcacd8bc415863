#include "lmi/delta_form_barrier.h"

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

#include "core/deadline.h"
#include "core/helper_thread.h"
#include "core/integer_power.h"
#include "core/parallel_for.h"
#include "core/rms.h"
#include "lmi/free_regressors.h"
#include "dense/llt_inverse.h"
#include "lmi/newton_factor.h"
#include "lmi/noise_block.h"
#include "dense/split_factorisations.h"
#include "dense/split_llt.h"
#include "toeplitz/correlation_2d.h"
#include "toeplitz/fir.h"
#include "toeplitz/signal_toeplitz.h"
#include "toeplitz/tap_toeplitz.h"

namespace lpvid {

bool barrier_applies(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective) {
  return z.cols() >= 1 && r.cols() >= 1 && !(objective.kind == BoundObjective::Kind::kMinDelta && !(objective.dmax.approx > 0)) &&
         !(objective.kind == BoundObjective::Kind::kWeighted && !(objective.lambda > 0 && objective.lambda < 1)) &&
         !(objective.delta_fixed() && !(objective.delta.approx > 0));
}

namespace {

using Index = Eigen::Index;
using Vecd = Eigen::VectorXd;
using Dense = Eigen::MatrixXd;
using Strided = Eigen::Map<const Dense, 0, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>>;

/// L × L lower-triangular Toeplitz matrix with first column c.
Dense lower_toeplitz(const Vecd& c) {
  const Index L = c.size();
  Dense T = Dense::Zero(L, L);
  for (Index j = 0; j < L; ++j) T.col(j).tail(L - j) = c.head(L - j);
  return T;
}

/// Ω_l(M) = Σ_{a−b=l} M(a, b), l = 0 … L−1 (subdiagonal sums).
template <typename X>
Vecd subdiagonal_sums(const Eigen::MatrixBase<X>& M) {
  const Index L = M.rows();
  Vecd out = Vecd::Zero(L);
  for (Index b = 0; b < L; ++b)
    for (Index a = b; a < L; ++a) out(a - b) += M(a, b);
  return out;
}

/// The L × L scalar sub-block (i, j) of a matrix of p × q blocks laid out
/// as rows a·p + i, columns b·q + j (the layout of T_Δ, P, Q, R):
/// sub(a, b) = M(a·p + i, b·q + j).
Strided sub_block(const Dense& M, Index p, Index q, Index i, Index j) {
  const Index L = M.rows() / p;
  return Strided(M.data() + i + j * M.rows(), L, M.cols() / q, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>(q * M.rows(), p));
}

/// The scaled problem. Variables x = (h, t) (t only when δ is free): entry
/// (i, j) of tap l at x((i·nz + j)·L + l), i.e. the taps matrix (L × ny·nz,
/// column i·nz + j) stored column by column. s is eliminated (see the
/// header) unless it is fixed (min δ at d_max). With free regressors G the
/// residual is P⊥r and every d is projected (P⊥(r − Zh) = P⊥r − P⊥Zh).
struct Problem : SignalScaling {  ///< n, ny, nz, the scales σ_z, σ_r; L = records_horizon, m = head rows
  double N = 0;
  /// The stacked rows (of r, z) before each record's first nonzero z (head:
  /// no Δ acts there) and from it (tail), each in stack order; m = #head.
  /// One record: rows < m and rows ≥ m.
  std::vector<Index> head_rows, tail_rows;
  RecordLengths records;    ///< n_1 … n_K (one record: {n})
  Dense r_head, r_tail;     ///< scaled residual on the head and tail rows (ny columns)
  FreeRegressors regressors;  ///< G of the header (empty: none)
  Dense W;                  ///< Zᵀ Q (taps × rank of G, the taps' order): the noise Hessian's correction
  /// Per input j of Δ: the tail rows × L matrix of the scaled z_j, record k's
  /// rows its (n_k − m_k)-square lower-triangular Toeplitz block, zero columns
  /// after (one record: L × L lower-triangular Toeplitz).
  std::vector<Dense> Z;
  std::vector<Dense> G;     ///< G[j·nz + j'] = Z_jᵀ Z_j'
  bool t_var = false;
  bool s_var = true;      ///< false: s = s_fix and (C2) keeps its own barrier −log(N s − ‖d‖²)
  double t_fix = 0, s_fix = 0;
  double ct = 0, cs = 0;  ///< objective weights of t, s
  double nu = 0;          ///< L·(ny + nz) + N + 1

  Index q() const { return ny * nz; }
  Index taps() const { return L * q(); }
  Index dim() const { return taps() + (t_var ? 1 : 0); }
  double t_of(const Vecd& x) const { return t_var ? x(taps()) : t_fix; }
  /// The taps of entry (i, j) over l.
  Eigen::Map<const Vecd> tap_sequence(const Vecd& x, Index i, Index j) const {
    return Eigen::Map<const Vecd>(x.data() + (i * nz + j) * L, L);
  }
};

/// T_Δ (L·ny × L·nz; rows a·ny + i, columns b·nz + j) of the taps in x.
Dense block_toeplitz(const Problem& p, const Vecd& x) {
  return tap_toeplitz_dense<double>(Eigen::Map<const Dense>(x.data(), p.L, p.q()), p.ny, p.nz);
}

/// d on the tail rows: r_i − Σ_j Z_j h_ij.
Dense residual_tail(const Problem& p, const Vecd& x) {
  Dense d = p.r_tail;
  for (Index i = 0; i < p.ny; ++i)
    for (Index j = 0; j < p.nz; ++j) d.col(i) -= p.Z[static_cast<size_t>(j)] * p.tap_sequence(x, i, j);
  return d;
}

/// The residual stacked like r in (C2) (row k·ny + i) from its head and tail rows.
Vecd stacked_residual(const Problem& p, const Dense& head, const Dense& tail) {
  Vecd v(p.n * p.ny);
  for (size_t a = 0; a < p.head_rows.size(); ++a) v.segment(p.head_rows[a] * p.ny, p.ny) = head.row(static_cast<Index>(a));
  for (size_t a = 0; a < p.tail_rows.size(); ++a) v.segment(p.tail_rows[a] * p.ny, p.ny) = tail.row(static_cast<Index>(a));
  return v;
}

/// The inverse of stacked_residual.
void split_residual(const Problem& p, const Vecd& v, Dense& head, Dense& tail) {
  head.resize(static_cast<Index>(p.head_rows.size()), p.ny);
  tail.resize(static_cast<Index>(p.tail_rows.size()), p.ny);
  for (size_t a = 0; a < p.head_rows.size(); ++a) head.row(static_cast<Index>(a)) = v.segment(p.head_rows[a] * p.ny, p.ny);
  for (size_t a = 0; a < p.tail_rows.size(); ++a) tail.row(static_cast<Index>(a)) = v.segment(p.tail_rows[a] * p.ny, p.ny);
}

/// (head, tail) ← P⊥(head, tail): the free regressors' part removed.
void project_residual(const Problem& p, Dense& head, Dense& tail) {
  Vecd v = stacked_residual(p, head, tail);
  p.regressors.project(v);
  split_residual(p, v, head, tail);
}

/// F_μ at x, or +∞ outside the interior, with what the derivatives reuse.
struct Point {
  bool interior = false;
  double value = std::numeric_limits<double>::infinity();
  Dense taps;  ///< L × (ny·nz), column i·nz + j = h_ij
  /// Computed on an empty matrix until evaluate() factors F1: a default-
  /// constructed LLT leaves its status uninitialised, and moving a Point
  /// that returned early (t <= 0) read it (UBSan: invalid ComputationInfo).
  SplitLlt llt{Dense(0, 0)};
  Dense d_head, d_tail;  ///< d on the head rows (r's own, projected with free regressors) and the tail rows
  double D = 0;    ///< ‖d‖² (all rows)
  double phi = 0;  ///< N·s_fix − ‖d‖² (s fixed only)
};

/// pt ← F_μ at x (pt's and F1's storage reused: no allocation per trial
/// point); `helper` (may be null) takes a share of the Cholesky factorisation.
void evaluate(const Problem& p, const Vecd& x, double mu, Point& pt, Dense& F1, HelperThread* helper) {
  pt.interior = false;
  pt.value = std::numeric_limits<double>::infinity();
  pt.phi = 0;
  const double t = p.t_of(x);
  pt.d_tail = residual_tail(p, x);
  pt.d_head = p.r_head;
  if (!p.regressors.empty()) project_residual(p, pt.d_head, pt.d_tail);
  pt.D = pt.d_head.squaredNorm() + pt.d_tail.squaredNorm();
  if (!(t > 0) || !std::isfinite(pt.D)) return;
  pt.phi = p.N * p.s_fix - pt.D;
  if (!p.s_var && !(pt.phi > 0)) return;
  pt.taps = Eigen::Map<const Dense>(x.data(), p.L, p.q());
  tap_gram_into(pt.taps, p.ny, p.nz, F1);  // T Tᵀ in O(L²)
  F1 = -F1;
  F1.diagonal().array() += t;
  pt.llt.compute_split(F1, helper);
  if (pt.llt.info() != Eigen::Success) return;
  const Vecd diag = pt.llt.matrixLLT().diagonal();
  if (!(diag.minCoeff() > 0)) return;
  const double noise = p.s_var ? p.cs * pt.D / (p.N * mu) : -std::log(pt.phi);
  pt.value = (p.t_var ? p.ct * t / mu : 0.0) + noise - 2.0 * diag.array().log().sum();
  pt.interior = std::isfinite(pt.value);
}

/// out(k, l) += Σ_c M(c + k, c + l) for k, l ∈ [0, L) (sums along the
/// diagonals, each accumulated from its far end: no L × L buffer).
template <typename X>
void add_diagonal_sums(const Eigen::MatrixBase<X>& M, Dense& out) {
  const Index L = M.rows();
  for (Index d = -(L - 1); d < L; ++d) {  // the diagonal l − k = d
    Index k = std::min(L - 1, L - 1 - d), l = k + d;
    double sum = 0.0;
    for (; k >= 0 && l >= 0; --k, --l) {
      sum = M(k, l) + sum;
      out(k, l) += sum;
    }
  }
}

/// M ← M + Mᵀ in place (entries (i, j) and (j, i) both get M(i, j) + M(j, i)),
/// in tiles of 64 × 64 so that the transposed reads stay in cache.
void add_transpose_in_place(Dense& M) {
  constexpr Index kTile = 64;
  const Index n = M.rows();
  for (Index j0 = 0; j0 < n; j0 += kTile)
    for (Index i0 = j0; i0 < n; i0 += kTile)
      for (Index j = j0; j < std::min(n, j0 + kTile); ++j)
        for (Index i = std::max(i0, j); i < std::min(n, i0 + kTile); ++i) M(i, j) = M(j, i) = M(i, j) + M(j, i);
}

/// What the derivatives of a Newton step reuse from step to step, allocated
/// once per solve: the FFT grid, its plans and buffers, the spectra and the
/// Toeplitz product of the current taps (no temporaries per Newton step:
/// fresh memory for them cost ~20 % of a SISO n = 1600 solve in page faults).
struct DerivativeWorkspace {
  explicit DerivativeWorkspace(const Problem& p)
      : grid(p.L), fft(grid), times_T(Dense::Zero(p.L, p.q()), p.ny, p.nz), P_hat(static_cast<size_t>(p.ny * p.ny)),
        R_hat(static_cast<size_t>(p.nz * p.nz)), Q_hat(static_cast<size_t>(p.q())), Qt_hat(static_cast<size_t>(p.q())),
        many_pairs(p.q() > 1) {}
  const CorrelationGrid grid;
  CorrelationWorkspace fft;
  ToeplitzProduct times_T;
  std::vector<Spectrum> P_hat, R_hat, Q_hat, Qt_hat;
  Dense Hh;  ///< a pair block of the Hessian, then P·Q
  HelperThread* helper = nullptr;  ///< takes half of the work when set (the same numbers)
  /// MIMO with a helper: its own buffers, for whole transforms and pair
  /// blocks (the grids are small: a transform split in two costs more
  /// hand-overs than it saves). SISO: one large grid, each transform split.
  std::unique_ptr<CorrelationWorkspace> fft2;
  Dense Hh2;
  bool many_pairs = false;
  void set_helper(HelperThread* h) {
    helper = h;
    fft.set_helper(many_pairs ? nullptr : h);
    if (many_pairs && h != nullptr && !fft2) fft2 = std::make_unique<CorrelationWorkspace>(grid);
  }
  /// Whether share() runs jobs on two threads.
  bool shares() const { return many_pairs && helper != nullptr; }
  /// job(k, buffers…) for k < count: alternately here and on the helper when
  /// shares(), else in order here.
  void share(size_t count, const std::function<void(size_t, CorrelationWorkspace&, Dense&)>& job) {
    if (!shares()) {
      for (size_t k = 0; k < count; ++k) job(k, fft, Hh);
      return;
    }
    fork_join(
        helper, [&] { for (size_t k = 1; k < count; k += 2) job(k, *fft2, Hh2); },
        [&] { for (size_t k = 0; k < count; k += 2) job(k, fft, Hh); });
  }
  /// Frees the spectra, the grid and the pair block (the dual matrices are
  /// built after the last derivatives: they need not share the memory peak).
  void release() {
    fft.release();
    if (fft2) fft2->release();
    Hh2 = Dense();
    for (auto* spectra : {&P_hat, &R_hat, &Q_hat, &Qt_hat})
      for (Spectrum& s : *spectra) s.data.reset();
    Hh = Dense();
  }
};

/// The noise's part of the gradient and Hessian: ∂‖d‖²/∂h_ij = −2 Z_jᵀ d_i,
/// ∂²‖d‖²/∂h_ij ∂h_ij' = 2 Z_jᵀ Z_j' (with free regressors d is projected and
/// the Hessian loses 2 W Wᵀ, W = ZᵀQ), weighted by c_s/(N μ) when s is
/// eliminated, or through −log φ with φ = N s − ‖d‖² when s is fixed.
void add_noise_terms(const Problem& p, const Point& pt, double mu, Vecd& g, Dense& H) {
  const Index L = p.L, ny = p.ny, nz = p.nz, nt = p.taps();
  const auto at = [&](Index i, Index j) { return (i * nz + j) * L; };
  Vecd Zd = Vecd::Zero(nt);
  for (Index i = 0; i < ny; ++i)
    for (Index j = 0; j < nz; ++j) Zd.segment(at(i, j), L) = p.Z[static_cast<size_t>(j)].transpose() * pt.d_tail.col(i);
  const double w = p.s_var ? p.cs / (p.N * mu) : 1.0 / pt.phi;  // c_s·‖d‖²/(N μ), or −log φ with φ = N s − ‖d‖²
  g.head(nt) -= 2.0 * w * Zd;
  for (Index i = 0; i < ny; ++i)
    for (Index j = 0; j < nz; ++j)
      for (Index j2 = 0; j2 < nz; ++j2) H.block(at(i, j), at(i, j2), L, L) += 2.0 * w * p.G[static_cast<size_t>(j * nz + j2)];
  if (!p.regressors.empty()) H.topLeftCorner(nt, nt) -= (2.0 * w) * (p.W * p.W.transpose());
  if (!p.s_var) H.topLeftCorner(nt, nt) += 4.0 * Zd * Zd.transpose() / (pt.phi * pt.phi);
}

/// The spectra the log-det Hessian correlates (sub-blocks of P, R, Q, Qᵀ);
/// g's taps part, 2 Ω_l(Q_ij).
void logdet_spectra(const Problem& p, const Dense& P, const Dense& Q, const Dense& R, DerivativeWorkspace& ws, Vecd& g) {
  const Index L = p.L, ny = p.ny, nz = p.nz;
  if (p.q() == 1) {  // one pair: corr(Q, Qᵀ) formed in Q̂'s array, Q̂ᵀ's array then takes P̂ (three spectra, not four)
    g.head(L) = 2.0 * subdiagonal_sums(Q);
    ws.fft.spectrum(Q, ws.Q_hat[0]);
    ws.fft.spectrum(Q.transpose(), ws.Qt_hat[0]);
    ws.fft.reflect_product(ws.Q_hat[0], ws.Qt_hat[0]);
    ws.fft.spectrum(P, ws.Qt_hat[0]);
    ws.fft.spectrum(R, ws.R_hat[0]);
    return;
  }
  std::vector<std::function<void(CorrelationWorkspace&)>> jobs;  // each spectrum whole on one thread
  for (Index i = 0; i < ny; ++i)
    for (Index i2 = 0; i2 < ny; ++i2)
      jobs.push_back([&, i, i2](CorrelationWorkspace& fft) {
        fft.spectrum(sub_block(P, ny, ny, i, i2), ws.P_hat[static_cast<size_t>(i * ny + i2)]);
      });
  for (Index j = 0; j < nz; ++j)
    for (Index j2 = 0; j2 < nz; ++j2)
      jobs.push_back([&, j, j2](CorrelationWorkspace& fft) {
        fft.spectrum(sub_block(R, nz, nz, j, j2), ws.R_hat[static_cast<size_t>(j * nz + j2)]);
      });
  for (Index i = 0; i < ny; ++i)
    for (Index j = 0; j < nz; ++j)
      jobs.push_back([&, i, j](CorrelationWorkspace& fft) {
        const Strided Qij = sub_block(Q, ny, nz, i, j);
        g.segment((i * nz + j) * L, L) = 2.0 * subdiagonal_sums(Qij);
        fft.spectrum(Qij, ws.Q_hat[static_cast<size_t>(i * nz + j)]);
        fft.spectrum(Qij.transpose(), ws.Qt_hat[static_cast<size_t>(i * nz + j)]);
      });
  ws.share(jobs.size(), [&](size_t k, CorrelationWorkspace& fft, Dense&) { jobs[k](fft); });
}

/// The Hessian of −log det(tI − TTᵀ) in the taps from the spectra of
/// logdet_spectra. The pair block (b, a) is the transpose of (a, b): each
/// unordered pair is correlated once (the FFTs are the MIMO Newton step's main cost).
void logdet_hessian(const Problem& p, const Dense& P, DerivativeWorkspace& ws, Dense& H) {
  const Index L = p.L, ny = p.ny, nz = p.nz;
  const auto at = [&](Index i, Index j) { return (i * nz + j) * L; };
  // one thread: the last use of P_ii''s spectrum takes the product in its array (one buffer less)
  std::vector<int> uses(static_cast<size_t>(ny * ny), 0);
  std::vector<std::pair<Index, Index>> pairs;
  for (Index a = 0; a < ny * nz; ++a)
    for (Index b = a; b < ny * nz; ++b) {
      ++uses[static_cast<size_t>((a / nz) * ny + b / nz)];
      pairs.emplace_back(a, b);
    }
  if (p.q() == 1 && H.rows() == L) {  // SISO with t fixed: the pair block is H itself (one L × L buffer less)
    ws.fft.correlate_reflected(ws.Q_hat[0], ws.Qt_hat[0], ws.R_hat[0], H);
    add_diagonal_sums(P, H);
    add_transpose_in_place(H);  // 2·(symmetric part)
    return;
  }
  const bool shared = ws.shares();
  // pair (a, b) writes the blocks (a, b) and (b, a) only: any thread, any order, the same H
  ws.share(pairs.size(), [&](size_t k, CorrelationWorkspace& fft, Dense& Hh) {
    const auto [a, b] = pairs[k];
    const Index i = a / nz, j = a % nz, i2 = b / nz, j2 = b % nz;
    const bool last_use = !shared && --uses[static_cast<size_t>(i * ny + i2)] == 0;
    if (p.q() == 1)  // logdet_spectra's single pair: the first term in Q̂'s array, P̂ in Q̂ᵀ's
      fft.correlate_reflected(ws.Q_hat[0], ws.Qt_hat[0], ws.R_hat[0], Hh);
    else
      fft.correlate_sum(ws.Q_hat[static_cast<size_t>(i * nz + j2)], ws.Qt_hat[static_cast<size_t>(i2 * nz + j)],
                        ws.P_hat[static_cast<size_t>(i * ny + i2)], ws.R_hat[static_cast<size_t>(j * nz + j2)], Hh, last_use);
    if (j == j2) add_diagonal_sums(sub_block(P, ny, ny, i, i2), Hh);
    if (a == b) {
      H.block(at(i, j), at(i, j), L, L) += Hh + Hh.transpose();  // 2·(symmetric part)
    } else {
      H.block(at(i, j), at(i2, j2), L, L) += 2.0 * Hh;
      H.block(at(i2, j2), at(i, j), L, L) += 2.0 * Hh.transpose();
    }
  });
}

/// Gradient and Hessian of F_μ at an interior point; P, Q, R as in the header.
/// Entry-pair blocks of the Hessian, variable (i, j) at shift k against
/// (i', j') at shift l (sub-blocks X_ab of P, Q, R as in sub_block):
///   2·sym( [j = j']·Σ_c P_ii'(c+k, c+l) + corr(Q_ij', Q_i'jᵀ)(k, −l) + corr(P_ii', R_jj')(k, l) ).
void derivatives(const Problem& p, const Point& pt, double mu, DerivativeWorkspace& ws, Vecd& g, Dense& H, Dense& P,
                 Dense& Q, Dense& R) {
  const Index L = p.L, ny = p.ny, nz = p.nz, nt = p.taps();
  llt_inverse(pt.llt, P, Q, ws.helper);  // P = F⁻¹ = L⁻ᵀL⁻¹ (Q: scratch until Q = P·T)
  ws.times_T.set_taps(pt.taps);  // Q = P·T and R = Tᵀ·Q by FFT
  ws.times_T.right_into(P, Q);
  ws.times_T.left_into(Q, R);
  R = 0.5 * (R + R.transpose());
  g = Vecd::Zero(p.dim());
  H = Dense::Zero(p.dim(), p.dim());
  logdet_spectra(p, P, Q, R, ws, g);  // −log det(tI − TTᵀ)
  logdet_hessian(p, P, ws, H);
  if (p.t_var) {
    g(nt) = p.ct / mu - P.trace();
    Dense& PQ = ws.Hh;
    PQ.noalias() = P * Q;
    for (Index i = 0; i < ny; ++i)
      for (Index j = 0; j < nz; ++j) H.block((i * nz + j) * L, nt, L, 1) = -2.0 * subdiagonal_sums(sub_block(PQ, ny, nz, i, j));
    H.block(nt, 0, 1, nt) = H.block(0, nt, nt, 1).transpose();
    H(nt, nt) = P.squaredNorm();
  }
  add_noise_terms(p, pt, mu, g, H);
}

/// The tangent of the central path from μ to μ/factor at a centred x:
/// with F_μ = f₀/μ + φ (f₀ = c_t t + c_s‖d‖²/N when s is eliminated, c_t t
/// when it is fixed), ∇f₀/μ + ∇φ = 0 differentiated in μ gives H ẋ = ∇f₀/μ²,
/// so Δx = (μ/factor − μ)·ẋ = −(1 − 1/factor)·H⁻¹(∇f₀/μ). Empty when H
/// could not be factored (`factored`: H's factorisation).
Vecd predictor_step(const Problem& p, const Point& pt, const NewtonFactor& factored, double mu, double factor) {
  Vecd v = Vecd::Zero(p.dim());
  if (p.t_var) v(p.taps()) = p.ct / mu;
  if (p.s_var) {
    const double w = p.cs / (p.N * mu);
    for (Index i = 0; i < p.ny; ++i)
      for (Index j = 0; j < p.nz; ++j)
        v.segment((i * p.nz + j) * p.L, p.L) = -2.0 * w * (p.Z[static_cast<size_t>(j)].transpose() * pt.d_tail.col(i));
  }
  if (!factored.positive()) return {};
  Vecd step = -(1.0 - 1.0 / factor) * factored.solve(v);
  return step.allFinite() ? step : Vecd();
}

/// The free regressors G of a scaled problem: r ← P⊥r and W = ZᵀQ (P⊥ and
/// Q do not depend on the scaling: range(G) is a subspace).
void add_free_regressors(Problem& p, const Mat<double>& free_regressors) {
  p.regressors = FreeRegressors(free_regressors, p.n, p.ny, "structured barrier");
  if (p.regressors.empty()) return;
  project_residual(p, p.r_head, p.r_tail);
  const Dense& Q = p.regressors.basis();
  p.W = Dense::Zero(p.taps(), Q.cols());
  Dense head, tail;
  for (Index c = 0; c < Q.cols(); ++c) {
    split_residual(p, Q.col(c), head, tail);
    for (Index i = 0; i < p.ny; ++i)
      for (Index j = 0; j < p.nz; ++j)
        p.W.col(c).segment((i * p.nz + j) * p.L, p.L) = p.Z[static_cast<size_t>(j)].transpose() * tail.col(i);
  }
}

/// The records' rows of the scaled problem: head and tail rows, r on them,
/// the horizon L = max_k (n_k − m_k), and Z (the Problem's fields; σ_z, σ_r set).
void record_rows(Problem& p, const Mat<double>& z, const Mat<double>& r, const RecordLengths& records_in) {
  const RecordLengths records = record_lengths_of(records_in, z.rows());
  const std::vector<Index> start = record_starts(records);
  std::vector<Index> first;  // per record: its first nonzero z (stacked row)
  for (size_t k = 0; k < records.size(); ++k) {
    first.push_back(start[k] + leading_zero_rows(z, start[k], records[k]));
    for (Index row = start[k]; row < start[k + 1]; ++row) (row < first[k] ? p.head_rows : p.tail_rows).push_back(row);
  }
  p.records = records;
  p.L = records_horizon(z, records);
  p.m = static_cast<Index>(p.head_rows.size());
  const Index M = static_cast<Index>(p.tail_rows.size());
  p.r_head.resize(p.m, p.ny);
  p.r_tail.resize(M, p.ny);
  for (Index a = 0; a < p.m; ++a) p.r_head.row(a) = r.row(p.head_rows[static_cast<size_t>(a)]) / p.sigma_r;
  for (Index a = 0; a < M; ++a) p.r_tail.row(a) = r.row(p.tail_rows[static_cast<size_t>(a)]) / p.sigma_r;
  for (Index j = 0; j < p.nz; ++j) {
    Dense Zj = Dense::Zero(M, p.L);
    Index o = 0;  // record k's first row in the stacked tail
    for (size_t k = 0; k < records.size(); ++k) {
      const Index Lk = start[k + 1] - first[k];
      Zj.block(o, 0, Lk, Lk) = lower_toeplitz(z.col(j).segment(first[k], Lk) / p.sigma_z);
      o += Lk;
    }
    p.Z.push_back(std::move(Zj));
  }
}

/// The scaled problem of solve_delta_form_barrier (σ_z, σ_r returned).
Problem make_problem(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective,
                     const Mat<double>& free_regressors, const RecordLengths& records, double& sigma_z, double& sigma_r) {
  Problem p;
  static_cast<SignalScaling&>(p) = signal_scaling(z, r);
  record_rows(p, z, r, records);
  p.N = static_cast<double>(p.n * p.ny);
  p.nu = static_cast<double>(p.L * (p.ny + p.nz)) + p.N + 1.0;
  sigma_z = p.sigma_z;
  sigma_r = p.sigma_r;
  for (Index j = 0; j < p.nz; ++j)
    for (Index j2 = 0; j2 < p.nz; ++j2) p.G.push_back(p.Z[static_cast<size_t>(j)].transpose() * p.Z[static_cast<size_t>(j2)]);
  add_free_regressors(p, free_regressors);
  p.t_var = !objective.delta_fixed();
  p.s_var = objective.kind != BoundObjective::Kind::kMinDelta;  // fixed bounds go through min d_max²
  const double kz = sigma_z / sigma_r;
  p.t_fix = objective.delta.approx * objective.delta.approx * kz * kz;
  p.s_fix = objective.dmax.approx * objective.dmax.approx / (sigma_r * sigma_r);
  if (objective.kind == BoundObjective::Kind::kWeighted) {
    p.ct = objective.lambda / (sigma_z * sigma_z);
    p.cs = 1.0 - objective.lambda;
  } else {
    p.ct = p.t_var ? 1.0 : 0.0;
    p.cs = p.s_var ? 1.0 : 0.0;
  }
  return p;
}

/// Min δ at a fixed d_max: taps strictly inside (C2). Per output i, the ridge
/// taps h_i(ρ) = Zcᵀ(K + ρI)⁻¹r_i with Zc = [Z_1 … Z_nz], K = Zc Zcᵀ
/// (d_i = ρ(K + ρI)⁻¹r_i → 0 as ρ → 0 for one record: Zc has full row rank
/// once the leading zeros are cut; several records stack more tail rows than
/// taps, and d_i tends to the part of r_i outside range(Zc)), at the largest
/// ρ that puts ‖d‖² at most halfway between its floor (‖r_head‖² plus that
/// part) and N·s. Not Zc⁻¹r itself: on a long record its entries
/// grow geometrically. Computed from the thin SVD Zc = U Σ Vᵀ, h_i(ρ) =
/// V diag(σ/(σ² + ρ)) Uᵀ r_i, not from an eigendecomposition of K: a lower
/// Toeplitz Zc whose inverse grows like 3^L (z = 0.5, −1, −1, …) has
/// σ_min/σ_max ~ 1e-10, which the SVD resolves while K's eigenvalues (~1e-20
/// of the largest) drown in its rounding (~1e-16), leaving the smallest
/// directions unfitted at every ρ. With free regressors r is P⊥r here and the
/// misfit ‖P⊥r − Z h‖² an upper bound on the projected one ‖P⊥(r − Z h)‖²,
/// so the start is inside (C2) all the same. Empty with the reason when there
/// is no such point.
std::string ridge_start(const Problem& p, Vecd& x) {
  const double cap = p.N * p.s_fix;
  if (!(p.r_head.squaredNorm() < cap)) return "the rows before the first nonzero z already exceed N*dmax^2";
  Dense Zc(p.r_tail.rows(), p.L * p.nz);
  for (Index j = 0; j < p.nz; ++j) Zc.middleCols(j * p.L, p.L) = p.Z[static_cast<size_t>(j)];
  const Eigen::BDCSVD<Dense> svd(Zc, Eigen::ComputeThinU | Eigen::ComputeThinV);
  if (svd.info() != Eigen::Success) return "no singular value decomposition for the start";
  const Dense B = svd.matrixU().transpose() * p.r_tail;  // min(rows, L·nz) × ny
  // several records: more tail rows than taps, and the part of r_tail outside
  // range(Zc) is a misfit no taps remove (one record: Zc has no more rows than columns)
  const double head = p.r_head.squaredNorm() + (Zc.rows() > Zc.cols() ? (p.r_tail - svd.matrixU() * B).squaredNorm() : 0.0);
  const double target = 0.5 * (head + cap);
  if (!(head < cap)) return "the residual no taps can fit already exceeds N*dmax^2";
  if (p.r_head.squaredNorm() + p.r_tail.squaredNorm() <= target) return "";  // h = 0 is inside
  const Vecd sigma = svd.singularValues();
  const Vecd lambda = sigma.array().square().matrix();
  const auto misfit = [&](double rho) {
    return head + ((rho / (lambda.array() + rho)).matrix().asDiagonal() * B).squaredNorm();
  };
  const double top = std::max(lambda.maxCoeff(), 1e-300);
  const auto largest_rho_within = [&](double allowed) {  // bisection in log ρ; NaN when even ρ → 0 misses
    double lo = std::log(top * 1e-30), hi = std::log(top * 1e8);
    if (!(misfit(std::exp(lo)) <= allowed)) return std::numeric_limits<double>::quiet_NaN();
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      (misfit(std::exp(mid)) <= allowed ? lo : hi) = mid;
    }
    return std::exp(lo);
  };
  const auto taps_norm2 = [&](double rho) {
    return ((sigma.array() / (lambda.array() + rho)).matrix().asDiagonal() * B).squaredNorm();
  };
  // The misfit budget: the ridge path is the minimum-‖h‖ path, and near an
  // ill-conditioned direction ‖h‖ jumps by orders of magnitude for a small
  // gain in misfit (z = 0.5, −1, −1, … at d_max a quarter of the residual's
  // RMS: ‖h‖² ≈ 1e18 at half the budget, ≈ 1 at 99.9 % of it, and the barrier
  // cannot walk back from the former). Of the fractions tried, the start
  // minimises log ‖h‖² − log(N·s − ‖d‖²), the two barrier terms it trades.
  double rho = std::numeric_limits<double>::quiet_NaN(), best = std::numeric_limits<double>::infinity();
  for (double fraction : {0.5, 0.9, 0.99, 0.999, 0.9999}) {
    const double allowed = head + fraction * (cap - head), r = largest_rho_within(allowed);
    if (!(r > 0)) continue;
    const double score = std::log(taps_norm2(r)) - std::log(cap - misfit(r));
    if (score < best) best = score, rho = r;
  }
  if (!(rho > 0)) return "no ridge start inside N*dmax^2 (the data is too ill-conditioned)";
  const Dense H = svd.matrixV() * ((sigma.array() / (lambda.array() + rho)).matrix().asDiagonal() * B);  // (L·nz) × ny
  for (Index i = 0; i < p.ny; ++i)
    for (Index j = 0; j < p.nz; ++j) x.segment((i * p.nz + j) * p.L, p.L) = H.col(i).segment(j * p.L, p.L);
  return "";
}

/// A power-iteration estimate of ‖T_h‖² (a lower estimate; the caller
/// doubles it and checks interiority).
double norm2_estimate(const Dense& T) {
  Vecd v = Vecd::Ones(T.cols()) / std::sqrt(static_cast<double>(T.cols()));
  double norm2 = 0;
  for (int it = 0; it < 30; ++it) {
    const Vecd w = T.transpose() * (T * v);
    norm2 = w.norm();
    if (!(norm2 > 0)) break;
    v = w / norm2;
  }
  return norm2;
}

DeltaFormSolution fail(DeltaFormSolution out, const std::string& why) {
  out.solve.status = SolveStatus::kBackendError;
  out.solve.message = "structured barrier: " + why;
  return out;
}

/// One run of the barrier method: the state its stages share (the scaled
/// problem, the iterate x = (h, t), μ, the evaluated point, the derivative
/// buffers) and the stages themselves, in the order solve_delta_form_barrier
/// calls them.
class BarrierRun {
 public:
  BarrierRun(const Problem& p, const BoundObjective& objective, const BarrierOptions& options)
      : p_(p), options_(options), helper_(helper_for(options)), ws_(p), feasibility_(objective.kind == BoundObjective::Kind::kFeasibility),
        nt_(p.taps()), Ly_(static_cast<double>(p.L * p.ny)), x_(Vecd::Zero(p.dim())) {
    ws_.set_helper(helper_.get());
  }

  /// Start: h = 0 and, for a free δ, t central for μ₀ (c_t/μ = tr P = L·ny/t);
  /// μ₀ puts the eliminated s at twice the residual's mean square. "" on success.
  std::string start() {
    const double D0 = p_.r_head.squaredNorm() + p_.r_tail.squaredNorm();
    mu_ = p_.cs * std::max(D0 / p_.N, 1e-12);
    if (p_.t_var) x_(nt_) = mu_ * Ly_ / p_.ct;
    if (!p_.s_var) {
      // min δ at a fixed d_max: (C2) strictly inside, then t = twice an
      // estimate of ‖T_h‖², doubled until interior; μ₀ central for it
      if (const std::string why = ridge_start(p_, x_); !why.empty()) return why;
      const double norm2 = norm2_estimate(block_toeplitz(p_, x_));
      x_(nt_) = 2.0 * norm2 + 1e-9 * (1.0 + norm2);
      mu_ = p_.ct * x_(nt_) / Ly_;
      for (int it = 0; it < 60 && (evaluate(p_, x_, mu_, pt_, F1_, helper_.get()), !pt_.interior); ++it) {
        check_deadline("the structured barrier was starting");  // a stop request or --timeout: one factorisation late at most
        x_(nt_) *= 2.0;
        mu_ = p_.ct * x_(nt_) / Ly_;
      }
    }
    evaluate(p_, x_, mu_, pt_, F1_, helper_.get());
    return pt_.interior ? "" : "the start is not interior";
  }

  /// Newton on F_μ until the decrement λ² is below `tol`; "" on success.
  std::string center(double tol, int max_steps) {
    for (int inner = 0; inner < max_steps; ++inner) {
      last_center_steps_ = inner;
      check_deadline("the structured barrier was solving");  // the user's --timeout, between Newton steps
      if (++newton_ > options_.max_newton) return "no convergence within " + std::to_string(options_.max_newton) + " Newton steps";
      Vecd dx;
      double dec2 = 0;
      if (const std::string err = newton_direction(dx, dec2); !err.empty()) return err;
      if (dec2 < tol) return "";
      if (!line_search(dx, dec2)) return "the line search found no interior point";
      if (stalled_) return "";  // no progress possible in floating point: as central as it gets
    }
    return "not centred within " + std::to_string(max_steps) + " Newton steps";
  }

  /// Follows the central path until the gap is small (or, for fixed bounds,
  /// until a feasible point or a proof of infeasibility appears). "" on success.
  std::string follow_path() {
    for (;;) {
      // 200, not 60: from h = 0 the first centering of a MIMO problem at a large δ
      // (Example 1, 2×2, n = 200, δ = 1) took about 70 damped steps
      if (const std::string err = center(0.25, 200); !err.empty()) return err;
      const double obj = objective_of(x_, pt_);
      if (feasibility_) {
        if (s_of(pt_) <= p_.s_fix) {  // a feasible point: the taps certify "consistent" (no polishing: keep it)
          found_feasible_ = true;
          return "";
        }
        if (obj - 2.0 * p_.nu * mu_ > p_.s_fix) {  // the central path's lower estimate is above d_max²
          infeasible_ = true;
          return "";
        }
      }
      if (p_.nu * mu_ <= std::max((feasibility_ ? options_.feasibility_rel_gap : options_.rel_gap) * std::abs(obj), options_.abs_gap))
        return "";
      reduce_mu();
    }
  }

  /// Y = μ·C⁻¹ is dual feasible only on the central path: centre tightly
  /// (the residual is what certify/dual_certify.h must project away and
  /// cover with a PSD margin), then the final derivatives. "" on success.
  std::string finish() {
    pivoted_newton_ = true;
    if (!found_feasible_)
      if (const std::string err = center(1e-14, 30); !err.empty() && err.rfind("not centred", 0) != 0) return err;
    if (!derivatives_current_) {  // else the last Newton step's, at this point and μ
      derivatives(p_, pt_, mu_, ws_, g_, H_, P_, Q_, R_);
    }
    // no further Newton step: the FFT buffers, the factorisation and the trial point go before write() allocates the duals
    ws_.release();
    newton_factor_.release();
    factor_of_H_ = false;
    trial_ = Point();
    F1_ = Dense();
    Hs_ = Dense();
    if (feasibility_ && !(s_of(pt_) <= p_.s_fix)) infeasible_ = true;  // undecided at the smallest gap: the dual certificate decides
    return "";
  }

  /// The answer in original units (as solve_delta_form): taps, bounds, dual matrices, status.
  void write(DeltaFormSolution& out, const BoundObjective& objective, double sigma_r, double kz) const {
    write_duals(out, sigma_r, kz);
    const double s = s_of(pt_);
    out.taps = Eigen::Map<const Dense>(x_.data(), p_.L, p_.q()) / kz;  // column i·nz + j: entry (i, j) over l
    out.delta2 = p_.t_var ? x_(nt_) / (kz * kz) : objective.delta.approx * objective.delta.approx;
    out.dmax2 = feasibility_ ? objective.dmax.approx * objective.dmax.approx : s * sigma_r * sigma_r;
    out.path_mu = found_feasible_ ? 0.0 : mu_;  // a point found on the way is not centred
    out.solve.status = infeasible_ ? SolveStatus::kPrimalInfeasible : SolveStatus::kOptimal;
    out.solve.iterations = newton_;
    // objective in original units: σ_r² × the scaled one (c_t was set so that
    // this holds for the weighted objective's t too); min δ: δ² = t'/kz²
    const double scale = p_.s_var ? sigma_r * sigma_r : 1.0 / (kz * kz);
    out.solve.objective = objective_of(x_, pt_) * scale;
    out.solve.dual_objective = (objective_of(x_, pt_) - p_.nu * mu_) * scale;
    out.solve.message = "structured barrier: " + std::to_string(newton_) + " Newton steps, final mu " + std::to_string(mu_);
  }

 private:
  /// s: eliminated (its minimiser for the current h) or fixed.
  double s_of(const Point& q) const { return p_.s_var ? q.D / p_.N + mu_ / p_.cs : p_.s_fix; }
  double objective_of(const Vecd& y, const Point& q) const { return (p_.t_var ? p_.ct * y(nt_) : 0.0) + p_.cs * s_of(q); }

  /// The Newton direction and its decrement λ² = −gᵀdx. MIMO: ZᵀZ-type noise
  /// terms are singular along taps that do not change d, and at small μ they
  /// dwarf the log-det curvature there; a zero pivot in floating point then
  /// gets a Levenberg shift τ·I (still a descent direction; the line search
  /// decides the step).
  std::string newton_direction(Vecd& dx, double& dec2) {
    newton_factor_.release();  // L × L matrices fewer at the derivatives' memory peak
    trial_ = Point();
    F1_ = Dense();
    derivatives(p_, pt_, mu_, ws_, g_, H_, P_, Q_, R_);
    derivatives_current_ = true;
    check_deadline("the structured barrier was solving");  // the derivatives take seconds on long records
    bool solved = false;
    const double scale_h = std::max(H_.diagonal().cwiseAbs().maxCoeff(), 1e-300);
    for (int shift = 0; shift < 8 && !solved; ++shift) {
      if (shift == 0) {
        newton_factor_.compute(H_, helper_.get(), pivoted_newton_);
      } else {
        Hs_ = H_;
        Hs_.diagonal().array() += scale_h * double_power_of_ten(-16 + 2 * shift);
        newton_factor_.compute(Hs_, helper_.get(), pivoted_newton_);
      }
      factor_of_H_ = shift == 0;
      solved = newton_factor_.positive();
      if (solved) dx = newton_factor_.solve(-g_);
      solved = solved && dx.allFinite();
    }
    if (!solved) return "the Newton system is singular";
    dec2 = -g_.dot(dx);
    return dec2 >= 0 ? "" : "not a descent direction (the Hessian lost definiteness)";
  }

  /// Backtracking (Armijo) from the full step; F_μ changes are O(1) numbers
  /// (the objective enters divided by μ but as a difference). nz > 1: the
  /// noise term is flat along taps with Σ_j Z_j h_ij = 0 and only the log-det
  /// barrier rules them; full steps with λ > 1 (outside the Dikin ellipsoid)
  /// there ran to within 1e-8 of tI − TTᵀ's boundary and Newton then crawled
  /// out at λ² ≈ 3 for ~100 steps (3×3, n = 200). From λ·α ≤ damping the step
  /// stays within a few Dikin radii. False when no interior point was found.
  bool line_search(const Vecd& dx, double dec2) {
    release_step_matrices();
    const double lambda = std::sqrt(dec2);
    double alpha = p_.nz > 1 ? std::min(1.0, options_.damping / (1.0 + lambda)) : 1.0;
    Point& trial = trial_;
    for (int ls = 0; ls < 60; ++ls, alpha *= 0.5) {
      check_deadline("the structured barrier was solving");  // each trial is one factorisation of the horizon
      evaluate(p_, x_ + alpha * dx, mu_, trial, F1_, helper_.get());
      if (trial.interior && (dec2 < 1e-6 || trial.value - pt_.value <= -0.25 * alpha * dec2)) break;
    }
    if (!trial.interior) return false;
    stalled_ = alpha < 1e-12;
    if (stalled_) return true;
    x_ += alpha * dx;
    std::swap(pt_, trial_);
    derivatives_current_ = false;
    return true;
  }

  /// μ divided by its factor, with the predictor's tangent step halved until
  /// it is interior and lowers F_μ (x is kept otherwise: F_μ's domain does not
  /// depend on μ).
  void reduce_mu() {
    const double factor = adapt_mu_factor();
    if (options_.predictor && !factor_of_H_) newton_factor_.compute(H_, helper_.get(), pivoted_newton_);  // else the last Newton step's factorisation of H is at hand
    factor_of_H_ = true;
    const Vecd step = options_.predictor ? predictor_step(p_, pt_, newton_factor_, mu_, factor) : Vecd();
    mu_ /= factor;
    release_step_matrices();
    evaluate(p_, x_, mu_, pt_, F1_, helper_.get());
    double beta = 1.0;
    for (int k = 0; k < 12 && step.size() == p_.dim(); ++k, beta *= 0.5) {
      check_deadline("the structured barrier was solving");
      evaluate(p_, x_ + beta * step, mu_, trial_, F1_, helper_.get());
      if (trial_.interior && trial_.value < pt_.value) {
        x_ += beta * step;
        std::swap(pt_, trial_);
        return;
      }
    }
  }

  /// P, Q and R go before trial points are factored (each an L × L matrix;
  /// with the trial point's factor and T Tᵀ's buffer they would make the
  /// solve's memory peak): derivatives() forms them again, and finish() when
  /// the point it certifies is not the one they were formed at.
  void release_step_matrices() {
    P_ = Dense();
    Q_ = Dense();
    R_ = Dense();
    derivatives_current_ = false;
  }

  /// The factor of the next μ reduction, from the last centering's Newton
  /// steps (BarrierOptions::slow_centering): √ after a slow one (not below
  /// min_mu_factor), squared after a quick one (≤ 2 steps; not above the base).
  double adapt_mu_factor() {
    const double base = p_.s_var ? options_.mu_factor : options_.mu_factor_fixed_noise;
    if (factor_ == 0) factor_ = base;
    if (last_center_steps_ > options_.slow_centering)
      factor_ = std::max(std::min(base, options_.min_mu_factor), std::sqrt(factor_));
    else if (last_center_steps_ <= 2)
      factor_ = std::min(base, factor_ * factor_);
    return factor_;
  }

  /// Dual matrices of (C1) and (C2) from the central point (scaled), then in
  /// original units as solve_delta_form.
  void write_duals(DeltaFormSolution& out, double sigma_r, double kz) const {
    const Index Y = p_.L * p_.ny, Z = p_.L * p_.nz, Nn = p_.n * p_.ny;
    out.dual_c1 = Dense::Zero(Y + Z, Y + Z);
    out.dual_c1.topLeftCorner(Y, Y) = mu_ * P_;
    out.dual_c1.topRightCorner(Y, Z) = -mu_ * Q_;
    out.dual_c1.bottomLeftCorner(Z, Y) = -mu_ * Q_.transpose();
    out.dual_c1.bottomRightCorner(Z, Z) = mu_ * (Dense::Identity(Z, Z) + R_);
    const Vecd d = stacked_residual(p_, pt_.d_head, pt_.d_tail);  // row k·ny + i of (C2)
    const double phi = p_.N * s_of(pt_) - pt_.D;  // = N μ / c_s on the path when s is eliminated
    out.dual_c2 = Dense::Zero(Nn + 1, Nn + 1);
    out.dual_c2(0, 0) = mu_ / phi;
    out.dual_c2.block(1, 0, Nn, 1) = -mu_ * d / phi;
    out.dual_c2.block(0, 1, 1, Nn) = out.dual_c2.block(1, 0, Nn, 1).transpose();
    out.dual_c2.bottomRightCorner(Nn, Nn) = mu_ * (Dense::Identity(Nn, Nn) + d * d.transpose() / phi);
    out.dual_c1.topRows(Y) *= kz;
    out.dual_c1.leftCols(Y) *= kz;
    out.dual_c2.row(0) /= sigma_r;
    out.dual_c2.col(0) /= sigma_r;
  }

  /// A helper thread when options.threads (0: the machine's cores, one inside
  /// a parallel_for's workers) is at least 2.
  static std::unique_ptr<HelperThread> helper_for(const BarrierOptions& options) {
    const unsigned threads = options.threads != 0 ? options.threads : inside_parallel_jobs() ? 1 : default_thread_count();
    return threads >= 2 ? std::make_unique<HelperThread>() : nullptr;
  }

  const Problem& p_;
  const BarrierOptions& options_;
  std::unique_ptr<HelperThread> helper_;
  DerivativeWorkspace ws_;
  const bool feasibility_;
  const Index nt_;
  const double Ly_;
  Vecd x_;
  double mu_ = 0;
  Point pt_;
  int newton_ = 0;
  int last_center_steps_ = 0;  ///< Newton steps of the last centering
  double factor_ = 0;          ///< the current μ reduction factor (0: not yet set)
  bool infeasible_ = false, found_feasible_ = false, stalled_ = false;
  Vecd g_;
  Dense H_, P_, Q_, R_;
  bool derivatives_current_ = false;  ///< g_ … R_ are those of pt_ at mu_
  // storage reused from step to step: the trial point, T Tᵀ's buffer, the Newton system's factorisation
  Point trial_;
  Dense F1_, Hs_;
  NewtonFactor newton_factor_;
  bool pivoted_newton_ = false;  ///< the final tight centering factors H by the pivoted LDLᵀ
  bool factor_of_H_ = false;  ///< newton_factor_ factors H_ itself (no Levenberg shift)
};

/// q (minimum-norm least squares for the final taps) and d = r − Z h − G q, original units.
void write_free_solution(DeltaFormSolution& out, const Problem& p, const Mat<double>& z, const Mat<double>& r) {
  Vecd e = stack_rows(Mat<double>(r - apply_fir_records(out.taps, z, p.ny, p.L, p.records)));
  out.free_coefficients = p.regressors.coefficients(e);
  if (p.regressors.count() > 0) e -= p.regressors.matrix() * out.free_coefficients;
  out.noise_residual = unstack_rows(e, p.ny);
}

}  // namespace

DeltaFormSolution solve_delta_form_barrier(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective,
                                           const BarrierOptions& options, const Mat<double>& free_regressors,
                                           const RecordLengths& records) {
  const auto start = std::chrono::steady_clock::now();
  objective.validate();
  DeltaFormSolution out;
  out.solve.backend = "barrier";
  if (z.rows() != r.rows() || !barrier_applies(z, r, objective))
    return fail(out, "applies to every objective (weighted: 0 < lambda < 1; fixed bounds: delta > 0; min delta: dmax > 0)");
  double sigma_z = 1, sigma_r = 1;
  const Problem p = make_problem(z, r, objective, free_regressors, records, sigma_z, sigma_r);
  out.leading_zeros = p.m;
  out.horizon = p.L;
  BarrierRun run(p, objective, options);
  if (const std::string err = run.start(); !err.empty()) return fail(out, err);
  if (const std::string err = run.follow_path(); !err.empty()) return fail(out, err);
  if (const std::string err = run.finish(); !err.empty()) return fail(out, err);
  run.write(out, objective, sigma_r, sigma_z / sigma_r);  // h' = kz·h, t' = kz²·t, s' = s/σ_r² with kz = σ_z/σ_r
  write_free_solution(out, p, z, r);
  out.solve.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

BarrierDerivatives barrier_derivatives(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective,
                                       const Eigen::VectorXd& x, double mu, const Mat<double>& free_regressors,
                                       const RecordLengths& records, unsigned threads) {
  double sigma_z = 1, sigma_r = 1;
  const Problem p = make_problem(z, r, objective, free_regressors, records, sigma_z, sigma_r);
  BarrierDerivatives out;
  Point pt;
  Dense F1;
  const std::unique_ptr<HelperThread> helper = threads >= 2 ? std::make_unique<HelperThread>() : nullptr;
  evaluate(p, x, mu, pt, F1, helper.get());
  out.value = pt.value;
  if (!pt.interior) return out;
  DerivativeWorkspace ws(p);
  ws.set_helper(helper.get());
  Dense P, Q, R;
  derivatives(p, pt, mu, ws, out.gradient, out.hessian, P, Q, R);
  return out;
}

}  // namespace lpvid
