#pragma once
/// A solver-neutral LMI program (docs/design.md §13.1: problem, solver, result apart).
///
///     minimise    cᵀx
///     subject to  F0_b + Σ_i x_i F_i,b  ⪰ 0      for every block b
///
/// x ∈ R^num_vars is free. Each block is a symmetric matrix inequality of its
/// own size, or — when `diagonal` — a set of `size` scalar inequalities
/// (a diagonal LMI: every F is diagonal). The program only holds the
/// nonzeros, so its memory is proportional to them, not to size².
///
/// Indices are 0-based everywhere in this API (variables, blocks, rows and
/// columns). Writers for outside formats (sdpa_file.h) convert.
///
/// Builders (Theorem 2.1 / 3.1 assembly) fill a program with add_block /
/// add_entry / add_scalar_inequality; a solver backend (solvers/) turns it
/// into its own structures in one place. Misuse throws std::invalid_argument
/// naming the block, the variable and the entry (docs/design.md §13.2).

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

namespace lpvid {

/// One stored entry of a symmetric matrix: the (i, j) and (j, i) element,
/// with i ≤ j. Off-diagonal values are NOT doubled: {0, 1, 2.0} means
/// M(0,1) = M(1,0) = 2.
struct SymEntry {
  int i = 0;
  int j = 0;
  double value = 0.0;
  friend bool operator==(const SymEntry&, const SymEntry&) = default;
};

/// A sparse symmetric matrix as upper-triangle triplets. Several entries at
/// the same (i, j) are summed (so builders may add contributions freely);
/// compress() puts it in canonical form.
struct SymSparse {
  std::vector<SymEntry> entries;

  /// Adds `value` at (i, j) and (j, i); swaps so that i ≤ j. No checks here:
  /// LmiProgram::add_entry and LmiProgram::validate check ranges.
  void add(int i, int j, double value);
  /// Canonical form: sorted by (i, j), duplicates summed, exact zeros
  /// dropped. Two matrices are equal iff their compressed entries are equal.
  void compress();
  bool empty() const { return entries.empty(); }
  std::size_t nonzeros() const { return entries.size(); }
  /// Dense size × size symmetric matrix (for tests and small blocks).
  Eigen::MatrixXd to_dense(int size) const;
  friend bool operator==(const SymSparse&, const SymSparse&) = default;
};

/// One LMI block: F0 + Σ_i x_i F_i ⪰ 0 (a size × size matrix inequality), or
/// when `diagonal` the size scalar inequalities (F0)_kk + Σ_i x_i (F_i)_kk ≥ 0.
struct LmiBlock {
  std::string name;
  int size = 0;
  bool diagonal = false;
  SymSparse F0;
  /// (variable index, F_i) pairs. A variable may appear in several pairs
  /// (they are summed); LmiProgram::compress() merges them, sorts them by
  /// variable and drops the ones that became empty.
  std::vector<std::pair<int, SymSparse>> Fi;
  friend bool operator==(const LmiBlock&, const LmiBlock&) = default;
};

/// The whole program: min cᵀx s.t. every block ⪰ 0. See the file comment.
struct LmiProgram {
  /// Number of (free) variables x_0 … x_{num_vars-1}.
  int num_vars = 0;
  /// Variable names: empty (no names) or exactly num_vars entries.
  std::vector<std::string> var_names;
  /// Cost vector c (MINIMISE cᵀx); exactly num_vars entries.
  std::vector<double> cost;
  std::vector<LmiBlock> blocks;
  /// What the program means outside the solver, as (key, value) text pairs:
  /// its kind ("kind" = "theorem-2.1-delta-form", …), the scalings applied to
  /// the data before it reached the solver and how a variable maps back to
  /// original units. Written as "*lpvid-about key value" comment lines of an
  /// SDPA file and in its sidecar (solvers/sdpa_sidecar.h), read back by
  /// read_sdpa. Keys and values have no line breaks; keys have no spaces.
  std::vector<std::pair<std::string, std::string>> about;

  /// Name of the diagonal block that add_scalar_inequality creates and grows.
  static constexpr const char* kScalarBlockName = "scalar_inequalities";

  /// Adds one variable with cost coefficient `cost_coefficient`; returns its
  /// index. If any variable has a name, every variable gets one (unnamed
  /// ones become "x<k>").
  int add_variable(const std::string& name = "", double cost_coefficient = 0.0);
  /// Adds `count` variables with zero cost; returns the index of the first.
  int add_variables(int count);
  /// Sets c_var (throws for an unknown variable or a non-finite value).
  void set_cost(int var, double value);

  /// Adds an empty block (size ≥ 1); returns its index.
  int add_block(const std::string& name, int size, bool diagonal = false);
  /// Adds `value` to entry (i, j) (and (j, i)) of F_var in `block`;
  /// var = -1 means F0. Throws std::invalid_argument for an unknown block or
  /// variable, an index outside the block, an off-diagonal entry of a
  /// diagonal block, or a non-finite value. Consecutive calls for the same
  /// variable of a block share one F_i (O(1) per call); a builder that
  /// interleaves variables gets one (var, F_i) pair per switch, which
  /// compress() merges — add a variable's entries together where you can.
  void add_entry(int block, int var, int i, int j, double value);
  /// The scalar inequality Σ_k a_k x_{var_k} + b ≥ 0, appended as a new
  /// diagonal entry of the diagonal block named kScalarBlockName (created at
  /// the end of `blocks` if there is none). Returns (block, row).
  std::pair<int, int> add_scalar_inequality(const std::vector<std::pair<int, double>>& a, double b);

  /// Throws std::invalid_argument naming the first offending block /
  /// variable / entry: sizes ≥ 1, cost and names of the right length,
  /// indices in range, i ≤ j, off-diagonal entries only in non-diagonal
  /// blocks, every value finite.
  void validate() const;
  /// Canonical form of every block (SymSparse::compress, Fi merged per
  /// variable, sorted by variable, empty F_i dropped). The program means the
  /// same before and after.
  void compress();
  /// A compressed copy.
  LmiProgram compressed() const;
  /// Total stored entries (F0 and all F_i of all blocks).
  std::size_t nonzeros() const;
  /// Name of variable k ("x<k>" if unnamed).
  std::string var_name(int k) const;

  /// Dense value of block b at x: F0 + Σ x_i F_i (a size × size matrix; for a
  /// diagonal block, the diagonal matrix). x must have num_vars entries.
  Eigen::MatrixXd block_value(int b, const std::vector<double>& x) const;
  /// cᵀx.
  double objective(const std::vector<double>& x) const;

  friend bool operator==(const LmiProgram&, const LmiProgram&) = default;
};

}  // namespace lpvid
