#include "cli/certificate_names.h"

#include "certify/certificate_files.h"

namespace lpvid::cli {

std::string diagnose_certificate_path(const std::string& certificate_path, size_t window, size_t windows, bool after) {
  const size_t dot = certificate_path.rfind(".json");
  const std::string stem = dot == std::string::npos ? certificate_path : certificate_path.substr(0, dot);
  const std::string tag = windows == 1 ? "" : ".w" + std::to_string(window + 1);
  return stem + tag + (after ? ".after.json" : ".before.json");
}

void write_window_certificate(WindowBounds& w, const std::string& certificate_path, size_t window, size_t windows, bool after) {
  if (certificate_path.empty()) return;  // the user named no file
  w.certificate = write_certificates(w.bounds, diagnose_certificate_path(certificate_path, window, windows, after)).certificate;
}

void write_diagnose_certificates(DiagnoseResult& result, const std::string& certificate_path) {
  if (certificate_path.empty()) return;  // the user named no file
  for (const bool after : {false, true}) {
    std::vector<WindowBounds>& side = after ? result.after : result.before;
    for (size_t i = 0; i < side.size(); ++i)
      if (side[i].certificate.empty()) write_window_certificate(side[i], certificate_path, i, side.size(), after);
    WindowBounds& thm31 = (after ? result.after_id : result.before_id).bounds;
    const std::string p = diagnose_certificate_path(certificate_path, 0, 1, after);
    thm31.certificate = write_certificates(thm31.bounds, p.substr(0, p.size() - 5) + ".thm31.json").certificate;
  }
}

void write_step_certificates(BasisSelectionResult& result, const std::string& stem) {
  for (BasisStep& s : result.steps) {
    const std::string file = s.same_as >= 0 ? result.steps[static_cast<size_t>(s.same_as)].certificate
                                            : write_certificates(s.bounds, stem + ".step" + std::to_string(s.index) + ".cert.json").certificate;
    s.certificate = s.verdict == BasisVerdict::kConsistent ? file : "";
    if (s.same_as >= 0) {
      s.class_certificate = result.steps[static_cast<size_t>(s.same_as)].class_certificate;
    } else if (s.klass && s.klass->certified()) {
      s.class_certificate = stem + ".step" + std::to_string(s.index) + ".class.json";
      write_certificate_at(*s.klass->certificate, s.class_certificate);
    }
  }
}

void write_tradeoff_certificates(std::vector<TradeoffPoint>& points, const std::string& stem) {
  for (size_t k = 0; k < points.size(); ++k)
    points[k].certificate =
        write_certificates(points[k].bounds, stem + ".lambda" + std::to_string(k + 1) + ".cert.json").certificate;
}

}  // namespace lpvid::cli
