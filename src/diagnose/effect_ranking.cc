#include "diagnose/effect_ranking.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/simulate.h"

namespace lpvid {

namespace {

using ojson = nlohmann::ordered_json;

ojson matrix_json(const Mat<double>& m) {
  ojson rows = ojson::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    ojson row = ojson::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(m(i, j));
    rows.push_back(std::move(row));
  }
  return rows;
}

/// The C and D terms of `fitted` whose basis `previous` does not have.
void new_terms_json(const ParamMatrix<double>& fitted, const ParamMatrix<double>& previous, const char* key,
                    const std::vector<std::string>& names, ojson& out) {
  for (const auto& t : fitted.terms) {
    bool old = false;
    for (const auto& p : previous.terms) {
      Monomial padded = p.basis;
      padded.powers.resize(t.basis.powers.size(), 0);
      old = old || padded == t.basis;
    }
    if (old) continue;
    out["basis"] = t.basis.text(names);
    out[key] = matrix_json(t.value);
  }
}

/// The best estimation fit over the starts with the given slots (`extra`
/// also tried as a start); FitResult::finite false if none stayed finite.
FitResult best_fit(const std::vector<LpvModel<double>>& starts, const LpvModel<double>* extra,
                   const std::vector<ParameterSlot>& slots, bool joint, const Experiment<double>& est,
                   const FitOptions& fit) {
  FitResult best;
  best.finite = false;
  best.rms = std::numeric_limits<double>::infinity();
  const auto consider = [&](const LpvModel<double>& start) {
    const FitResult f = fit_slots(start, joint ? with_dynamics_slots(slots, start) : slots, est, fit);
    if (f.finite && f.rms < best.rms) best = f;
  };
  for (const LpvModel<double>& start : starts) consider(start);
  if (extra) consider(*extra);
  return best;
}

/// A candidate at its best fit: the effect with the dynamics kept, and (with
/// joint_dynamics) with A, B re-fitted jointly from every start and from the
/// first fit; of the two, the one with the lower selection RMS is kept (the
/// joint fit has more freedom and can fit the noise: issue 9 item 2).
ScoredCandidate fit_candidate(const EffectCandidate& c, const Experiment<double>& est, const Experiment<double>& val,
                              const RankingOptions& o, const LpvModel<double>& previous) {
  ScoredCandidate s;
  s.kind = c.kind;
  s.label = c.label;
  s.effect_parameters = c.effect_parameters;
  FitResult f = best_fit(c.starts, nullptr, c.slots, false, est, o.fit);
  double val_rms = f.finite ? validation_rms(f.model, val, o.init_samples) : std::numeric_limits<double>::infinity();
  if (o.joint_dynamics) {
    const FitResult g = best_fit(c.starts, f.finite ? &f.model : nullptr, c.slots, true, est, o.fit);
    const double g_val = g.finite ? validation_rms(g.model, val, o.init_samples) : std::numeric_limits<double>::infinity();
    if (g_val < val_rms || !f.finite) {
      f = g;
      val_rms = g_val;
    }
  }
  if (!f.finite) {
    s.rms_estimation = s.rms_validation = s.score = std::numeric_limits<double>::infinity();
    s.model = c.starts.front();
    return s;
  }
  s.model = f.model;
  s.rms_estimation = f.rms;
  s.rms_validation = val_rms;
  const double nval = static_cast<double>(val.n() * val.ny());
  s.score = s.rms_validation * s.rms_validation * (1.0 + 2.0 * s.effect_parameters / nval);
  s.parameters = effect_parameters(c.kind, c.label, s.model, previous);
  return s;
}

}  // namespace

FitResult fit_declared(const LpvModel<double>& declared, const Experiment<double>& est, const FitOptions& fit) {
  const LpvModel<double> m = explicit_model(declared);
  std::vector<ParameterSlot> slots;
  for (const ParameterSlot& s : output_map_slots(m)) {
    const auto& terms = s.where == ParameterSlot::Where::kC ? m.C.terms : m.D.terms;
    const Monomial& f = terms[static_cast<size_t>(s.term)].basis;
    if (std::find(declared.correction.basis.begin(), declared.correction.basis.end(), f) !=
        declared.correction.basis.end())
      slots.push_back(s);
  }
  if (declared.offset.values.empty())
    for (const ParameterSlot& s : offset_slots(m)) slots.push_back(s);
  for (const ParameterSlot& s : x0_slots(m)) slots.push_back(s);
  return fit_slots(m, slots, est, fit);
}

