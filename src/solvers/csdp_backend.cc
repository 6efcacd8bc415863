#include "solvers/csdp_backend.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "core/deadline.h"
#include "solvers/watchdog_child.h"

extern "C" {
#include <csdp/declarations.h>
}

namespace lpvid {

// ============================================================================
// Sign convention (written once).
//
// CSDP solves the pair
//   primal:  max tr(C X)   s.t. tr(A_i X) = a_i,  X ⪰ 0
//   dual:    min aᵀy       s.t. Σ_i y_i A_i − C = Z ⪰ 0.
// Our (P) "min cᵀx s.t. F0 + Σ x_i F_i ⪰ 0" is CSDP's DUAL with
//   y = x,   A_i = F_i,   C = −F0,   a = c,   Z = F(x),
// and our (D) "max −⟨F0, Y⟩ s.t. ⟨F_i, Y⟩ = c_i, Y ⪰ 0" is CSDP's primal with
// X = Y. So our objective is CSDP's dobj and our dual objective its pobj.
// CSDP's "primal infeasible" is therefore OUR dual infeasible and vice versa.
// ============================================================================

namespace {

/// Our codes for runs that CSDP itself did not end (run_sdp_watched).
constexpr int kCodeStalled = -2;
constexpr int kCodeChildFailed = -3;

/// CSDP's return code → SolveStatus. The one place where CSDP's codes are
/// interpreted (codes from the CSDP 6.2 user's guide and lib/sdp.c).
SolveStatus status_from_csdp(int code, std::string& words) {
  switch (code) {
    case 0:
      words = "CSDP 0: success, problem solved to optimality";
      return SolveStatus::kOptimal;
    case 1:  // CSDP's primal (our (D)) infeasible: y with aᵀy < 0, Σ y_i A_i ⪰ 0.
      words = "CSDP 1: CSDP's primal is infeasible (certificate y): our objective is unbounded below";
      return SolveStatus::kDualInfeasible;
    case 2:  // CSDP's dual (our (P)) infeasible: X ⪰ 0, A(X) = 0, tr(CX) > 0.
      words = "CSDP 2: CSDP's dual is infeasible (certificate X): our LMI has no solution";
      return SolveStatus::kPrimalInfeasible;
    case 3:  // Tolerances missed by a factor < 1000. NOT success.
      words = "CSDP 3: partial success, solution found but full accuracy not reached";
      return SolveStatus::kOptimalInaccurate;
    case 4:
      words = "CSDP 4: maximum iterations reached";
      return SolveStatus::kIterationLimit;
    case 5:
      words = "CSDP 5: stuck at edge of primal feasibility";
      return SolveStatus::kBackendError;
    case 6:
      words = "CSDP 6: stuck at edge of dual feasibility";
      return SolveStatus::kBackendError;
    case 7:
      words = "CSDP 7: lack of progress";
      return SolveStatus::kBackendError;
    case 8:
      words = "CSDP 8: X, Z or O was singular";
      return SolveStatus::kBackendError;
    case 9:
      words = "CSDP 9: detected NaN or Inf values";
      return SolveStatus::kBackendError;
    case 10:
      words = "CSDP 10: stopped by a signal (user_exit)";
      return SolveStatus::kBackendError;
    case kCodeStalled:
      words = "CSDP made no progress inside one iteration and was stopped by the watchdog (CPU-time budget spent)";
      return SolveStatus::kBackendError;
    case kCodeChildFailed:
      words = "the CSDP process ended abnormally";
      return SolveStatus::kBackendError;
    default:
      words = "CSDP " + std::to_string(code) + ": unknown return code";
      return SolveStatus::kBackendError;
  }
}

/// CSDP keeps the Schur matrix O (k × k, dense) indexed with int unless it
/// was built with BIT64; CSDP refuses more constraints than this in 32-bit
/// index mode (readprob.c). We keep to the same limit.
constexpr int kMaxCsdpVariables = 23169;

/// CSDP's parameters, set here instead of from "param.csdp" (easy_sdp() would
/// read that file from the working directory, and a partial file leaves
/// fields uninitialised). Values not taken from SolverOptions are CSDP's
/// documented defaults; perturbobj and affine are chosen by the caller (see
/// kAttempts).
paramstruc csdp_parameters(const SolverOptions& o, int perturbobj, int affine) {
  paramstruc p{};
  p.axtol = o.feas_tol;
  p.atytol = o.feas_tol;
  p.objtol = o.gap_tol;
  p.pinftol = o.divergence_bound;
  p.dinftol = o.divergence_bound;
  p.maxiter = o.max_iterations;
  p.minstepfrac = 0.90;
  p.maxstepfrac = 0.97;
  p.minstepp = 1.0e-8;
  p.minstepd = 1.0e-8;
  p.usexzgap = 1;
  p.tweakgap = 0;
  p.affine = affine;
  p.perturbobj = perturbobj;
  p.fastmode = 0;
  return p;
}

/// Everything CSDP allocates or reads, freed in one place whatever happens.
struct CsdpProblem {
  int n = 0;  // total size Σ block sizes
  int k = 0;  // number of constraints = our variables
  blockmatrix C{0, nullptr};
  double* a = nullptr;
  constraintmatrix* constraints = nullptr;
  std::vector<sparseblock*> owned_blocks;

