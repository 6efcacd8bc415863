#pragma once
/// The SDP back ends by name: the one place that knows every backend
/// (solvers/csdp_backend.h, solvers/sdpa_backend.h), above their common
/// interface solvers/sdp_solver.h.

#include <memory>
#include <string>
#include <vector>

#include "solvers/sdp_solver.h"

namespace lpvid {

/// The names make_solver accepts: {"csdp", "sdpa"}.
std::vector<std::string> available_solvers();

/// A new backend by name. Throws std::invalid_argument for an unknown name,
/// listing the available ones.
std::unique_ptr<SdpSolver> make_solver(const std::string& name);

}  // namespace lpvid
