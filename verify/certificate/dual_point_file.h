#pragma once
/// The JSON object of one dual point ("dual" of a dual claim, "leaf" of a
/// class claim; certificate_file.h): horizon, σ, g and the form's own fields
/// (Y1 for "dual_delta", the recipe for "dual_delta_path").

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "json/json_tree.h"
#include "verify/certificate/certificate.h"

namespace lpvid {

/// Reads the dual point `node` (JSON path `where`, e.g. "dual"); `extra_keys`
/// are further keys the caller reads itself. Throws InputError naming the file,
/// line and path.
DualPoint parse_dual_point_object(const JsonNode& node, const std::string& file, const std::string& where, Eigen::Index ny,
                                  Eigen::Index nz, CertificateForm form, const std::vector<std::string>& extra_keys = {});

/// The JSON object of a dual point (exact numbers).
nlohmann::ordered_json dual_point_json(const DualPoint& p, CertificateForm form);

}  // namespace lpvid
