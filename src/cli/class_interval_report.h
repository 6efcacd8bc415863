#pragma once
/// identify's class interval (identify/class_interval.h): its options, its
/// certificate file ("<stem>.class.json" beside the identified model's
/// certificate), its lines and its JSON.

#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "identify/class_interval.h"

namespace lpvid::cli {

struct ClassIntervalArgs {
  bool skip = false;                                  ///< --no-class-bound
  double box = ClassBoundOptions{}.box_fraction;      ///< --class-box
  int leaves = ClassBoundOptions{}.max_leaves;        ///< --class-leaves
  int stall = ClassBoundOptions{}.stall_splits;       ///< --class-stall
};
void add_class_interval_options(CLI::App* cmd, ClassIntervalArgs& a);

/// Where the class certificate of `certificate_path` goes (a.cert.json → a.cert.class.json).
std::string class_certificate_path(const std::string& certificate_path);

/// Writes the certificate (when certified and `certificate_path` is not ""), prints
/// the interval and returns the report's "class_interval" object.
nlohmann::ordered_json report_class_interval(const ClassInterval& ci, const CertifiedBounds& upper,
                                             const std::string& certificate_path);

}  // namespace lpvid::cli
