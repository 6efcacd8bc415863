#pragma once
/// The "class" object of a class claim (certificate_file.h,
/// docs/class_lower_bound.md): the unknowns, the parameters' names, the free
/// ones, the box of the others and the preorder tree of dual points.

#include <string>

#include <nlohmann/json.hpp>

#include "json/json_tree.h"
#include "verify/certificate/certificate.h"

namespace lpvid {

/// Most nodes a class tree may have, and its deepest split chain (each
/// leaf is an exact check of its own: the cost is bounded before any is read).
inline constexpr long kMaxClassNodes = 4095;
inline constexpr long kMaxClassDepth = 60;

/// Reads and checks the structure (sizes, indices, a complete tree). Throws
/// InputError "file:line: class.path: reason".
ClassRegion parse_class_region(const JsonNode& node, const std::string& file, Eigen::Index ny, Eigen::Index nz,
                               CertificateForm form);

nlohmann::ordered_json class_region_json(const ClassRegion& region, CertificateForm form);

}  // namespace lpvid
