#include "solvers/external_solvers.h"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <sys/wait.h>

#include "core/input_error.h"
#include "solvers/sdpa_file.h"
#include "solvers/sdpa_sidecar.h"
#include "solvers/solver_factory.h"

namespace lpvid {

RecordingSolver::RecordingSolver(std::unique_ptr<SdpSolver> inner, std::string path)
    : inner_(std::move(inner)), path_(std::move(path)) {}

SolveResult RecordingSolver::solve(const LmiProgram& program, const SolverOptions& options) {
  ++count_;
  std::string numbered = path_;
  const size_t dot = numbered.rfind(".dat-s");
  numbered = (dot == std::string::npos ? numbered : numbered.substr(0, dot)) + "." + std::to_string(count_) + ".dat-s";
  write_sdpa_with_sidecar(program, numbered);
  write_sdpa_with_sidecar(program, path_);
  return inner_->solve(program, options);
}

namespace {

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

SolveResult CsdpCommandSolver::solve(const LmiProgram& program, const SolverOptions& options) {
  namespace fs = std::filesystem;
  const auto start = std::chrono::steady_clock::now();
  std::random_device rd;
  const fs::path dir = fs::temp_directory_path() / ("lpvid-csdp-" + std::to_string(rd()));
  fs::create_directories(dir);
  const std::string in = (dir / "program.dat-s").string(), sol = (dir / "program.sol").string();
  const LmiProgram compressed = program.compressed();
  write_sdpa_file(compressed, in);
  // Run in the temp dir so that a stray param.csdp elsewhere cannot change it.
  const std::string cmd = "cd " + shell_quote(dir.string()) + " && " + command_ + " program.dat-s program.sol" +
                          (options.verbose ? "" : " > /dev/null 2>&1");
  const int raw = std::system(cmd.c_str());
  SolveResult r;
  if (raw == -1 || !WIFEXITED(raw) || WEXITSTATUS(raw) == 127 || !fs::exists(sol)) {
    r.status = SolveStatus::kBackendError;
    r.backend = name();
    r.message = "could not run '" + command_ + "' (is the coinor-csdp package installed?)";
  } else {
    r = read_csdp_solution(sol, compressed, WEXITSTATUS(raw));
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::unique_ptr<SdpSolver> make_solver_for_cli(const std::string& name, const std::string& write_sdpa) {
  std::unique_ptr<SdpSolver> s =
      name == "csdp-command" ? std::unique_ptr<SdpSolver>(new CsdpCommandSolver()) : make_solver(name);
  if (!write_sdpa.empty()) s = std::make_unique<RecordingSolver>(std::move(s), write_sdpa);
  return s;
}

}  // namespace lpvid