RankingResult rank_effects(const LpvModel<double>& declared, const Experiment<double>& est,
                           const Experiment<double>& val, const RankingOptions& o) {
  RankingResult res;
  const FitResult before = fit_declared(declared, est, o.fit);
  res.before = before.model;
  res.before_estimation = before.rms;
  res.before_validation = validation_rms(before.model, val, o.init_samples);
  LpvModel<double> current = before.model;
  double current_est = before.rms, current_val = res.before_validation;
  for (int round = 0; round < o.max_effects; ++round) {
    RankingRound r;
    r.current = current;
    r.current_validation = current_val;
    const FitResult refit = fit_slots(current, refit_slots(current), est, o.fit);
    r.refit_validation = refit.finite ? validation_rms(refit.model, val, o.init_samples)
                                      : std::numeric_limits<double>::infinity();
    if (o.joint_dynamics) {  // the no-effect reference gets the same freedom as the candidates
      const FitResult joint = fit_slots(current, with_dynamics_slots(refit_slots(current), current), est, o.fit);
      if (joint.finite) r.refit_validation = std::min(r.refit_validation, validation_rms(joint.model, val, o.init_samples));
    }
    r.reference_validation = std::min(current_val, r.refit_validation);
    for (const EffectCandidate& c : candidate_effects(current, est, o.candidates))
      r.ranked.push_back(fit_candidate(c, est, val, o, current));
    for (ScoredCandidate& s : r.ranked)
      s.explained = std::isfinite(s.rms_validation)
                        ? 1.0 - (s.rms_validation * s.rms_validation) / (r.reference_validation * r.reference_validation)
                        : -std::numeric_limits<double>::infinity();
    std::stable_sort(r.ranked.begin(), r.ranked.end(),
                     [](const ScoredCandidate& a, const ScoredCandidate& b) { return a.score < b.score; });
    if (!r.ranked.empty() && r.ranked.front().rms_validation <= (1.0 - o.min_gain) * r.reference_validation) {
      r.chosen = 0;
      current = r.ranked.front().model;
      current_est = r.ranked.front().rms_estimation;
      current_val = r.ranked.front().rms_validation;
      res.chosen.push_back(r.ranked.front());
    }
    const bool stop = r.chosen < 0;
    res.rounds.push_back(std::move(r));
    if (stop) break;
  }
  res.after = current;
  res.after_estimation = current_est;
  res.after_validation = current_val;
  return res;
}

ojson effect_parameters(const std::string& kind, const std::string& label, const LpvModel<double>& fitted,
                        const LpvModel<double>& previous) {
  ojson j = ojson::object();
  if (kind == "basis_term") {
    new_terms_json(fitted.C, previous.C, "C", fitted.scheduling, j);
    new_terms_json(fitted.D, previous.D, "D", fitted.scheduling, j);
    new_terms_json(fitted.B, previous.B, "B", fitted.scheduling, j);
    new_terms_json(fitted.A, previous.A, "A", fitted.scheduling, j);
    j["enters"] = j.contains("A")   ? "A (the state equation: x+ = (A + f(rho) A_f) x + B u, rho the model's own state)"
                  : j.contains("B") ? "B (the state equation: x+ = A x + (B + f(rho) B_f) u)"
                                    : "C, D (output correction S_C, eq. 10)";
    if (fitted.scheduling.size() > previous.scheduling.size()) {
      ojson s = ojson::object();
      for (size_t i = previous.scheduling.size(); i < fitted.scheduling.size(); ++i)
        s[fitted.scheduling[i]] = fitted.columns.rho[i];
      j["new_scheduling"] = std::move(s);
    }
  } else if (kind == "output_offset" || kind == "abs_value") {
    ojson phi = ojson::array();
    for (const auto& v : fitted.offset.values) phi.push_back(matrix_json(v.transpose()).front());
    j["phi"] = std::move(phi);
    ojson basis = ojson::array();
    for (const Monomial& h : fitted.offset.basis) basis.push_back(h.text(fitted.scheduling));
    j["basis"] = std::move(basis);
  }
  const auto map_json = [&](const StaticMap<double>& g) {
    ojson m = ojson::object();
    m["map"] = to_string(g.kind);
    if (g.kind == StaticKind::kSaturation || g.kind == StaticKind::kDeadZone) {
      m["lower"] = g.lower;
      m["upper"] = g.upper;
    }
    if (g.kind == StaticKind::kPolynomial) m["coefficients"] = g.coefficients;
    if (g.kind == StaticKind::kPiecewiseLinear) {
      m["knots"] = g.knots;
      m["values"] = g.coefficients;
    }
    return m;
  };
  if (kind == "input_saturation" || kind == "dead_zone" || kind == "input_polynomial")
    j["input_map"] = map_json(fitted.statics.input);
  if (kind == "output_saturation" || kind == "abs_value" || kind == "output_polynomial" ||
      kind == "output_piecewise_linear")
    j["output_map"] = map_json(fitted.statics.output);
  if (kind == "input_delay") j["delay_samples"] = fitted.statics.input_delay;
  j["label"] = label;
  return j;
}

}  // namespace lpvid
