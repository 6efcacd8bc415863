#include "solvers/solver_factory.h"

#include <stdexcept>

#include "solvers/csdp_backend.h"
#include "solvers/sdpa_backend.h"

namespace lpvid {

std::vector<std::string> available_solvers() { return {"csdp", "sdpa"}; }

std::unique_ptr<SdpSolver> make_solver(const std::string& name) {
  if (name == "csdp") return std::make_unique<CsdpSolver>();
  if (name == "sdpa") return std::make_unique<SdpaSolver>();
  std::string known;
  for (const std::string& n : available_solvers()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown SDP solver '" + name + "' (available: " + known + ")");
}

}  // namespace lpvid
