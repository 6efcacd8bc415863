#include "diagnose/order_variants.h"

#include <algorithm>
#include <string>

#include "fit/model_parameters.h"
#include "model/state_scheduling.h"

namespace lpvid {

namespace {

Mat<double> pad(const Mat<double>& m, Eigen::Index rows, Eigen::Index cols) {
  Mat<double> out = Mat<double>::Zero(rows, cols);
  out.topLeftCorner(m.rows(), m.cols()) = m;
  return out;
}

void pad_terms(ParamMatrix<double>& pm, Eigen::Index rows, Eigen::Index cols) {
  for (auto& t : pm.terms) t.value = pad(t.value, rows, cols);
  pm.rows = rows;
  pm.cols = cols;
}

bool is_output_map_kind(const std::string& kind) {
  return kind == "abs_value" || kind == "output_polynomial" || kind == "output_saturation" ||
         kind == "output_piecewise_linear";
}

}  // namespace

std::optional<LpvModel<double>> raise_order(const LpvModel<double>& m) {
  const Eigen::Index n = m.nx;
  if (n < 1) return std::nullopt;
  int constant_terms = 0;
  for (const auto& t : m.A.terms)
    if (t.basis.is_constant()) {
      if (!observer_shaped(t.value, 1)) return std::nullopt;  // order 1: any 1×1
      ++constant_terms;
    }
  if (constant_terms != 1) return std::nullopt;
  if (!state_scheduled(m.columns.rho, m.nx).empty()) return std::nullopt;
  for (const auto* list : {&m.correction.A, &m.correction.B})
    for (const Mat<double>& x : *list)
      if (x.size() != 0 && !x.isZero(0)) return std::nullopt;
  if (m.uncertainty.structure == UncertaintyStructure::kGeneral) return std::nullopt;

  LpvModel<double> r = m;
  r.nx = static_cast<int>(n + 1);
  pad_terms(r.A, n + 1, n + 1);
  for (auto& t : r.A.terms)
    if (t.basis.is_constant()) t.value(n - 1, n) = 1.0;  // the superdiagonal's new one; a_{n+1} = 0
  pad_terms(r.B, n + 1, m.nu);
  pad_terms(r.C, m.ny, n + 1);
  for (auto& a : r.correction.A) a = Mat<double>::Zero(n + 1, n + 1);
  for (auto& b : r.correction.B) b = Mat<double>::Zero(n + 1, m.nu);
  for (auto& e : r.state_offset.values) {  // E(ρ) gets a zero entry for the new state
    Vec<double> padded = Vec<double>::Zero(n + 1);
    padded.head(e.size()) = e;
    e = padded;
  }
  const auto padded_state = [n](const Vec<double>& x) {
    Vec<double> out = Vec<double>::Zero(n + 1);
    if (x.size() == n) out.head(n) = x;
    return out;
  };
  r.x0 = padded_state(m.x0);
  for (auto& x : r.later_x0) x = padded_state(x);
  return r;
}

std::vector<EffectCandidate> raised_order_candidates(const LpvModel<double>& current, const Experiment<double>& est,
                                                     const CandidateOptions& options) {
  const std::optional<LpvModel<double>> raised = raise_order(current);
  if (!raised) return {};
  std::vector<EffectCandidate> out;
  const std::string suffix = ", linear part of order " + std::to_string(raised->nx) + " (was " +
                             std::to_string(current.nx) + ")";
  for (EffectCandidate& c : candidate_effects(*raised, est, options)) {
    if (!is_output_map_kind(c.kind)) continue;
    c.label += suffix;
    c.effect_parameters += 1 + raised->nu;  // the new denominator coefficient and B row
    c.slots = with_dynamics_slots(c.slots, c.starts.front());  // the new pole must move
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace lpvid
