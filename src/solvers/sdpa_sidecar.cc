#include "solvers/sdpa_sidecar.h"

#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/file_io.h"
#include "solvers/sdpa_file.h"

namespace lpvid {

std::string sdpa_sidecar_path(const std::string& sdpa_path) { return sdpa_path + ".json"; }

std::string sdpa_sidecar_text(const LmiProgram& program, const std::string& sdpa_path) {
  const LmiProgram p = program.compressed();  // the numbering of the written file
  nlohmann::ordered_json j;
  j["format"] = "lpvid-sdpa-sidecar/1";
  j["sdpa_file"] = std::filesystem::path(sdpa_path).filename().string();
  j["convention"] =
      "SDPA sparse: minimise c'x subject to sum_k x_k F_k - F_0 >= 0 for every block; lpvid's program is "
      "F0 + sum_k x_k F_k >= 0, so the file's matrix 0 is minus lpvid's F0. Variable and block indices are 1-based.";
  nlohmann::ordered_json about = nlohmann::ordered_json::object();
  for (const auto& [key, value] : p.about) about[key] = value;
  j["about"] = about;
  nlohmann::ordered_json vars = nlohmann::ordered_json::array();
  for (int k = 0; k < p.num_vars; ++k)
    vars.push_back({{"index", k + 1}, {"name", p.var_name(k)}, {"cost", p.cost[static_cast<std::size_t>(k)]}});
  j["variables"] = vars;
  nlohmann::ordered_json blocks = nlohmann::ordered_json::array();
  for (std::size_t b = 0; b < p.blocks.size(); ++b)
    blocks.push_back({{"index", b + 1},
                      {"name", p.blocks[b].name},
                      {"size", p.blocks[b].size},
                      {"diagonal", p.blocks[b].diagonal}});
  j["blocks"] = blocks;
  return j.dump(2) + "\n";
}

void write_sdpa_with_sidecar(const LmiProgram& program, const std::string& sdpa_path) {
  write_sdpa_file(program, sdpa_path);
  write_text_file(sdpa_sidecar_path(sdpa_path), sdpa_sidecar_text(program, sdpa_path), "SDPA sidecar");
}

}  // namespace lpvid
