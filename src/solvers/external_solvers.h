#pragma once
/// Solvers outside this process: any LmiProgram can be
/// written as an SDPA sparse file, solved by an outside program, and its
/// answer read back for certification.
///
///  - RecordingSolver wraps a backend and writes each program it is given to
///    an SDPA file (`--write-sdpa F.dat-s`; with several solves, F.dat-s is
///    the last one and F.<k>.dat-s the k-th), each with its sidecar
///    F….dat-s.json (solvers/sdpa_sidecar.h: scalings, variable meanings).
///  - CsdpCommandSolver writes the program, runs the `csdp` command-line
///    program (Debian package coinor-csdp) on it, and reads its solution
///    file back (`--solver csdp-command`). Nothing of CSDP is linked for it.

#include <memory>
#include <string>

#include "solvers/sdp_solver.h"

namespace lpvid {

class RecordingSolver : public SdpSolver {
 public:
  RecordingSolver(std::unique_ptr<SdpSolver> inner, std::string path);
  std::string name() const override { return inner_->name(); }
  SolveResult solve(const LmiProgram& program, const SolverOptions& options) override;

 private:
  std::unique_ptr<SdpSolver> inner_;
  std::string path_;
  int count_ = 0;
};

class CsdpCommandSolver : public SdpSolver {
 public:
  /// `command`: the csdp executable (default "csdp", found on PATH).
  explicit CsdpCommandSolver(std::string command = "csdp") : command_(std::move(command)) {}
  std::string name() const override { return "csdp-command"; }
  SolveResult solve(const LmiProgram& program, const SolverOptions& options) override;

 private:
  std::string command_;
};

/// make_solver plus "csdp-command"; wrapped in a RecordingSolver when
/// `write_sdpa` is non-empty.
std::unique_ptr<SdpSolver> make_solver_for_cli(const std::string& name, const std::string& write_sdpa);

}  // namespace lpvid
