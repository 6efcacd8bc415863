#include "solvers/lmi_program.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace lpvid {
namespace {

std::string block_label(const LmiProgram& p, int b) {
  std::ostringstream os;
  os << "block " << b;
  if (b >= 0 && b < static_cast<int>(p.blocks.size()) && !p.blocks[static_cast<std::size_t>(b)].name.empty())
    os << " '" << p.blocks[static_cast<std::size_t>(b)].name << "'";
  return os.str();
}

std::string matrix_label(const LmiProgram& p, int var) {
  if (var < 0) return "F0 (constant term)";
  return "F_" + std::to_string(var) + " of variable '" + p.var_name(var) + "'";
}

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("LmiProgram: " + what); }

void check_entry(const LmiProgram& p, int b, int var, int i, int j, double value, bool require_upper) {
  const LmiBlock& blk = p.blocks[static_cast<std::size_t>(b)];
  const bool outside = i < 0 || j < 0 || i >= blk.size || j >= blk.size;
  const bool lower = require_upper && i > j;
  const bool off_diagonal = blk.diagonal && i != j;
  if (!outside && !lower && !off_diagonal && std::isfinite(value)) return;  // the message is built only for a bad entry
  std::ostringstream where;
  where << block_label(p, b) << ", " << matrix_label(p, var) << ", entry (" << i << ", " << j << ") = " << value;
  if (outside) fail(where.str() + ": index outside the block of size " + std::to_string(blk.size));
  if (lower) fail(where.str() + ": stored entries need i <= j");
  if (off_diagonal) fail(where.str() + ": off-diagonal entry in a diagonal block");
  fail(where.str() + ": value is not finite");
}

}  // namespace

// --- SymSparse -------------------------------------------------------------

void SymSparse::add(int i, int j, double value) {
  if (i > j) std::swap(i, j);
  entries.push_back({i, j, value});
}

