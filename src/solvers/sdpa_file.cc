#include "solvers/sdpa_file.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "core/file_io.h"
#include "core/input_error.h"
#include "solvers/csdp_backend.h"
#include "solvers/sdpa_backend.h"

namespace lpvid {
namespace {

constexpr std::string_view kBlockTag = "*lpvid-block ";
constexpr std::string_view kVarTag = "*lpvid-var ";
constexpr std::string_view kAboutTag = "*lpvid-about ";

// --- writing -----------------------------------------------------------------

void check_name(const std::string& name, const std::string& what) {
  if (name.find_first_of("\r\n") != std::string::npos)
    throw std::invalid_argument("write_sdpa: " + what + " name '" + name + "' contains a line break");
}

void check_about(const std::pair<std::string, std::string>& kv) {
  if (kv.first.empty() || kv.first.find_first_of(" \t\r\n") != std::string::npos)
    throw std::invalid_argument("write_sdpa: about key '" + kv.first + "' is empty or contains white space");
  check_name(kv.second, "about value of '" + kv.first + "': the");
}

/// "%.17g": enough digits for every double to read back as itself.
void put_number(std::ostream& out, double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  out << buf;
}

// --- reading: lines and numbers ----------------------------------------------

/// Line-by-line reader that knows where it is, for messages.
class Lines {
 public:
  Lines(std::istream& in, std::string name) : in_(in), name_(std::move(name)) {}
  bool next(std::string& line) {
    if (!std::getline(in_, line)) return false;
    ++number_;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
  }
  long number() const { return number_; }
  const std::string& name() const { return name_; }
  [[noreturn]] void fail(const std::string& reason) const { throw_input_error(name_, number_, "", reason); }

 private:
  std::istream& in_;
  std::string name_;
  long number_ = 0;
};

bool blank(std::string_view s) { return s.find_first_not_of(" \t") == std::string_view::npos; }

/// SDPA header lines may use "{", "}", "(", ")" and "," as separators.
void separators_to_spaces(std::string& s) {
  for (char& ch : s)
    if (ch == ',' || ch == '{' || ch == '}' || ch == '(' || ch == ')') ch = ' ';
}

/// Splits at spaces and tabs.
std::vector<std::string_view> tokens(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t k = 0;
  while (k < s.size()) {
    while (k < s.size() && (s[k] == ' ' || s[k] == '\t')) ++k;
    std::size_t end = k;
    while (end < s.size() && s[end] != ' ' && s[end] != '\t') ++end;
    if (end > k) out.push_back(s.substr(k, end - k));
    k = end;
  }
  return out;
}

bool parse_long(std::string_view t, long& value) {
  const std::string s(t);
  char* end = nullptr;
  errno = 0;
  value = std::strtol(s.c_str(), &end, 10);
  return errno == 0 && end == s.c_str() + s.size() && !s.empty();
}

bool parse_double(std::string_view t, double& value) {
  const std::string s(t);
  char* end = nullptr;
  errno = 0;
  value = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && !s.empty() && std::isfinite(value);
}

/// The header (m, nblocks, block sizes, c) as one stream of numbers that may
/// span lines; on each line, the first token that is not a number ends the
/// line ("2 = mDIM").
class HeaderNumbers {
 public:
  explicit HeaderNumbers(Lines& lines) : lines_(lines) {}

  long next_integer(const std::string& what) {
    const std::string_view t = next_token(what);
    long v = 0;
    if (!parse_long(t, v)) lines_.fail(what + ": '" + std::string(t) + "' is not an integer");
    return v;
  }
  double next_double(const std::string& what) {
    const std::string_view t = next_token(what);
    double v = 0;
    if (!parse_double(t, v)) lines_.fail(what + ": '" + std::string(t) + "' is not a finite number");
    return v;
  }
  /// After the header: numbers left on the current line are an error.
  void finish() {
    if (pos_ < toks_.size()) {
      double v = 0;
      if (parse_double(toks_[pos_], v)) lines_.fail("more numbers than expected after the cost vector");
    }
  }
  /// Name/var comments found before the header.
  std::vector<std::string> comments;

