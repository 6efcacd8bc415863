#include "cli/diagnose_output.h"

#include <cmath>
#include <cstdio>
#include <iostream>

#include "cli/report.h"
#include "model/simulate.h"

namespace lpvid::cli {
namespace {

using ojson = nlohmann::ordered_json;

std::string num(double x, int digits = 4) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

ojson finite_or_null(double x) { return std::isfinite(x) ? ojson(x) : ojson(nullptr); }

ojson side_json(double rms_est, double rms_val, const WindowBounds& w) {
  ojson j = ojson::object();
  j["rms_estimation"] = finite_or_null(rms_est);
  j["rms_validation"] = finite_or_null(rms_val);
  const CertifiedBounds& b = w.bounds;
  j["delta"] = b.verified ? ojson(b.delta) : ojson(nullptr);
  j["dmax"] = b.verified ? ojson(b.dmax) : ojson(nullptr);
  j["verified"] = b.verified;
  if (!b.verified) j["reason"] = b.reason;
  j["certificate"] = w.certificate;
  j["window"] = {{"estimation_rows", {w.begin, w.end}},
                 {"file_rows", {w.file_begin, w.file_end}},
                 {"meaning", "Theorem 2.1 on exactly these rows: the model (numbers rounded to 12 digits, initial "
                             "state = the fitted model's own state at the first row) explains them with ||Delta|| <= "
                             "delta and noise RMS <= dmax"}};
  return j;
}

ojson candidate_json(const ScoredCandidate& c) {
  return {{"kind", c.kind},
          {"label", c.label},
          {"effect_parameters", c.effect_parameters},
          {"rms_estimation", finite_or_null(c.rms_estimation)},
          {"rms_validation", finite_or_null(c.rms_validation)},
          {"explained_validation", finite_or_null(c.explained)},
          {"score", finite_or_null(c.score)},
          {"parameters", c.parameters}};
}

std::string bound_line(const WindowBounds& w) {
  const CertifiedBounds& b = w.bounds;
  if (!b.verified) return "not verified (" + b.reason + ")";
  return "delta <= " + num(b.delta) + ", dmax <= " + num(b.dmax) + " (verified, file rows " +
         std::to_string(w.file_begin) + ":" + std::to_string(w.file_end) + ")";
}

}  // namespace

void print_and_write_diagnose_report(const DiagnoseReportInputs& in, const std::string& report_path) {
  const RankingResult& r = *in.rank;
  std::cout << "lpvid diagnose\n"
            << "  estimation  " << in.command_line_data << " (" << in.est->n() << " samples)\n"
            << "  validation  " << in.validation << " (" << in.val->n() << " samples; x0 fitted on the first "
            << in.init_samples << ", then free-run simulation)\n";
  ojson rounds = ojson::array();
  for (size_t i = 0; i < r.rounds.size(); ++i) {
    const RankingRound& rr = r.rounds[i];
    std::cout << "\nround " << i + 1 << ": validation RMS of the current model " << num(rr.current_validation)
              << ", re-fitted without a new effect " << num(rr.refit_validation) << "\n"
              << "  rank  kind               val RMS    explained  est RMS    params  candidate\n";
    ojson cands = ojson::array();
    for (size_t k = 0; k < rr.ranked.size(); ++k) {
      const ScoredCandidate& c = rr.ranked[k];
      char line[256];
      std::snprintf(line, sizeof line, "  %-4zu  %-17s  %-9s  %-9s  %-9s  %-6d  %s%s\n", k + 1, c.kind.c_str(),
                    num(c.rms_validation).c_str(), (num(100 * c.explained, 3) + "%").c_str(),
                    num(c.rms_estimation).c_str(), c.effect_parameters, c.label.c_str(),
                    static_cast<int>(k) == rr.chosen ? "   <- chosen" : "");
      std::cout << line;
      cands.push_back(candidate_json(c));
    }
    if (rr.chosen < 0)
      std::cout << "  -> none: no candidate lowers the validation RMS by the required share below "
                << num(rr.reference_validation) << "\n";
    rounds.push_back({{"reference_validation", rr.reference_validation},
                      {"chosen", rr.chosen >= 0 ? ojson(rr.ranked[static_cast<size_t>(rr.chosen)].kind) : ojson("none")},
                      {"candidates", cands}});
  }
  ojson effects = ojson::array();
  for (const ScoredCandidate& c : r.chosen) effects.push_back(candidate_json(c));
  if (effects.empty())
    effects.push_back({{"kind", "none"},
                       {"label", "no effect explains the residual better than refitting (noise level)"},
                       {"rms_validation", r.before_validation}});

  std::cout << "\neffects added: ";
  if (r.chosen.empty()) std::cout << "none";
  for (size_t i = 0; i < r.chosen.size(); ++i) std::cout << (i ? ", " : "") << r.chosen[i].label;
  std::cout << "\n\n              RMS estimation  RMS validation  bounds\n"
            << "  before      " << num(r.before_estimation) << std::string(16 - std::min<size_t>(15, num(r.before_estimation).size()), ' ')
            << num(r.before_validation) << std::string(16 - std::min<size_t>(15, num(r.before_validation).size()), ' ')
            << bound_line(*in.before) << "\n"
            << "  after       " << num(r.after_estimation) << std::string(16 - std::min<size_t>(15, num(r.after_estimation).size()), ' ')
            << num(r.after_validation) << std::string(16 - std::min<size_t>(15, num(r.after_validation).size()), ' ')
            << bound_line(*in.after) << "\n"
            << "  certificates " << in.before->certificate << ", " << in.after->certificate
            << " (check: lpvid-verify certificate FILE)\n";

  ojson j = ojson::object();
  j["status"] = in.before->bounds.verified && in.after->bounds.verified ? "ok" : "not verified";
  j["command"] = "diagnose";
  j["estimation"] = {{"file", in.command_line_data}, {"samples", in.est->n()}};
  j["validation"] = {{"source", in.validation}, {"samples", in.val->n()}, {"init_samples", in.init_samples}};
  j["effects"] = effects;
  j["before"] = side_json(r.before_estimation, r.before_validation, *in.before);
  j["after"] = side_json(r.after_estimation, r.after_validation, *in.after);
  j["noise_normalisation"] = "RMS: ||d||_2 <= dmax*sqrt(n*ny) (SPEC 4)";
  j["toeplitz_mode"] = "signal";
  j["solver"] = in.solver;
  j["relaxation"] = "none: the parameters are output-error least-squares fits on the whole estimation record; the "
                    "bounds are Theorem 2.1 for the fitted model on the window";
  j["verified"] = in.before->bounds.verified && in.after->bounds.verified;
  j["rounds"] = rounds;
  j["plots"] = ojson::array();
  if (!in.model_out.empty()) j["model"] = in.model_out;
  write_json(report_path, j);
}

}  // namespace lpvid::cli
