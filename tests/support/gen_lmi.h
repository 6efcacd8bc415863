#pragma once
/// Generators for LMI programs (solvers tests). Built by construction, no
/// rejection: a strictly feasible point x0 and a strictly feasible dual Y0
/// are chosen first, then F0 and c are made to fit them, so every generated
/// program has a finite optimum attained on both sides (strong duality).

#include <rapidcheck.h>

#include <ostream>
#include <vector>

#include <Eigen/Dense>

#include "solvers/lmi_program.h"

namespace lpvid {

/// How rapidcheck prints a counterexample: sizes, cost and every entry.
inline void showValue(const LmiProgram& p, std::ostream& os) {
  os << "LmiProgram{num_vars " << p.num_vars << ", cost [";
  for (double c : p.cost) os << ' ' << c;
  os << " ]";
  for (const LmiBlock& b : p.blocks) {
    os << "\n  block '" << b.name << "' size " << b.size << (b.diagonal ? " diagonal" : "") << ": F0";
    for (const SymEntry& e : b.F0.entries) os << " (" << e.i << ',' << e.j << ")=" << e.value;
    for (const auto& [k, F] : b.Fi) {
      os << "; F_" << k;
      for (const SymEntry& e : F.entries) os << " (" << e.i << ',' << e.j << ")=" << e.value;
    }
  }
  os << "}";
}

}  // namespace lpvid

namespace lpvid::gen {

/// k/4 for k in [-4, 4]: exactly representable, small.
inline double quarter() { return *rc::gen::inRange(-4, 5) / 4.0; }

/// A random symmetric positive definite matrix I + B Bᵀ/4 (B with entries
/// in {-1, 0, 1}).
inline Eigen::MatrixXd positive_definite(int n) {
  Eigen::MatrixXd B(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) B(i, j) = *rc::gen::inRange(-1, 2);
  return Eigen::MatrixXd::Identity(n, n) + B * B.transpose() / 4.0;
}

/// A well-posed program: 1–4 variables, 1–3 random blocks of size 1–5 (some
/// diagonal), plus a diagonal block of lower bounds x_k ≥ x0_k − 1 that makes
/// the F_k linearly independent. x0 is strictly feasible (F(x0) ≻ 0) and
/// c_k = ⟨F_k, Y0⟩ for some Y0 ≻ 0, so the optimum is finite and attained.
inline rc::Gen<LmiProgram> well_posed_lmi_program() {
  return rc::gen::exec([] {
    LmiProgram p;
    const int nvars = *rc::gen::inRange(1, 5);
    p.add_variables(nvars);
    std::vector<double> x0(static_cast<std::size_t>(nvars));
    for (double& v : x0) v = 2.0 * quarter();

    const int nblocks = *rc::gen::inRange(1, 4);
    std::vector<Eigen::MatrixXd> Y0;
    for (int b = 0; b < nblocks; ++b) {
      const int n = *rc::gen::inRange(1, 6);
      const bool diagonal = *rc::gen::inRange(0, 3) == 0;
      const int blk = p.add_block("random" + std::to_string(b), n, diagonal);
      Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(n, n);  // Σ x0_k F_k
      for (int k = 0; k < nvars; ++k)
        for (int i = 0; i < n; ++i)
          for (int j = i; j < (diagonal ? i + 1 : n); ++j) {
            if (*rc::gen::inRange(0, 3) != 0) continue;  // about a third of the entries
            const double v = quarter();
            if (v == 0.0) continue;
            p.add_entry(blk, k, i, j, v);
            sum(i, j) += x0[static_cast<std::size_t>(k)] * v;
            if (i != j) sum(j, i) += x0[static_cast<std::size_t>(k)] * v;
          }
      Eigen::MatrixXd S = positive_definite(n);  // F(x0) = S ≻ 0
      if (diagonal) S = Eigen::MatrixXd(S.diagonal().asDiagonal());
      const Eigen::MatrixXd F0 = S - sum;
      for (int i = 0; i < n; ++i)
        for (int j = i; j < n; ++j)
          if (F0(i, j) != 0.0 && (!diagonal || i == j)) p.add_entry(blk, -1, i, j, F0(i, j));
      Eigen::MatrixXd Y = positive_definite(n);
      if (diagonal) Y = Eigen::MatrixXd(Y.diagonal().asDiagonal());
      Y0.push_back(Y);
    }
    // Lower bounds x_k − (x0_k − 1) ≥ 0.
    const int bounds = p.add_block("bounds", nvars, true);
    for (int k = 0; k < nvars; ++k) {
      p.add_entry(bounds, k, k, k, 1.0);
      p.add_entry(bounds, -1, k, k, 1.0 - x0[static_cast<std::size_t>(k)]);
    }
    Y0.push_back(Eigen::MatrixXd::Identity(nvars, nvars));

    // c_k = ⟨F_k, Y0⟩.
    for (std::size_t b = 0; b < p.blocks.size(); ++b)
      for (const auto& [k, F] : p.blocks[b].Fi)
        for (const SymEntry& e : F.entries)
          p.cost[static_cast<std::size_t>(k)] += (e.i == e.j ? 1.0 : 2.0) * e.value * Y0[b](e.i, e.j);
    return p;
  });
}

}  // namespace lpvid::gen