 private:
  std::string_view next_token(const std::string& what) {
    while (pos_ >= toks_.size()) {
      if (!lines_.next(line_)) lines_.fail("end of file while reading " + what);
      if (line_.empty() || blank(line_)) continue;
      if (!started_ && (line_[0] == '"' || line_[0] == '*')) {
        comments.push_back(line_);
        continue;
      }
      started_ = true;
      separators_to_spaces(line_);
      toks_ = tokens(line_);
      // Keep the leading numbers of the line only.
      std::size_t n = 0;
      double v = 0;
      while (n < toks_.size() && parse_double(toks_[n], v)) ++n;
      toks_.resize(n);
      pos_ = 0;
      if (toks_.empty()) lines_.fail("expected " + what + ", found '" + line_ + "'");
    }
    return toks_[pos_++];
  }

  Lines& lines_;
  std::string line_;
  std::vector<std::string_view> toks_;
  std::size_t pos_ = 0;
  bool started_ = false;
};

/// Applies the "*lpvid-block b name" / "*lpvid-var k name" / "*lpvid-about key value" comments.
void apply_name_comments(const std::vector<std::string>& comments, LmiProgram& p) {
  bool any_var = false;
  std::vector<std::string> var_names(static_cast<std::size_t>(p.num_vars));
  for (const std::string& c : comments) {
    if (c.rfind(kAboutTag, 0) == 0) {
      const std::string rest = c.substr(kAboutTag.size());
      const std::size_t space = rest.find(' ');
      if (space == std::string::npos || space == 0) continue;  // not ours after all
      p.about.emplace_back(rest.substr(0, space), rest.substr(space + 1));
      continue;
    }
    const bool is_block = c.rfind(kBlockTag, 0) == 0;
    const bool is_var = c.rfind(kVarTag, 0) == 0;
    if (!is_block && !is_var) continue;
    const std::string rest = c.substr(is_block ? kBlockTag.size() : kVarTag.size());
    const std::size_t space = rest.find(' ');
    long index = 0;
    if (!parse_long(std::string_view(rest).substr(0, space), index)) continue;  // not ours after all
    const std::string name = space == std::string::npos ? "" : rest.substr(space + 1);
    if (is_block && index >= 1 && index <= static_cast<long>(p.blocks.size()))
      p.blocks[static_cast<std::size_t>(index - 1)].name = name;
    if (is_var && index >= 1 && index <= p.num_vars) {
      var_names[static_cast<std::size_t>(index - 1)] = name;
      any_var = true;
    }
  }
  if (any_var) p.var_names = std::move(var_names);
}

/// The file's text as a stream (read_text_file: regular files within the size limit).
std::istringstream open_for_reading(const std::string& path) { return std::istringstream(read_text_file(path)); }

/// −⟨F0, Y⟩ over all blocks (Y from dual_blocks; diagonal blocks as columns).
double dual_value(const LmiProgram& p, const std::vector<Eigen::MatrixXd>& Y) {
  double s = 0.0;
  for (std::size_t b = 0; b < p.blocks.size() && b < Y.size(); ++b) {
    const LmiBlock& blk = p.blocks[b];
    for (const SymEntry& e : blk.F0.entries) {
      const double y = blk.diagonal ? Y[b](e.i, 0) : Y[b](e.i, e.j);
      s -= (e.i == e.j ? 1.0 : 2.0) * e.value * y;
    }
  }
  return s;
}

/// The values of xVec: "{x_1,x_2,…}" after the '=' of `line` and on the
/// following line(s).
std::vector<double> sdpa_x_vector(Lines& lines, const std::string& line) {
  std::string text = line.substr(line.find('=') + 1);
  while (text.find('}') == std::string::npos) {
    std::string more;
    if (!lines.next(more)) lines.fail("end of file inside xVec");
    text += ' ' + more;
  }
  if (text.find('{') == std::string::npos) lines.fail("xVec without '{'");
  text = text.substr(text.find('{'), text.find('}') - text.find('{'));
  separators_to_spaces(text);
  std::vector<double> x;
  for (std::string_view t : tokens(text)) {
    double v = 0;
    if (!parse_double(t, v)) lines.fail("xVec entry '" + std::string(t) + "' is not a finite number");
    x.push_back(v);
  }
  return x;
}

}  // namespace

// --- write ---------------------------------------------------------------------

void write_sdpa(const LmiProgram& program, std::ostream& out) {
  program.validate();
  for (const LmiBlock& blk : program.blocks) check_name(blk.name, "block");
  for (const std::string& n : program.var_names) check_name(n, "variable");
  for (const auto& kv : program.about) check_about(kv);
  const LmiProgram p = program.compressed();

  out << "\"lpvid LMI program: min c'x s.t. F0 + sum_k x_k F_k >= 0, written as SDPA's sum_k x_k F_k - F_0 "
         ">= 0 (matrix 0 = -F0)\n";
  for (std::size_t b = 0; b < p.blocks.size(); ++b) out << kBlockTag << b + 1 << ' ' << p.blocks[b].name << '\n';
  for (std::size_t k = 0; k < p.var_names.size(); ++k) out << kVarTag << k + 1 << ' ' << p.var_names[k] << '\n';
  for (const auto& [key, value] : p.about) out << kAboutTag << key << ' ' << value << '\n';
  out << p.num_vars << " = mDIM\n";
  out << p.blocks.size() << " = nBLOCK\n";
  for (std::size_t b = 0; b < p.blocks.size(); ++b)
    out << (b ? " " : "") << (p.blocks[b].diagonal ? -p.blocks[b].size : p.blocks[b].size);
  out << '\n';
  for (std::size_t k = 0; k < p.cost.size(); ++k) {
    if (k) out << ' ';
    put_number(out, p.cost[k]);
  }
  out << '\n';
  for (std::size_t b = 0; b < p.blocks.size(); ++b) {
    const LmiBlock& blk = p.blocks[b];
    auto put = [&](int matno, const SymEntry& e, double sign) {
      out << matno << ' ' << b + 1 << ' ' << e.i + 1 << ' ' << e.j + 1 << ' ';
      put_number(out, sign * e.value);
      out << '\n';
    };
    for (const SymEntry& e : blk.F0.entries) put(0, e, -1.0);  // F_0 (SDPA) = −F0 (ours)
    for (const auto& [var, F] : blk.Fi)
      for (const SymEntry& e : F.entries) put(var + 1, e, 1.0);
  }
}

void write_sdpa_file(const LmiProgram& program, const std::string& path) {
  std::ostringstream out;
  write_sdpa(program, out);
  write_text_file(path, out.str(), "SDPA file");
}

// --- read ----------------------------------------------------------------------

LmiProgram read_sdpa(std::istream& in, const std::string& name) {
  Lines lines(in, name);
  HeaderNumbers header(lines);
  LmiProgram p;
  const long m = header.next_integer("the number of variables (mDIM)");
  if (m < 0 || m > std::numeric_limits<int>::max() / 2) lines.fail("number of variables " + std::to_string(m) + " out of range");
  const long nblocks = header.next_integer("the number of blocks (nBLOCK)");
  if (nblocks < 0 || nblocks > std::numeric_limits<int>::max() / 2)
    lines.fail("number of blocks " + std::to_string(nblocks) + " out of range");
  for (long b = 0; b < nblocks; ++b) {
    const long s = header.next_integer("the size of block " + std::to_string(b + 1));
    if (s == 0 || s > std::numeric_limits<int>::max() / 2 || s < -(std::numeric_limits<int>::max() / 2))
      lines.fail("block " + std::to_string(b + 1) + " has size " + std::to_string(s));
    p.add_block("", static_cast<int>(s < 0 ? -s : s), s < 0);
  }
  p.num_vars = static_cast<int>(m);
  for (long k = 0; k < m; ++k) p.cost.push_back(header.next_double("cost coefficient " + std::to_string(k + 1)));
  header.finish();

  std::string line;
  while (lines.next(line)) {
    if (blank(line) || line[0] == '"' || line[0] == '*') continue;
    separators_to_spaces(line);
    const std::vector<std::string_view> t = tokens(line);
    if (t.size() != 5) lines.fail("expected 'matrix block i j value', found " + std::to_string(t.size()) + " fields");
    long mat = 0, blk = 0, i = 0, j = 0;
    double v = 0;
    if (!parse_long(t[0], mat) || mat < 0 || mat > m)
      lines.fail("matrix number '" + std::string(t[0]) + "' is not an integer in [0, " + std::to_string(m) + "]");
    if (!parse_long(t[1], blk) || blk < 1 || blk > nblocks)
      lines.fail("block number '" + std::string(t[1]) + "' is not an integer in [1, " + std::to_string(nblocks) + "]");
    const LmiBlock& b = p.blocks[static_cast<std::size_t>(blk - 1)];
    if (!parse_long(t[2], i) || !parse_long(t[3], j) || i < 1 || j < 1 || i > b.size || j > b.size)
      lines.fail("entry (" + std::string(t[2]) + ", " + std::string(t[3]) + ") is outside block " +
                 std::to_string(blk) + " of size " + std::to_string(b.size));
    if (b.diagonal && i != j)
      lines.fail("off-diagonal entry (" + std::to_string(i) + ", " + std::to_string(j) + ") in diagonal block " +
                 std::to_string(blk));
    if (!parse_double(t[4], v)) lines.fail("value '" + std::string(t[4]) + "' is not a finite number");
    // Matrix 0 is SDPA's F_0 = −F0 (ours).
    p.add_entry(static_cast<int>(blk - 1), static_cast<int>(mat - 1), static_cast<int>(i - 1), static_cast<int>(j - 1),
                mat == 0 ? -v : v);
  }
  if (in.bad()) lines.fail("read error");
  apply_name_comments(header.comments, p);
  p.compress();
  return p;
}

LmiProgram read_sdpa_file(const std::string& path) {
  std::istringstream in = open_for_reading(path);
  return read_sdpa(in, path);
}

// --- solutions of outside solvers --------------------------------------------

SolveResult read_csdp_solution(const std::string& path, const LmiProgram& program, int exit_code) {
  return parse_csdp_solution(read_text_file(path), path, program, exit_code);
}

SolveResult parse_csdp_solution(const std::string& text, const std::string& path, const LmiProgram& program, int exit_code) {
  program.validate();
  std::istringstream in(text);
  Lines lines(in, path);
  SolveResult r;
  r.backend = "csdp (command)";
  r.status = csdp_status(exit_code, &r.message);

  std::string line;
  if (!lines.next(line)) lines.fail("empty file: expected CSDP's y vector on line 1");
  for (std::string_view t : tokens(line)) {
    double v = 0;
    if (!parse_double(t, v)) lines.fail("y entry '" + std::string(t) + "' is not a finite number");
    r.x.push_back(v);  // CSDP's y = our x
  }
  if (r.x.size() != static_cast<std::size_t>(program.num_vars))
    lines.fail("y has " + std::to_string(r.x.size()) + " entries, the program has " +
               std::to_string(program.num_vars) + " variables");

  for (const LmiBlock& blk : program.blocks)
    r.dual_blocks.push_back(Eigen::MatrixXd::Zero(blk.size, blk.diagonal ? 1 : blk.size));
  while (lines.next(line)) {
    if (blank(line)) continue;
    const std::vector<std::string_view> t = tokens(line);
    long mat = 0, blk = 0, i = 0, j = 0;
    double v = 0;
    if (t.size() != 5 || !parse_long(t[0], mat) || !parse_long(t[1], blk) || !parse_long(t[2], i) ||
        !parse_long(t[3], j) || !parse_double(t[4], v))
      lines.fail("expected 'matrix block i j value'");
    if (mat != 1 && mat != 2) lines.fail("matrix number " + std::to_string(mat) + " is neither 1 (Z) nor 2 (X)");
    if (blk < 1 || blk > static_cast<long>(program.blocks.size()))
      lines.fail("block " + std::to_string(blk) + " out of range [1, " + std::to_string(program.blocks.size()) + "]");
    const LmiBlock& b = program.blocks[static_cast<std::size_t>(blk - 1)];
    if (i < 1 || j < 1 || i > b.size || j > b.size || (b.diagonal && i != j))
      lines.fail("entry (" + std::to_string(i) + ", " + std::to_string(j) + ") does not fit block " +
                 std::to_string(blk) + (b.diagonal ? " (diagonal)" : "") + " of size " + std::to_string(b.size));
    if (mat != 2) continue;  // Z = F(x): we recompute it from x when needed
    Eigen::MatrixXd& Y = r.dual_blocks[static_cast<std::size_t>(blk - 1)];  // CSDP's X = our Y
    if (b.diagonal) {
      Y(i - 1, 0) = v;
    } else {
      Y(i - 1, j - 1) = v;
      Y(j - 1, i - 1) = v;
    }
  }
  r.objective = program.objective(r.x);
  r.dual_objective = dual_value(program, r.dual_blocks);
  return r;
}

SolveResult read_sdpa_result(const std::string& path, const LmiProgram& program, const SolverOptions& options) {
  return parse_sdpa_result(read_text_file(path), path, program, options);
}

SolveResult parse_sdpa_result(const std::string& text, const std::string& path, const LmiProgram& program,
                              const SolverOptions& options) {
  program.validate();
  std::istringstream in(text);
  Lines lines(in, path);
  SolveResult r;
  r.backend = "sdpa (command)";
  std::string phase;
  double primal = std::numeric_limits<double>::quiet_NaN(), dual = primal;
  bool have_x = false;

  auto value_after_equals = [&](const std::string& l) {
    const std::size_t eq = l.find('=');
    const std::vector<std::string_view> t = tokens(std::string_view(l).substr(eq + 1));
    if (t.empty()) lines.fail("no value after '='");
    return std::string(t[0]);
  };
  auto starts_with_key = [](const std::string& l, std::string_view key) {
    const std::size_t first = l.find_first_not_of(" \t");
    return first != std::string::npos && l.compare(first, key.size(), key) == 0 &&
           l.find('=', first + key.size()) != std::string::npos;
  };

  std::string line;
  while (lines.next(line)) {
    if (starts_with_key(line, "phase.value")) {
      phase = value_after_equals(line);
    } else if (starts_with_key(line, "Iteration")) {
      long it = 0;
      if (!parse_long(value_after_equals(line), it)) lines.fail("Iteration is not an integer");
      r.iterations = static_cast<int>(it);
    } else if (starts_with_key(line, "objValPrimal")) {
      if (!parse_double(value_after_equals(line), primal)) lines.fail("objValPrimal is not a finite number");
    } else if (starts_with_key(line, "objValDual")) {
      if (!parse_double(value_after_equals(line), dual)) lines.fail("objValDual is not a finite number");
    } else if (starts_with_key(line, "xVec") && !have_x) {
      r.x = sdpa_x_vector(lines, line);
      have_x = true;
    }
  }
  if (phase.empty()) lines.fail("no 'phase.value =' line: not an SDPA result file");
  if (!have_x) lines.fail("no 'xVec =' in the file");
  if (r.x.size() != static_cast<std::size_t>(program.num_vars))
    lines.fail("xVec has " + std::to_string(r.x.size()) + " entries, the program has " +
               std::to_string(program.num_vars) + " variables");
  const double gap = std::fabs(primal - dual) / (1.0 + std::fabs(primal) + std::fabs(dual));
  r.status = sdpa_status(phase, std::isfinite(gap) ? gap : std::numeric_limits<double>::infinity(),
                         r.iterations >= options.max_iterations, options.gap_tol, &r.message);
  r.objective = program.objective(r.x);
  r.dual_objective = dual;  // ⟨F_0, Y⟩ = −⟨F0, Y⟩
  return r;
}

}  // namespace lpvid
