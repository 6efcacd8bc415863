#include "cli/class_interval_report.h"

#include <iostream>
#include <sstream>

#include "certify/certificate_files.h"
#include "core/decimal_rounding.h"
#include "core/number_text.h"
#include "cli/help_text.h"

namespace lpvid::cli {

void add_class_interval_options(CLI::App* cmd, ClassIntervalArgs& a) {
  cmd->add_flag("--no-class-bound", a.skip,
                "skip the class interval (the certified lower end of Theorem 3.1's optimum over every theta of the "
                "correction basis, or of a box around the found theta when the corrections move z)");
  cmd->add_option("--class-box", a.box,
                  with_default("half-width of the class box: each correction that moves z may move it by this fraction "
                               "of ||z||",
                               a.box))
      ->check(CLI::PositiveNumber);
  cmd->add_option("--class-leaves", a.leaves, with_default("leaves of the class bound's branch and bound", a.leaves))
      ->check(CLI::Range(1, 4095));
  cmd->add_option("--class-stall", a.stall,
                  with_default("stop branching after this many successive splits that did not raise the lowest leaf's "
                               "bound (0: split to --class-leaves)",
                               a.stall))
      ->check(CLI::Range(0, 4095));
}

std::string class_certificate_path(const std::string& certificate_path) {
  const std::string ext = ".json";
  const bool has_ext = certificate_path.size() > ext.size() &&
                       certificate_path.compare(certificate_path.size() - ext.size(), ext.size(), ext) == 0;
  return (has_ext ? certificate_path.substr(0, certificate_path.size() - ext.size()) : certificate_path) + ".class.json";
}

namespace {

nlohmann::ordered_json region_json(const ClassBoundResult& r) {
  nlohmann::ordered_json j;
  j["kind"] = r.whole_class ? "every theta of the correction basis" : "box around the identified theta";
  nlohmann::ordered_json params = nlohmann::ordered_json::array();
  for (size_t i = 0; i < r.names.size(); ++i) {
    const bool free = std::find(r.free.begin(), r.free.end(), static_cast<long>(i)) != r.free.end();
    nlohmann::ordered_json p{{"name", r.names[i]}, {"free", free}};
    if (!free) {
      p["center"] = r.center(static_cast<Eigen::Index>(i));
      p["radius"] = r.radius(static_cast<Eigen::Index>(i));
    }
    params.push_back(p);
  }
  j["parameters"] = params;
  j["leaves"] = r.leaves;
  return j;
}

}  // namespace

nlohmann::ordered_json report_class_interval(const ClassInterval& ci, const CertifiedBounds& upper,
                                             const std::string& certificate_path) {
  const ClassBoundResult& r = ci.bound;
  nlohmann::ordered_json j;
  std::cout << "\nClass interval (Theorem 3.1 over " << (r.whole_class ? "every theta of the correction basis" : "a box around the found theta")
            << ", exact check)\n";
  if (!r.certified()) {
    std::cout << "  no certified class lower end: " << r.reason << "\n";
    j["lower_verified"] = false;
    j["reason"] = r.reason;
    return j;
  }
  // no file unless the user named a certificate ("" from named_certificate_path)
  const std::string path = certificate_path.empty() ? "" : class_certificate_path(certificate_path);
  if (!path.empty()) write_certificate_at(*r.certificate, path);
  std::cout << "  [" << lower_text(r.lower, 6) << ", " << upper_text(upper.upper, 6) << "]  relative gap "
            << ci.relative_gap << "  (" << r.leaves << (r.leaves == 1 ? " leaf" : " leaves") << ", " << r.seconds << " s)\n"
            << "  lower end   " << (path.empty() ? std::string("(no file written)") : path)
            << " checked exactly: no theta of the region reaches a lower objective\n";
  if (!r.whole_class)
    std::cout << "  region      " << r.free.size() << " free parameters, " << r.names.size() - r.free.size()
              << " in a box (see the report's class_interval.region)\n";
  if (ci.adopted) std::cout << "  the class optimum (convex case) was certified with a lower upper end and replaces the found theta\n";
  j["lower_verified"] = true;
  j["lower"] = double_down(r.lower);
  j["upper"] = double_up(upper.upper);
  j["lower_exact"] = exact_decimal_or_fraction(r.lower);
  j["upper_exact"] = exact_decimal_or_fraction(upper.upper);
  j["relative_gap"] = ci.relative_gap;
  j["lower_certificate"] = path.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(path);
  j["region"] = region_json(r);
  j["adopted_class_optimum"] = ci.adopted;
  j["seconds"] = r.seconds;
  return j;
}

}  // namespace lpvid::cli