  CsdpProblem() = default;
  CsdpProblem(const CsdpProblem&) = delete;
  CsdpProblem& operator=(const CsdpProblem&) = delete;
  ~CsdpProblem() {
    for (sparseblock* p : owned_blocks) {
      std::free(p->entries);
      std::free(p->iindices);
      std::free(p->jindices);
      std::free(p);
    }
    std::free(constraints);
    std::free(a);
    if (C.blocks != nullptr) {
      for (int b = 1; b <= C.nblocks; ++b) std::free(C.blocks[b].data.mat);  // vec and mat share the union
      std::free(C.blocks);
    }
  }
};

template <typename T>
T* checked_calloc(std::size_t count) {
  void* p = std::calloc(count == 0 ? 1 : count, sizeof(T));
  if (p == nullptr) throw std::bad_alloc();
  return static_cast<T*>(p);
}

/// CSDP's constraints A_i = F_i of a reduced program whose objective blocks
/// `out.C` are built (their categories decide which blocks are sparse).
void build_constraints(const LmiProgram& p, CsdpProblem& out) {
  const int nb = static_cast<int>(p.blocks.size());
  out.constraints = checked_calloc<constraintmatrix>(static_cast<std::size_t>(out.k) + 1);
  // Blocks are visited from last to first and prepended, so each constraint's
  // list ends up in block order (CSDP does not require it; it is tidy).
  for (int b = nb; b >= 1; --b) {
    const LmiBlock& blk = p.blocks[static_cast<std::size_t>(b - 1)];
    for (const auto& [var, F] : blk.Fi) {  // A_i = F_i
      const int num = static_cast<int>(F.entries.size());
      auto* sb = checked_calloc<sparseblock>(1);
      out.owned_blocks.push_back(sb);
      sb->entries = checked_calloc<double>(static_cast<std::size_t>(num) + 1);
      sb->iindices = checked_calloc<int>(static_cast<std::size_t>(num) + 1);
      sb->jindices = checked_calloc<int>(static_cast<std::size_t>(num) + 1);
      for (int e = 0; e < num; ++e) {
        const SymEntry& en = F.entries[static_cast<std::size_t>(e)];
        sb->entries[e + 1] = en.value;
        sb->iindices[e + 1] = en.i + 1;
        sb->jindices[e + 1] = en.j + 1;
      }
      sb->numentries = num;
      sb->blocknum = b;
      sb->blocksize = blk.size;
      sb->constraintnum = var + 1;
      // Dense or sparse handling in CSDP's Schur complement (op_o): the same
      // rule as easy_sdp() applies; diagonal blocks are always sparse.
      const double kk = out.k, nn = num, ss = blk.size;
      const bool dense = kk * kk * nn * nn > 0.125 * kk * ss * ss * ss && num > 5;
      sb->issparse = (out.C.blocks[b].blockcategory == DIAG || !dense) ? 1 : 0;
      sb->next = out.constraints[var + 1].blocks;
      out.constraints[var + 1].blocks = sb;
      sb->nextbyblock = nullptr;
    }
  }
}

/// Builds CSDP's C, a and constraints from a reduced program (every F_i
/// nonempty, every block depends on x). Indices are 1-based; matrix blocks
/// are Fortran column-major; constraint entries are upper triangle (i ≤ j),
/// sorted by (i, j), without duplicates — exactly what easy_sdp's checks
/// would demand, so nothing in CSDP needs to exit().
void build_problem(const LmiProgram& p, CsdpProblem& out) {
  const int nb = static_cast<int>(p.blocks.size());
  out.k = p.num_vars;
  out.C.nblocks = nb;
  out.C.blocks = checked_calloc<blockrec>(static_cast<std::size_t>(nb) + 1);
  for (int b = 1; b <= nb; ++b) {
    const LmiBlock& blk = p.blocks[static_cast<std::size_t>(b - 1)];
    const int s = blk.size;
    out.n += s;
    blockrec& rec = out.C.blocks[b];
    rec.blocksize = s;
    if (sdp_detail::acts_diagonally(blk)) {
      rec.blockcategory = DIAG;
      rec.data.vec = checked_calloc<double>(static_cast<std::size_t>(s) + 1);
      for (const SymEntry& e : blk.F0.entries) rec.data.vec[e.i + 1] = -e.value;  // C = −F0
    } else {
      rec.blockcategory = MATRIX;
      rec.data.mat = checked_calloc<double>(static_cast<std::size_t>(s) * static_cast<std::size_t>(s));
      for (const SymEntry& e : blk.F0.entries) {
        rec.data.mat[ijtok(e.i + 1, e.j + 1, s)] = -e.value;  // C = −F0, both triangles
        rec.data.mat[ijtok(e.j + 1, e.i + 1, s)] = -e.value;
      }
    }
  }

  out.a = checked_calloc<double>(static_cast<std::size_t>(out.k) + 1);
  for (int i = 1; i <= out.k; ++i) out.a[i] = p.cost[static_cast<std::size_t>(i - 1)];  // a = c

  build_constraints(p, out);
}

/// Heap blocks that sdp() needs and easy_sdp() would allocate.
struct Workspace {
  blockmatrix work1{}, work2{}, work3{}, Zi{}, dZ{}, dX{};
  blockmatrix bestx{}, bestz{}, cholxinv{}, cholzinv{};  // packed
  blockmatrix X{}, Z{};
  double* y = nullptr;
  std::vector<double*> vecs;
  double* O = nullptr;
  std::vector<sparseblock*> byblocks;  // 1-based, [0] unused
  constraintmatrix fill{nullptr};
  bool have_mats = false, have_packed = false, have_solution = false;

