#include "cli/records_report.h"

#include <cstdio>
#include <sstream>

namespace lpvid::cli {

nlohmann::ordered_json records_json(const std::vector<DataReference>& refs, const RecordTable& t) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (size_t k = 0; k < refs.size() && k < t.records.size(); ++k) {
    const DataReference& ref = refs[k];
    const RecordFigures& f = t.records[k];
    nlohmann::ordered_json j;
    j["file"] = ref.file;
    j["rows"] = ref.row_end >= 0 ? nlohmann::ordered_json::array({ref.row_begin, ref.row_end}) : nlohmann::ordered_json(nullptr);
    j["sha256"] = ref.sha256;
    j["samples"] = f.samples;
    j["rms_residual"] = f.rms_residual;
    j["fit_percent"] = f.fit_percent;
    if (f.rms_noise) j["rms_noise"] = *f.rms_noise;
    if (f.dmax_share) j["dmax_share"] = *f.dmax_share;
    list.push_back(j);
  }
  return list;
}

std::string records_text(const std::vector<DataReference>& refs, const RecordTable& t) {
  std::ostringstream o;
  const bool noise = t.pooled.rms_noise.has_value();
  o << "  records     samples  rms(r)       fit %" << (noise ? "    rms(d)       share of ||d||^2" : "") << "\n";
  const auto line = [&](const std::string& name, const RecordFigures& f) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "  %-10s %8ld  %-11.6g %7.2f", name.c_str(), f.samples, f.rms_residual, f.fit_percent);
    o << buf;
    if (noise) {
      std::snprintf(buf, sizeof buf, "    %-11.6g  %.4f", f.rms_noise.value_or(0.0), f.dmax_share.value_or(0.0));
      o << buf;
    }
    o << "\n";
  };
  for (size_t k = 0; k < t.records.size(); ++k) line(std::to_string(k + 1), t.records[k]);
  line("pooled", t.pooled);
  for (size_t k = 0; k < refs.size(); ++k)
    o << "              " << k + 1 << ": " << refs[k].file
      << (refs[k].row_end >= 0 ? " rows " + std::to_string(refs[k].row_begin) + ":" + std::to_string(refs[k].row_end) : "")
      << "\n";
  return o.str();
}

std::string add_record_figures(nlohmann::ordered_json& report, const std::vector<DataReference>& refs,
                               const LpvModel<double>& model, const Experiment<double>& exp, const CertifiedBounds& b) {
  if (refs.size() < 2) return "";
  const RecordTable t = record_figures(model, exp, b);
  report["records"] = records_json(refs, t);
  nlohmann::ordered_json pooled;
  pooled["samples"] = t.pooled.samples;
  pooled["rms_residual"] = t.pooled.rms_residual;
  pooled["fit_percent"] = t.pooled.fit_percent;
  if (t.pooled.rms_noise) pooled["rms_noise"] = *t.pooled.rms_noise;
  report["records_pooled"] = pooled;
  return records_text(refs, t);
}

}  // namespace lpvid::cli
