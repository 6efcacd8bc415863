/// Solve times of the SDP backends (CLI timing mode; DESIGN layout "bench/").
///
///   sdp_bench                     all problems below, both backends
///   sdp_bench --only lambda       only the λ_max problems
///   sdp_bench --only toeplitz     only the Toeplitz-like problem
///   sdp_bench --solvers csdp      one backend
///   sdp_bench --toeplitz 400 500  Toeplitz-like block of size 400 with 500 variables
///   sdp_bench --write-sdpa DIR    also write each program as DIR/<name>.dat-s
///
/// Problems:
///  - lambda_max n: min t s.t. t I − M ⪰ 0 for a random symmetric M (seeded),
///    n = 100, 200, 400; the answer is checked against Eigen's λ_max.
///  - toeplitz n k: min cᵀx s.t. I + Σ_d x_d E_d ⪰ 0 (one block of size n),
///    where E_d (d < n) has ones on the d-th super- and sub-diagonal (a
///    symmetric Toeplitz basis, n − d entries each) and the remaining k − n
///    variables each scale four consecutive diagonal entries; c_d = ⟨E_d, Y0⟩
///    with Y0 = [0.9^|i−j|] ≻ 0, so the optimum is finite. Default n = 800,
///    k = 1000: sparse, O(n) nonzeros per variable, like T_w in Theorem 2.1.
///
/// OpenBLAS runs single-threaded (SolverOptions::threads = 1) unless
/// --threads is given.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "solvers/lmi_program.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "solvers/sdpa_file.h"

namespace {

using lpvid::LmiProgram;

LmiProgram lambda_max_program(int n, double& lambda) {
  std::mt19937 rng(static_cast<unsigned>(n));
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::MatrixXd M(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j) M(i, j) = M(j, i) = normal(rng);
  lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M, Eigen::EigenvaluesOnly).eigenvalues()(n - 1);
  LmiProgram p;
  const int t = p.add_variable("t", 1.0);
  const int b = p.add_block("tI-M", n);
  for (int i = 0; i < n; ++i) {
    p.add_entry(b, t, i, i, 1.0);
    for (int j = i; j < n; ++j) p.add_entry(b, -1, i, j, -M(i, j));
  }
  return p;
}

LmiProgram toeplitz_program(int n, int k) {
  LmiProgram p;
  const int b = p.add_block("toeplitz", n);
  for (int i = 0; i < n; ++i) p.add_entry(b, -1, i, i, 1.0);  // F0 = I: x = 0 is strictly feasible
  auto y0 = [](int i, int j) { return std::pow(0.9, std::abs(i - j)); };
  for (int v = 0; v < k; ++v) {
    double c = 0.0;
    const int x = p.add_variable("x" + std::to_string(v));
    if (v < n) {  // E_d, d = v
      const int d = v;
      for (int i = 0; i + d < n; ++i) {
        p.add_entry(b, x, i, i + d, 1.0);
        c += (d == 0 ? 1.0 : 2.0) * y0(i, i + d);
      }
    } else {  // four diagonal entries
      const int start = (4 * (v - n)) % (n - 3);
      for (int i = start; i < start + 4; ++i) {
        p.add_entry(b, x, i, i, 1.0);
        c += y0(i, i);
      }
    }
    p.set_cost(x, c);
  }
  return p;
}

void report(const std::string& problem, const LmiProgram& p, const lpvid::SolveResult& r, const std::string& check) {
  std::printf("%-22s %-5s vars %5d  nnz %8zu  %-18s it %3d  obj % .10e  %9.3f s  %s\n", problem.c_str(),
              r.backend.c_str(), p.num_vars, p.nonzeros(), lpvid::to_string(r.status), r.iterations, r.objective,
              r.seconds, check.c_str());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> solvers = lpvid::available_solvers();
  std::string only, write_dir;
  int toeplitz_n = 800, toeplitz_k = 1000;
  lpvid::SolverOptions options;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--only" && a + 1 < argc) {
      only = argv[++a];
    } else if (arg == "--solvers" && a + 1 < argc) {
      solvers = {argv[++a]};
    } else if (arg == "--toeplitz" && a + 2 < argc) {
      toeplitz_n = std::atoi(argv[++a]);
      toeplitz_k = std::atoi(argv[++a]);
    } else if (arg == "--threads" && a + 1 < argc) {
      options.threads = std::atoi(argv[++a]);
    } else if (arg == "--write-sdpa" && a + 1 < argc) {
      write_dir = argv[++a];
    } else {
      std::fprintf(stderr, "usage: %s [--only lambda|toeplitz] [--solvers NAME] [--toeplitz N K] [--threads T] "
                   "[--write-sdpa DIR]\n", argv[0]);
      return 2;
    }
  }
  std::printf("gap_tol %g, feas_tol %g, max_iterations %d, threads %d\n", options.gap_tol, options.feas_tol,
              options.max_iterations, options.threads);

  if (only.empty() || only == "lambda") {
    for (int n : {100, 200, 400}) {
      double lambda = 0.0;
      const LmiProgram p = lambda_max_program(n, lambda);
      const std::string name = "lambda_max_" + std::to_string(n);
      if (!write_dir.empty()) lpvid::write_sdpa_file(p, write_dir + "/" + name + ".dat-s");
      for (const std::string& s : solvers) {
        const lpvid::SolveResult r = lpvid::make_solver(s)->solve(p, options);
        char check[64];
        std::snprintf(check, sizeof check, "|t - lambda_max| = %.1e", std::fabs(r.x[0] - lambda));
        report(name, p, r, check);
      }
    }
  }
  if (only.empty() || only == "toeplitz") {
    const LmiProgram p = toeplitz_program(toeplitz_n, toeplitz_k);
    const std::string name = "toeplitz_" + std::to_string(toeplitz_n) + "_" + std::to_string(toeplitz_k);
    if (!write_dir.empty()) lpvid::write_sdpa_file(p, write_dir + "/" + name + ".dat-s");
    for (const std::string& s : solvers) {
      const lpvid::SolveResult r = lpvid::make_solver(s)->solve(p, options);
      report(name, p, r, r.message.substr(0, 60));
    }
  }
  return 0;
}