  Workspace() = default;
  Workspace(const Workspace&) = delete;
  Workspace& operator=(const Workspace&) = delete;
  ~Workspace() {
    if (have_mats)
      for (blockmatrix* m : {&work1, &work2, &work3, &Zi, &dZ, &dX}) free_mat(*m);
    if (have_packed)
      for (blockmatrix* m : {&bestx, &bestz, &cholxinv, &cholzinv}) free_mat_packed(*m);
    if (have_solution) {
      free_mat(X);
      free_mat(Z);
      std::free(y);
    }
    for (double* v : vecs) std::free(v);
    std::free(O);
    for (sparseblock* p = fill.blocks; p != nullptr;) {
      sparseblock* next = p->next;
      std::free(p->entries);
      std::free(p->iindices);
      std::free(p->jindices);
      std::free(p);
      p = next;
    }
  }
  double* vec(std::size_t count) {
    vecs.push_back(checked_calloc<double>(count));
    return vecs.back();
  }
};

/// Links each block's sparse constraint blocks in increasing constraint
/// order (op_o walks j > i along nextbyblock) and returns byblocks (1-based).
std::vector<sparseblock*> link_by_blocks(const CsdpProblem& prob) {
  std::vector<sparseblock*> byblocks(static_cast<std::size_t>(prob.C.nblocks) + 1, nullptr);
  std::vector<sparseblock*> last(byblocks.size(), nullptr);
  for (int i = 1; i <= prob.k; ++i)
    for (sparseblock* sb = prob.constraints[i].blocks; sb != nullptr; sb = sb->next) {
      const auto b = static_cast<std::size_t>(sb->blocknum);
      if (last[b] == nullptr)
        byblocks[b] = sb;
      else
        last[b]->nextbyblock = sb;
      last[b] = sb;
    }
  return byblocks;
}

/// One run of CSDP's sdp() from its default starting point.
struct Attempt {
  int code = -1;
  double pobj = 0.0, dobj = 0.0;
  std::vector<double> y;               // 0-based
  std::vector<Eigen::MatrixXd> X;      // only if asked
  double relative_gap() const { return std::fabs(dobj - pobj) / (1.0 + std::fabs(dobj) + std::fabs(pobj)); }
};

Attempt run_sdp(const CsdpProblem& prob, std::vector<sparseblock*>& byblocks, const paramstruc& params,
                int printlevel, const LmiProgram& p, bool want_dual) {
  const int n = prob.n, k = prob.k;
  Workspace w;
  alloc_mat(prob.C, &w.work1);
  alloc_mat(prob.C, &w.work2);
  alloc_mat(prob.C, &w.work3);
  alloc_mat(prob.C, &w.Zi);
  alloc_mat(prob.C, &w.dZ);
  alloc_mat(prob.C, &w.dX);
  w.have_mats = true;
  alloc_mat_packed(prob.C, &w.bestx);
  alloc_mat_packed(prob.C, &w.bestz);
  alloc_mat_packed(prob.C, &w.cholxinv);
  alloc_mat_packed(prob.C, &w.cholzinv);
  w.have_packed = true;
  const std::size_t nk = static_cast<std::size_t>(n > k ? n : k) + 1;
  double* workvec[8];
  for (double*& v : workvec) v = w.vec(nk);
  double* diagO = w.vec(nk);
  double* besty = w.vec(static_cast<std::size_t>(k) + 1);
  double* rhs = w.vec(static_cast<std::size_t>(k) + 1);
  double* dy = w.vec(static_cast<std::size_t>(k) + 1);
  double* dy1 = w.vec(static_cast<std::size_t>(k) + 1);
  double* Fp = w.vec(static_cast<std::size_t>(k) + 1);
  const std::size_t ldam = static_cast<std::size_t>(k % 2 == 0 ? k + 1 : k);  // as sdp() computes it
  w.O = checked_calloc<double>(ldam * ldam);

  makefill(k, prob.C, prob.constraints, &w.fill, w.work1, printlevel);
  initsoln(n, k, prob.C, prob.a, prob.constraints, &w.X, &w.y, &w.Z);
  w.have_solution = true;

  Attempt out;
  out.code = sdp(n, k, prob.C, prob.a, 0.0, prob.constraints, byblocks.data(), w.fill, w.X, w.y, w.Z, w.cholxinv,
                 w.cholzinv, &out.pobj, &out.dobj, w.work1, w.work2, w.work3, workvec[0], workvec[1], workvec[2],
                 workvec[3], workvec[4], workvec[5], workvec[6], workvec[7], diagO, w.bestx, besty, w.bestz, w.Zi,
                 w.O, rhs, w.dZ, w.dX, dy, dy1, Fp, printlevel, params);
  out.y.assign(w.y + 1, w.y + 1 + k);
  if (want_dual) {
    for (int b = 1; b <= w.X.nblocks; ++b) {
      const blockrec& rec = w.X.blocks[b];
      const int s = rec.blocksize;
      const bool column = p.blocks[static_cast<std::size_t>(b - 1)].diagonal;  // the program's layout
      if (rec.blockcategory == DIAG) {
        Eigen::MatrixXd Y = Eigen::MatrixXd::Zero(s, column ? 1 : s);
        for (int i = 1; i <= s; ++i) Y(i - 1, column ? 0 : i - 1) = rec.data.vec[i];
        out.X.push_back(std::move(Y));
      } else {
        out.X.push_back(Eigen::Map<const Eigen::MatrixXd>(rec.data.mat, s, s));  // column-major
      }
    }
  }
  return out;
}

template <typename T>
void put(std::FILE* f, const T* v, std::size_t count) {
  if (count > 0 && std::fwrite(v, sizeof(T), count, f) != count) _exit(3);  // in the child: a failed run
}
template <typename T>
bool get(std::FILE* f, T* v, std::size_t count) {
  return count == 0 || std::fread(v, sizeof(T), count, f) == count;
}

void write_attempt(std::FILE* f, const Attempt& a) {
  const long head[3] = {a.code, static_cast<long>(a.y.size()), static_cast<long>(a.X.size())};
  const double obj[2] = {a.pobj, a.dobj};
  put(f, head, 3);
  put(f, obj, 2);
  put(f, a.y.data(), a.y.size());
  for (const Eigen::MatrixXd& X : a.X) {
    const long dims[2] = {static_cast<long>(X.rows()), static_cast<long>(X.cols())};
    put(f, dims, 2);
    put(f, X.data(), static_cast<std::size_t>(X.size()));
  }
}

bool read_attempt(std::FILE* f, Attempt& a) {
  long head[3];
  double obj[2];
  if (!get(f, head, 3) || !get(f, obj, 2) || head[1] < 0 || head[2] < 0) return false;
  a.code = static_cast<int>(head[0]);
  a.pobj = obj[0];
  a.dobj = obj[1];
  a.y.resize(static_cast<std::size_t>(head[1]));
  if (!get(f, a.y.data(), a.y.size())) return false;
  for (long b = 0; b < head[2]; ++b) {
    long dims[2];
    if (!get(f, dims, 2) || dims[0] < 0 || dims[1] < 0) return false;
    Eigen::MatrixXd X(dims[0], dims[1]);
    if (!get(f, X.data(), static_cast<std::size_t>(X.size()))) return false;
    a.X.push_back(std::move(X));
  }
  return true;
}

/// run_sdp in a child process under the stall watchdog (watchdog_child.h):
/// CSDP can spin forever inside one iteration, where its maxiter cap never
/// looks (IdentifyRegression.CsdpReturnsOnThisRelaxation: perturbobj 0 loops
/// in copy_mat at iteration 50). The child prints CSDP's per-iteration lines
/// (printlevel ≥ 1) as the heartbeat; they are shown only when verbose. The
/// budget is CPU time, so load never stops a healthy solve; past the user's
/// --timeout the child is killed and TimedOut thrown.
Attempt run_sdp_watched(const CsdpProblem& prob, std::vector<sparseblock*>& byblocks, const paramstruc& params,
                        int printlevel, const LmiProgram& p, bool want_dual, std::string& note) {
  Attempt out;
  std::FILE* f = std::tmpfile();
  if (f == nullptr) {  // no temporary file: run unguarded
    note = "unguarded run (no temporary file)";
    return run_sdp(prob, byblocks, params, printlevel, p, want_dual);
  }
  WatchdogOptions wo;
  wo.echo = printlevel > 0;
  // CPU budget floor from the size: one iteration costs about m²·Σn_b (Schur
  // matrix) + Σn_b³ (factorisations) flops; at a pessimistic 1e9 flop/s,
  // allow 10 iterations' worth of CPU time without output.
  double m = static_cast<double>(p.num_vars), sum_n = 0, sum_n3 = 0;
  for (const LmiBlock& b : p.blocks) {
    const double nb = static_cast<double>(b.size);
    sum_n += nb;
    if (!b.diagonal) sum_n3 += nb * nb * nb;
  }
  wo.min_stall_cpu_seconds = std::max(wo.min_stall_cpu_seconds, 10.0 * 1e-9 * (m * m * sum_n + sum_n3 + m * m * m));
  const WatchdogOutcome w = run_in_watched_child(
      [&](std::FILE* r) { write_attempt(r, run_sdp(prob, byblocks, params, std::max(printlevel, 1), p, want_dual)); },
      f, wo);
  if (w.finished && read_attempt(f, out)) {
    note.clear();
  } else if (w.stalled) {
    out = Attempt{};
    out.code = kCodeStalled;
    char buf[160];
    std::snprintf(buf, sizeof buf, "stopped after %.3g CPU s without progress, above its budget of %.3g CPU s",
                  w.stall_cpu_seconds, w.budget_cpu_seconds);
    note = buf;
  } else {
    out = Attempt{};
    out.code = kCodeChildFailed;
    note = w.error.empty() ? "its result could not be read" : w.error;
  }
  std::fclose(f);
  if (w.timed_out) check_deadline("CSDP was solving");
  return out;
}

/// Codes after which a second run with the other perturbobj is worth it.
bool worth_retrying(int code) {
  return code == 3 || (code >= 5 && code <= 9) || code == kCodeStalled || code == kCodeChildFailed;
}

/// Status rank for choosing between two runs (lower is better).
int rank(SolveStatus s) {
  switch (s) {
    case SolveStatus::kOptimal: return 0;
    case SolveStatus::kOptimalInaccurate: return 1;
    case SolveStatus::kPrimalInfeasible:
    case SolveStatus::kDualInfeasible: return 2;
    case SolveStatus::kIterationLimit: return 3;
    case SolveStatus::kBackendError: return 4;
  }
  return 4;
}

/// The runs we try, in order, while CSDP ends with code 3 or 5–9 (partial
/// success, stuck, lack of progress, singular, NaN). Measured with the
/// `csdp` command on random well-posed programs of tests/support/gen_lmi.h's
/// kind (1500 mixed LMI/LP programs, 1000 small pure LPs), failures were:
///   perturbobj 0, affine 0:  6 / 1500 and 48 / 1000
///   perturbobj 1, affine 0:  3 / 1500 and 20 / 1000 (CSDP's defaults; also
///                            fails min t s.t. [[t,1],[1,1]] ⪰ 0 with code 5)
///   perturbobj 0, affine 1:  0 / 1500 and  0 / 1000
/// and the failing sets hardly overlap. perturbobj perturbs C by
/// 1e-6·‖C‖/√n; affine = 1 takes primal-dual affine steps (mu = 0) instead
/// of CSDP's centred ones. We start with CSDP's usual centred steps and
/// fall back to the others; the best run is kept (status first, then the
/// relative gap), and the message says what happened.
struct AttemptParameters {
  int perturbobj;
  int affine;
};
constexpr AttemptParameters kAttempts[] = {{0, 0}, {0, 1}, {1, 0}};

SolveResult csdp_solve_reduced(const LmiProgram& p, const SolverOptions& options) {
  SolveResult r;
  if (p.num_vars > kMaxCsdpVariables) {
    r.status = SolveStatus::kBackendError;
    r.message = "CSDP: " + std::to_string(p.num_vars) + " variables exceed CSDP's limit of " +
                std::to_string(kMaxCsdpVariables) + " (dense k x k Schur matrix)";
    return r;
  }
  CsdpProblem prob;
  build_problem(p, prob);
  std::vector<sparseblock*> byblocks = link_by_blocks(prob);
  const int printlevel = options.verbose ? options.print_level : 0;

  Attempt best;
  SolveStatus status = SolveStatus::kBackendError;
  std::string words, history;
  int runs = 0;
  for (const AttemptParameters& a : kAttempts) {
    std::string note;
    Attempt run = run_sdp_watched(prob, byblocks, csdp_parameters(options, a.perturbobj, a.affine), printlevel, p,
                                  options.want_dual, note);
    std::string run_words;
    const SolveStatus run_status = status_from_csdp(run.code, run_words);
    const bool better = runs == 0 || rank(run_status) < rank(status) ||
                        (rank(run_status) == rank(status) && run.relative_gap() < best.relative_gap());
    history += std::string(runs ? "; " : "") + "CSDP " + std::to_string(run.code) + " with perturbobj " +
               std::to_string(a.perturbobj) + ", affine " + std::to_string(a.affine) + (note.empty() ? "" : " (" + note + ")");
    ++runs;
    if (better) {
      best = std::move(run);
      status = run_status;
      words = run_words;
    }
    if (!worth_retrying(best.code)) break;
  }
  if (runs > 1) words += " (runs: " + history + ")";
  if (options.verbose) std::fflush(stdout);

  r.status = status;
  r.message = words;
  r.x = std::move(best.y);          // y = x
  r.dual_objective = best.pobj;     // tr(C X) = −⟨F0, Y⟩; our cᵀx is recomputed from x by the caller
  r.iterations = -1;                // sdp() does not report it
  r.dual_blocks = std::move(best.X);  // X = Y
  return r;
}

}  // namespace

SolveStatus csdp_status(int return_code, std::string* words) {
  std::string w;
  const SolveStatus s = status_from_csdp(return_code, w);
  if (words != nullptr) *words = w;
  return s;
}

SolveResult CsdpSolver::solve(const LmiProgram& program, const SolverOptions& options) {
  return sdp_detail::solve_with_presolve(program, options, name(), &csdp_solve_reduced);
}

}  // namespace lpvid