void SymSparse::compress() {
  std::sort(entries.begin(), entries.end(),
            [](const SymEntry& a, const SymEntry& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
  std::size_t out = 0;
  for (std::size_t k = 0; k < entries.size();) {
    SymEntry sum = entries[k];
    std::size_t next = k + 1;
    for (; next < entries.size() && entries[next].i == sum.i && entries[next].j == sum.j; ++next)
      sum.value += entries[next].value;
    if (sum.value != 0.0) entries[out++] = sum;
    k = next;
  }
  entries.resize(out);
}

Eigen::MatrixXd SymSparse::to_dense(int size) const {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(size, size);
  for (const SymEntry& e : entries) {
    m(e.i, e.j) += e.value;
    if (e.i != e.j) m(e.j, e.i) += e.value;
  }
  return m;
}

// --- LmiProgram: building ----------------------------------------------------

std::string LmiProgram::var_name(int k) const {
  if (k >= 0 && static_cast<std::size_t>(k) < var_names.size() && !var_names[static_cast<std::size_t>(k)].empty())
    return var_names[static_cast<std::size_t>(k)];
  return "x" + std::to_string(k);
}

int LmiProgram::add_variable(const std::string& name, double cost_coefficient) {
  if (!std::isfinite(cost_coefficient))
    fail("variable '" + name + "': cost " + std::to_string(cost_coefficient) + " is not finite");
  const bool named = !name.empty() || !var_names.empty();
  if (named && var_names.empty())
    for (int k = 0; k < num_vars; ++k) var_names.push_back("x" + std::to_string(k));
  cost.resize(static_cast<std::size_t>(num_vars), 0.0);
  cost.push_back(cost_coefficient);
  if (named) var_names.push_back(name.empty() ? "x" + std::to_string(num_vars) : name);
  return num_vars++;
}

int LmiProgram::add_variables(int count) {
  if (count < 0) fail("add_variables: negative count " + std::to_string(count));
  const int first = num_vars;
  for (int k = 0; k < count; ++k) add_variable();
  return first;
}

void LmiProgram::set_cost(int var, double value) {
  if (var < 0 || var >= num_vars)
    fail("set_cost: variable " + std::to_string(var) + " out of range [0, " + std::to_string(num_vars) + ")");
  if (!std::isfinite(value)) fail("set_cost: cost of " + matrix_label(*this, var) + " is not finite");
  cost.resize(static_cast<std::size_t>(num_vars), 0.0);
  cost[static_cast<std::size_t>(var)] = value;
}

int LmiProgram::add_block(const std::string& name, int size, bool diagonal) {
  if (size < 1) fail("add_block '" + name + "': size " + std::to_string(size) + " must be at least 1");
  LmiBlock blk;
  blk.name = name;
  blk.size = size;
  blk.diagonal = diagonal;
  blocks.push_back(std::move(blk));
  return static_cast<int>(blocks.size()) - 1;
}

void LmiProgram::add_entry(int block, int var, int i, int j, double value) {
  if (block < 0 || block >= static_cast<int>(blocks.size()))
    fail("add_entry: block " + std::to_string(block) + " out of range [0, " + std::to_string(blocks.size()) + ")");
  if (var < -1 || var >= num_vars)
    fail("add_entry: " + block_label(*this, block) + ": variable " + std::to_string(var) + " out of range [-1, " +
         std::to_string(num_vars) + ")");
  check_entry(*this, block, var, i, j, value, false);
  LmiBlock& blk = blocks[static_cast<std::size_t>(block)];
  if (var < 0) {
    blk.F0.add(i, j, value);
    return;
  }
  if (blk.Fi.empty() || blk.Fi.back().first != var) blk.Fi.emplace_back(var, SymSparse{});
  blk.Fi.back().second.add(i, j, value);
}

std::pair<int, int> LmiProgram::add_scalar_inequality(const std::vector<std::pair<int, double>>& a, double b) {
  int block = -1;
  for (int k = static_cast<int>(blocks.size()) - 1; k >= 0; --k) {
    const LmiBlock& blk = blocks[static_cast<std::size_t>(k)];
    if (blk.diagonal && blk.name == kScalarBlockName) {
      block = k;
      break;
    }
  }
  // Check everything before changing anything, so a throw leaves no half row.
  for (const auto& [var, coef] : a) {
    if (var < 0 || var >= num_vars)
      fail("add_scalar_inequality: variable " + std::to_string(var) + " out of range [0, " + std::to_string(num_vars) +
           ")");
    if (!std::isfinite(coef)) fail("add_scalar_inequality: coefficient of " + matrix_label(*this, var) + " is not finite");
  }
  if (!std::isfinite(b)) fail("add_scalar_inequality: constant term is not finite");
  if (block < 0) {
    block = add_block(kScalarBlockName, 1, true);
  } else {
    ++blocks[static_cast<std::size_t>(block)].size;
  }
  const int row = blocks[static_cast<std::size_t>(block)].size - 1;
  if (b != 0.0) add_entry(block, -1, row, row, b);
  for (const auto& [var, coef] : a)
    if (coef != 0.0) add_entry(block, var, row, row, coef);
  return {block, row};
}

// --- LmiProgram: checking and canonical form ---------------------------------

void LmiProgram::validate() const {
  if (num_vars < 0) fail("num_vars = " + std::to_string(num_vars) + " is negative");
  if (cost.size() != static_cast<std::size_t>(num_vars))
    fail("cost has " + std::to_string(cost.size()) + " entries, num_vars = " + std::to_string(num_vars));
  if (!var_names.empty() && var_names.size() != static_cast<std::size_t>(num_vars))
    fail("var_names has " + std::to_string(var_names.size()) + " entries, num_vars = " + std::to_string(num_vars));
  for (int k = 0; k < num_vars; ++k)
    if (!std::isfinite(cost[static_cast<std::size_t>(k)]))
      fail("cost of " + matrix_label(*this, k) + " is not finite");
  for (int b = 0; b < static_cast<int>(blocks.size()); ++b) {
    const LmiBlock& blk = blocks[static_cast<std::size_t>(b)];
    if (blk.size < 1) fail(block_label(*this, b) + ": size " + std::to_string(blk.size) + " must be at least 1");
    for (const SymEntry& e : blk.F0.entries) check_entry(*this, b, -1, e.i, e.j, e.value, true);
    for (const auto& [var, F] : blk.Fi) {
      if (var < 0 || var >= num_vars)
        fail(block_label(*this, b) + ": variable " + std::to_string(var) + " out of range [0, " +
             std::to_string(num_vars) + ")");
      for (const SymEntry& e : F.entries) check_entry(*this, b, var, e.i, e.j, e.value, true);
    }
  }
}

void LmiProgram::compress() {
  for (LmiBlock& blk : blocks) {
    blk.F0.compress();
    std::stable_sort(blk.Fi.begin(), blk.Fi.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::pair<int, SymSparse>> merged;
    for (auto& [var, F] : blk.Fi) {
      if (!merged.empty() && merged.back().first == var) {
        auto& dst = merged.back().second.entries;
        dst.insert(dst.end(), F.entries.begin(), F.entries.end());
      } else {
        merged.emplace_back(var, std::move(F));
      }
    }
    blk.Fi.clear();
    for (auto& [var, F] : merged) {
      F.compress();
      if (!F.empty()) blk.Fi.emplace_back(var, std::move(F));
    }
  }
}

LmiProgram LmiProgram::compressed() const {
  LmiProgram copy = *this;
  copy.compress();
  return copy;
}

std::size_t LmiProgram::nonzeros() const {
  std::size_t n = 0;
  for (const LmiBlock& blk : blocks) {
    n += blk.F0.nonzeros();
    for (const auto& [var, F] : blk.Fi) n += F.nonzeros();
  }
  return n;
}

// --- LmiProgram: evaluation --------------------------------------------------

Eigen::MatrixXd LmiProgram::block_value(int b, const std::vector<double>& x) const {
  if (b < 0 || b >= static_cast<int>(blocks.size()))
    fail("block_value: block " + std::to_string(b) + " out of range [0, " + std::to_string(blocks.size()) + ")");
  if (x.size() != static_cast<std::size_t>(num_vars))
    fail("block_value: x has " + std::to_string(x.size()) + " entries, num_vars = " + std::to_string(num_vars));
  const LmiBlock& blk = blocks[static_cast<std::size_t>(b)];
  Eigen::MatrixXd m = blk.F0.to_dense(blk.size);
  for (const auto& [var, F] : blk.Fi) {
    const double xv = x[static_cast<std::size_t>(var)];
    for (const SymEntry& e : F.entries) {
      m(e.i, e.j) += xv * e.value;
      if (e.i != e.j) m(e.j, e.i) += xv * e.value;
    }
  }
  return m;
}

double LmiProgram::objective(const std::vector<double>& x) const {
  if (x.size() != cost.size())
    fail("objective: x has " + std::to_string(x.size()) + " entries, cost has " + std::to_string(cost.size()));
  double s = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) s += cost[k] * x[k];
  return s;
}

}  // namespace lpvid
