#pragma once
/// SDPA sparse files (".dat-s") for outside solvers (docs/design.md §13.1: "any program
/// can be written as an SDPA file"), and their answers read back.
///
/// The SDPA sparse format, as written here (and read by SDPA, CSDP, SeDuMi's
/// and JuMP's readers):
///
///     "comment lines first, each starting with " or *
///     m                          number of variables
///     nblocks                    number of blocks
///     s_1 s_2 …                  block sizes, negative for a diagonal block
///     c_1 c_2 …                  the cost vector, on one line
///     k b i j v                  entry (i, j) = v of matrix k in block b
///
/// meaning  min cᵀx  s.t.  Σ_k x_k F_k − F_0 ⪰ 0  (SDPA's sign convention:
/// matrix 0 is the NEGATED constant term of our LmiProgram, F_0 = −F0).
/// Indices are 1-based; entries are upper triangle (i ≤ j), one per line,
/// without duplicates, values with 17 significant digits (so a round trip is
/// exact). Block and variable names travel in comment lines
/// "*lpvid-block <b> <name>" and "*lpvid-var <k> <name>", the program's
/// meaning (LmiProgram::about: kind, scalings) in "*lpvid-about <key> <value>";
/// other readers skip them. A variable that appears in no block is written as its cost alone;
/// CSDP and SDPA refuse such files (they need every F_k nonempty).
///
/// Every reading error is an InputError "file:line: reason".

#include <iosfwd>
#include <string>
#include <vector>

#include "solvers/lmi_program.h"
#include "solvers/sdp_solver.h"

namespace lpvid {

/// Writes `program` (validated, then in compressed form) to `out`.
/// Throws std::invalid_argument for an invalid program or a name containing a
/// line break.
void write_sdpa(const LmiProgram& program, std::ostream& out);
/// The same to a file; throws InputError if it cannot be written.
void write_sdpa_file(const LmiProgram& program, const std::string& path);

/// Reads an SDPA sparse file. Accepts what write_sdpa writes and the usual
/// variations: "{", "}", "(", ")" and "," as separators in the header, text
/// after the numbers on the m / nblocks lines ("2 = mDIM"), header numbers
/// spread over several lines, entries with i > j (taken as (j, i)),
/// duplicate entries (summed), blank lines. Returns a compressed program, so
/// read(write(p)) == p.compressed(). `name` is the file name for messages.
LmiProgram read_sdpa(std::istream& in, const std::string& name);
/// The same from a file.
LmiProgram read_sdpa_file(const std::string& path);

/// Reads the solution file written by the `csdp` command
/// (`csdp prob.dat-s prob.sol`): line 1 is CSDP's y, which is our x; lines
/// "1 b i j v" hold CSDP's Z = F(x) and lines "2 b i j v" CSDP's X, which is
/// our dual Y. `exit_code` is csdp's exit status (its sdp() return code) and
/// gives the status (csdp_status). Fills x, objective (cᵀx), dual_objective
/// (−⟨F0, Y⟩), dual_blocks (always), backend "csdp (command)", message.
/// Throws InputError naming file:line if the file does not fit `program`.
SolveResult read_csdp_solution(const std::string& path, const LmiProgram& program, int exit_code);
/// The same on the file's text (`name` for messages).
SolveResult parse_csdp_solution(const std::string& text, const std::string& name, const LmiProgram& program, int exit_code);

/// Reads the result file written by the `sdpa` command
/// (`sdpa prob.dat-s prob.out`): "phase.value = …", "Iteration = …",
/// "objValPrimal = …", "objValDual = …" and "xVec =" followed by
/// "{x_1,x_2,…}". The status is sdpa_status() of the phase with the gap and
/// iteration limit from `options` (SDPA prints xVec with "%+8.3e" unless its
/// param.sdpa asks for more digits: write "%+.17e" there). Fills x,
/// objective (cᵀx), dual_objective (objValDual), iterations, backend
/// "sdpa (command)", message. No dual_blocks.
SolveResult read_sdpa_result(const std::string& path, const LmiProgram& program, const SolverOptions& options);
/// The same on the file's text (`name` for messages).
SolveResult parse_sdpa_result(const std::string& text, const std::string& name, const LmiProgram& program,
                              const SolverOptions& options);

}  // namespace lpvid
