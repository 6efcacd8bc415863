#include "diagnose/effect_ranking.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <mutex>
#include <tuple>

#include "core/parallel_for.h"
#include "data/experiment_builder.h"
#include "diagnose/order_variants.h"
#include "diagnose/residual_analysis.h"
#include "fit/record_states.h"
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

/// Whether `m` has a term with basis f (monomials of fewer scheduling
/// variables padded with zero powers: later rounds append variables).
bool has_basis(const ParamMatrix<double>& m, const Monomial& f) {
  for (const auto& p : m.terms) {
    Monomial a = p.basis, b = f;
    const size_t n = std::max(a.powers.size(), b.powers.size());
    a.powers.resize(n, 0);
    b.powers.resize(n, 0);
    if (a == b) return true;
  }
  return false;
}

/// The terms of `introduced` whose basis `previous` does not have (the
/// effect's own terms), with their values in `fitted` (the same model, or a
/// later one in which they were re-fitted).
void new_terms_json(const ParamMatrix<double>& fitted, const ParamMatrix<double>& introduced,
                    const ParamMatrix<double>& previous, const char* key, const std::vector<std::string>& names,
                    ojson& out) {
  for (const auto& t : fitted.terms) {
    if (has_basis(previous, t.basis) || !has_basis(introduced, t.basis)) continue;
    out["basis"] = t.basis.text(names);
    out[key] = matrix_json(t.value);
  }
}

/// The scheduling variables `introduced` has beyond `previous`, with their
/// columns in `fitted` (name -> column).
ojson new_scheduling_json(const LpvModel<double>& fitted, const LpvModel<double>& introduced,
                          const LpvModel<double>& previous) {
  ojson s = ojson::object();
  for (size_t i = previous.scheduling.size(); i < introduced.scheduling.size() && i < fitted.scheduling.size(); ++i)
    s[fitted.scheduling[i]] = fitted.columns.rho[i];
  return s;
}

/// effect_parameters of a basis_term effect: its new term, where it enters,
/// and the scheduling variables it added.
void basis_term_parameters(const LpvModel<double>& fitted, const LpvModel<double>& introduced,
                           const LpvModel<double>& previous, ojson& j) {
  new_terms_json(fitted.C, introduced.C, previous.C, "C", fitted.scheduling, j);
  new_terms_json(fitted.D, introduced.D, previous.D, "D", fitted.scheduling, j);
  new_terms_json(fitted.B, introduced.B, previous.B, "B", fitted.scheduling, j);
  new_terms_json(fitted.A, introduced.A, previous.A, "A", fitted.scheduling, j);
  j["enters"] = j.contains("A")   ? "A (the state equation: x+ = (A + f(rho) A_f) x + B u, rho the model's own state)"
                : j.contains("B") ? "B (the state equation: x+ = A x + (B + f(rho) B_f) u)"
                                  : "C, D (output correction S_C, eq. 10)";
  if (introduced.scheduling.size() > previous.scheduling.size())
    j["new_scheduling"] = new_scheduling_json(fitted, introduced, previous);
}

/// effect_parameters of an output offset (output_offset, abs_value): the
/// offset's values phi and basis.
void offset_parameters(const LpvModel<double>& fitted, ojson& j) {
  ojson phi = ojson::array();
  for (const auto& v : fitted.offset.values) phi.push_back(matrix_json(v.transpose()).front());
  j["phi"] = std::move(phi);
  ojson basis = ojson::array();
  for (const Monomial& h : fitted.offset.basis) basis.push_back(h.text(fitted.scheduling));
  j["basis"] = std::move(basis);
}

/// A static map's kind and parameters.
ojson static_map_json(const StaticMap<double>& g) {
  ojson m = ojson::object();
  m["map"] = to_string(g.kind);
  if (g.kind == StaticKind::kSaturation || g.kind == StaticKind::kDeadZone) {
    m["lower"] = g.lower;
    m["upper"] = g.upper;
  }
  if (g.kind == StaticKind::kPolynomial) m["coefficients"] = g.coefficients;
  if (!g.range.empty()) m["range"] = g.range;  // linear beyond it (model/static_blocks.h)
  if (g.kind == StaticKind::kPiecewiseLinear) {
    m["knots"] = g.knots;
    m["values"] = g.coefficients;
  }
  return m;
}

/// effect_parameters of a state_nonlinearity effect.
void state_nonlinearity_parameters(const std::string& label, const LpvModel<double>& fitted,
                                   const LpvModel<double>& introduced, const LpvModel<double>& previous, ojson& j) {
  // x+ = A x + B u + E(ρ): the function column(s) and e
  j["new_scheduling"] = new_scheduling_json(fitted, introduced, previous);
  ojson terms = ojson::array();
  for (size_t t = 0; t < introduced.state_offset.basis.size() && t < fitted.state_offset.basis.size() &&
                     t < fitted.state_offset.values.size();
       ++t)
    terms.push_back({{"basis", fitted.state_offset.basis[t].text(fitted.scheduling)},
                     {"e", matrix_json(fitted.state_offset.values[t].transpose()).front()}});
  j["state_offset"] = std::move(terms);
  j["enters"] = "the state equation: x+ = A x + B u + sum_j h_j(rho) e_j (model field state_offset)";
  if (label.rfind("store cascade", 0) == 0) {  // the linear part was replaced: its new matrices too
    for (const auto& [name, pm] : {std::pair<const char*, const ParamMatrix<double>*>{"A", &fitted.A}, {"B", &fitted.B},
                                   {"C", &fitted.C}, {"D", &fitted.D}})
      for (const auto& t : pm->terms)
        if (t.basis.degree() == 0) j[name] = matrix_json(t.value);
  }
}

/// The fit with the lowest RMS among `fits` (finite false if none is finite).
FitResult lowest_rms(const std::vector<FitResult>& fits) {
  FitResult best;
  best.finite = false;
  best.rms = std::numeric_limits<double>::infinity();
  for (const FitResult& f : fits)
    if (f.finite && f.rms < best.rms) best = f;
  return best;
}

/// The estimation fit from each start with the given slots (with `joint`
/// also A, B: with_dynamics_slots).
std::vector<FitResult> fit_each_start(const std::vector<LpvModel<double>>& starts, const std::vector<ParameterSlot>& slots,
                                      bool joint, const Experiment<double>& est, const FitOptions& fit) {
  std::vector<FitResult> out;
  out.reserve(starts.size());
  for (const LpvModel<double>& start : starts)
    out.push_back(fit_slots(start, joint ? with_dynamics_slots(slots, start) : slots, est, fit));
  return out;
}

/// The best estimation fit over the starts with the given slots (`extra`
/// also tried as a start); FitResult::finite false if none stayed finite.
FitResult best_fit(const std::vector<LpvModel<double>>& starts, const LpvModel<double>* extra,
                   const std::vector<ParameterSlot>& slots, bool joint, const Experiment<double>& est,
                   const FitOptions& fit) {
  std::vector<FitResult> fits = fit_each_start(starts, slots, joint, est, fit);
  if (extra) fits.push_back(fit_slots(*extra, joint ? with_dynamics_slots(slots, *extra) : slots, est, fit));
  return lowest_rms(fits);
}

/// A candidate at its best fit: the effect with the dynamics kept, and (with
/// joint_dynamics) with A, B re-fitted jointly from every start and from the
/// first fit; of the two, the one with the lower selection RMS is kept (the
/// joint fit has more freedom and can fit the noise).
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
      s.joint = true;
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


/// The round's candidates: the effect library on the current model, and
/// the output maps on the current model with one more state.
std::vector<EffectCandidate> round_candidates(const LpvModel<double>& current, const Experiment<double>& est,
                                              const RankingOptions& o) {
  std::vector<EffectCandidate> c = candidate_effects(current, est, o.candidates);
  if (o.order_variants)
    for (EffectCandidate& r : raised_order_candidates(current, est, o.candidates)) c.push_back(std::move(r));
  return c;
}

/// The training rows of set t: for fold t (t < K) the longer of the two
/// contiguous stretches of its record beside its block and every other
/// record whole, each a record of its own (fold_plan.h training_pieces);
/// t == K is the whole estimation data.
Experiment<double> training_set(const Experiment<double>& est, const std::vector<FoldBlock>& blocks, size_t t) {
  if (t >= blocks.size()) return est;
  std::vector<Experiment<double>> parts;
  for (const FoldBlock& p : training_pieces(est.record_lengths(), blocks, t)) parts.push_back(select_rows(est, p.first, p.last));
  return parts.size() == 1 ? parts[0] : stack_records(parts);
}

/// Held-out squared error of `m` on block j (fold_plan.h "score").
void score_block(const FitResult& f, const Experiment<double>& est, const std::vector<FoldBlock>& blocks, size_t j,
                 Eigen::Index warmup, FoldFigures& out) {
  const Experiment<double> b = select_rows(est, blocks[j].first, blocks[j].last);
  out.count[j] = (b.n() - warmup) * b.ny();
  out.sse[j] = std::numeric_limits<double>::infinity();
  if (!f.finite) return;
  const FreeRunScore s = warmup_score(f.model, b, warmup);
  if (std::isfinite(s.rms)) out.sse[j] = s.rms * s.rms * static_cast<double>(out.count[j]);
}

FoldFigures empty_figures(size_t k) {
  FoldFigures f;
  f.sse.assign(k, std::numeric_limits<double>::infinity());
  f.count.assign(k, 0);
  return f;
}

/// One family of models (a candidate, the no-effect re-fit, the declared
/// model) fitted on every training set: its fold figures and its fit on the
/// whole record.
struct FoldedFamily {
  FitResult whole;
  FoldFigures figures;
  std::vector<FitResult> per_fold;  ///< the fit on each fold's training rows
  /// A family with a grid of starts (EffectCandidate::starts_for): which
  /// start the whole-record fit comes from (see choose_start_by_folds).
  StartChoice start;
};

/// One family fitted on one training set: the fit with the lowest training
/// RMS, and for a family with a grid of starts the fit from each start (in
/// the grid's order, the same on every training set).
struct FamilyFitOutcome {
  FitResult best;
  std::vector<FitResult> by_start;
};

/// How a family is fitted on one training set: set t < K is fold t's
/// training rows, t == K the whole record.
using FamilyFit = std::function<FamilyFitOutcome(const Experiment<double>& training, size_t t, const FitOptions& fit)>;

/// The held-out SSE of one fit on block j (+inf when not finite).
double block_sse(const FitResult& f, const Experiment<double>& block, Eigen::Index warmup, Eigen::Index count) {
  if (!f.finite) return std::numeric_limits<double>::infinity();
  const FreeRunScore s = warmup_score(f.model, block, warmup);
  return std::isfinite(s.rms) ? s.rms * s.rms * static_cast<double>(count) : std::numeric_limits<double>::infinity();
}

/// Runs every (family, training set) pair as one job (core/parallel_for.h).
std::vector<FoldedFamily> fit_families(const std::vector<FamilyFit>& families, const std::vector<std::string>& labels,
                                       const std::string& stage, const Experiment<double>& est,
                                       const std::vector<FoldBlock>& blocks, const RankingOptions& o) {
  const size_t k = blocks.size(), sets = k + 1, jobs = families.size() * sets;
  std::vector<FoldedFamily> out(families.size());
  std::vector<std::vector<std::vector<double>>> start_sse(families.size(), std::vector<std::vector<double>>(k));
  std::vector<std::vector<FitResult>> whole_by_start(families.size());
  for (FoldedFamily& f : out) {
    f.figures = empty_figures(k);
    f.per_fold.resize(k);
  }
  std::mutex report;
  size_t done = 0;
  parallel_for(jobs, o.threads, [&](size_t job) {
    const size_t i = job / sets, t = job % sets;
    FamilyFitOutcome r = families[i](training_set(est, blocks, t), t, o.fit);
    if (t == k) {
      out[i].whole = r.best;
      whole_by_start[i] = std::move(r.by_start);
    } else {
      score_block(r.best, est, blocks, t, o.fold_warmup, out[i].figures);
      out[i].per_fold[t] = r.best;
      const Experiment<double> block = select_rows(est, blocks[t].first, blocks[t].last);
      for (const FitResult& f : r.by_start)
        start_sse[i][t].push_back(block_sse(f, block, o.fold_warmup, out[i].figures.count[t]));
    }
    if (o.progress) {
      const std::lock_guard<std::mutex> lock(report);
      ++done;
      o.progress("effects, " + stage + ": fit " + std::to_string(done) + " of " + std::to_string(jobs) + " (" + labels[i] + ", " +
                 (t == k ? std::string("all rows") : "without fold " + std::to_string(t + 1)) + ")");
    }
  });
  for (size_t i = 0; i < families.size(); ++i) {
    if (whole_by_start[i].size() < 2) continue;
    out[i].start = choose_start_by_folds(start_sse[i], out[i].figures.count, whole_by_start[i]);
    if (out[i].start.chosen >= 0) out[i].whole = whole_by_start[i][static_cast<size_t>(out[i].start.chosen)];
  }
  return out;
}

/// A candidate fitted on some rows from every start (its starts_for those
/// rows when it has them: then the fit from each start is kept too).
FamilyFitOutcome fit_family_member(const EffectCandidate& c, bool joint, const Experiment<double>& training,
                                   const FitOptions& fit) {
  FamilyFitOutcome out;
  if (c.starts_for) {
    const std::vector<LpvModel<double>> own = c.starts_for(training);
    if (!own.empty()) {
      out.by_start = fit_each_start(own, c.slots, joint, training, fit);
      out.best = lowest_rms(out.by_start);
      return out;
    }
  }
  out.best = best_fit(c.starts, nullptr, c.slots, joint, training, fit);
  return out;
}

/// A candidate's family: on the whole record the candidate built on the
/// current model; on fold t the SAME effect built on the current model as
/// fitted on fold t's training rows (`per_fold[t]`, null when that fold has
/// no such candidate: the fold then counts as lost). So no fold's fit starts
/// from parameters that have seen its held-out block, in any round. In fold
/// mode A, B move with the effect (the joint re-fit) unless the user fixed
/// them (--fixed-dynamics).
FamilyFit candidate_family(const EffectCandidate& whole, const std::vector<const EffectCandidate*>& per_fold,
                           const RankingOptions& o) {
  const EffectCandidate* wp = &whole;
  const bool joint = o.joint_dynamics;
  return [wp, per_fold, joint](const Experiment<double>& training, size_t t, const FitOptions& fit) {
    if (t >= per_fold.size()) return fit_family_member(*wp, joint, training, fit);
    if (per_fold[t] == nullptr) {
      FamilyFitOutcome none;
      none.best.finite = false;
      none.best.rms = std::numeric_limits<double>::infinity();
      return none;
    }
    return fit_family_member(*per_fold[t], joint, training, fit);
  };
}

/// What identifies "the same effect" across models that differ only in
/// their parameter values: the kind, the label without its numbers (starting
/// values are printed in it), and the number of slots, without the initial
/// states of later records (a fold's training rows can hold fewer records
/// than the whole estimation data; each fit adds the states its data have).
std::string candidate_key(const EffectCandidate& c) {
  std::string stem;
  for (char ch : c.label)
    if (!std::isdigit(static_cast<unsigned char>(ch)) && ch != '.' && ch != '-' && ch != '+' && ch != 'e') stem += ch;
  const auto slots =
      std::count_if(c.slots.begin(), c.slots.end(), [](const ParameterSlot& s) { return !later_record_state(s); });
  return c.kind + "|" + stem + "|" + std::to_string(slots);
}

/// For each candidate of `whole`, the candidate of `fold` with the same key
/// (each used once), or null.
std::vector<const EffectCandidate*> match_candidates(const std::vector<EffectCandidate>& whole,
                                                     const std::vector<EffectCandidate>& fold) {
  std::vector<const EffectCandidate*> out(whole.size(), nullptr);
  std::vector<bool> used(fold.size(), false);
  for (size_t i = 0; i < whole.size(); ++i) {
    const std::string key = candidate_key(whole[i]);
    for (size_t j = 0; j < fold.size(); ++j)
      if (!used[j] && candidate_key(fold[j]) == key) {
        out[i] = &fold[j];
        used[j] = true;
        break;
      }
  }
  return out;
}

ScoredCandidate scored_from_family(const EffectCandidate& c, const FoldedFamily& f, const LpvModel<double>& previous,
                                   bool joint) {
  ScoredCandidate s;
  s.kind = c.kind;
  s.label = c.label;
  s.effect_parameters = c.effect_parameters;
  s.joint = joint;
  s.folds = f.figures;
  s.start = f.start;
  const FitResult& w = f.whole;
  s.rms_validation = s.folds.total_rms();
  if (!w.finite || !std::isfinite(s.rms_validation)) {
    s.rms_estimation = s.rms_validation = s.score = std::numeric_limits<double>::infinity();
    s.model = c.starts.front();
    return s;
  }
  s.model = w.model;
  s.rms_estimation = w.rms;
  Eigen::Index scored = 0;
  for (Eigen::Index n : s.folds.count) scored += n;
  s.score = s.rms_validation * s.rms_validation * (1.0 + 2.0 * s.effect_parameters / static_cast<double>(scored));
  s.parameters = effect_parameters(c.kind, c.label, s.model, previous);
  return s;
}

void set_explained(RankingRound& r) {
  for (ScoredCandidate& s : r.ranked) {
    // a free run that left every scale of the data diverged: its RMS is
    // stated as inf (as for one that overflowed), not as a number like 4e95
    if (s.rms_validation > kDivergedFactor * r.reference_validation)
      s.rms_validation = std::numeric_limits<double>::infinity();
    s.explained = std::isfinite(s.rms_validation)
                      ? 1.0 - (s.rms_validation * s.rms_validation) / (r.reference_validation * r.reference_validation)
                      : -std::numeric_limits<double>::infinity();
  }
  std::stable_sort(r.ranked.begin(), r.ranked.end(),
                   [](const ScoredCandidate& a, const ScoredCandidate& b) { return a.score < b.score; });
}

/// Fold mode's state between rounds: the current model on the whole record
/// and, per fold, the training rows and the current model fitted on them.
struct FoldChain {
  LpvModel<double> current;
  double current_est = 0;
  FoldFigures current_folds;  // set in round 1 (the declared structure re-fitted per fold)
  std::vector<Experiment<double>> training;   ///< [t]: fold t's training rows
  std::vector<LpvModel<double>> current_fold;  ///< [t]: fold t's current model
};

/// The chain before round 1: res.before on the whole record, and the
/// declared unknowns fitted on each fold's training rows.
FoldChain start_fold_chain(const LpvModel<double>& declared, const Experiment<double>& est, const RankingResult& res,
                           const FitOptions& fit) {
  FoldChain c;
  c.current = res.before;
  c.current_est = res.before_estimation;
  // the current model of each fold, fitted on that fold's training rows only:
  // the chain of models a fold would have chosen without its held-out block
  const size_t k = res.fold_blocks.size();
  c.training.resize(k);
  c.current_fold.resize(k);
  for (size_t t = 0; t < k; ++t) {
    c.training[t] = training_set(est, res.fold_blocks, t);
    const FitResult f = fit_declared(declared, c.training[t], fit);
    c.current_fold[t] = f.finite ? f.model : res.before;
  }
  return c;
}

/// The no-effect candidate on `m`: its refit_slots, no new effect.
EffectCandidate no_effect_candidate(const LpvModel<double>& m) {
  EffectCandidate c;
  c.kind = "none";
  c.starts = {m};
  c.slots = refit_slots(m);
  return c;
}

/// One round of fold mode: the candidates the families point into (filled
/// in place, so the pointers stay valid), the families in fit_families' job
/// order (the no-effect reference, then each candidate) and their labels.
struct FoldRound {
  std::vector<EffectCandidate> cands;                    ///< on the current model, whole record
  std::vector<std::vector<EffectCandidate>> fold_cands;  ///< [t]: on fold t's current model
  EffectCandidate refit;
  std::vector<EffectCandidate> fold_refit;
  std::vector<FamilyFit> families;
  std::vector<std::string> labels;
};

/// Fills `fr` for the chain's current models: each candidate of the whole
/// record with the same effect of each fold (match_candidates).
void fold_round_families(const FoldChain& chain, const Experiment<double>& est, const RankingOptions& o, FoldRound& fr) {
  const size_t k = chain.training.size();
  fr.cands = round_candidates(chain.current, est, o);
  fr.fold_cands.resize(k);
  parallel_for(k, o.threads,
               [&](size_t t) { fr.fold_cands[t] = round_candidates(chain.current_fold[t], chain.training[t], o); });
  std::vector<std::vector<const EffectCandidate*>> matched(k);  // [t][i]
  for (size_t t = 0; t < k; ++t) matched[t] = match_candidates(fr.cands, fr.fold_cands[t]);
  // the no-effect reference: the same freedom, no new effect
  fr.refit = no_effect_candidate(chain.current);
  fr.fold_refit.resize(k);
  std::vector<const EffectCandidate*> refit_per_fold(k);
  for (size_t t = 0; t < k; ++t) {
    fr.fold_refit[t] = no_effect_candidate(chain.current_fold[t]);
    refit_per_fold[t] = &fr.fold_refit[t];
  }
  fr.families = {candidate_family(fr.refit, refit_per_fold, o)};
  fr.labels = {"no new effect"};
  for (size_t i = 0; i < fr.cands.size(); ++i) {
    std::vector<const EffectCandidate*> per_fold(k);
    for (size_t t = 0; t < k; ++t) per_fold[t] = matched[t][i];
    fr.families.push_back(candidate_family(fr.cands[i], per_fold, o));
    fr.labels.push_back(fr.cands[i].label);
  }
}

/// The round's no-effect figures and its reference folds (what a candidate
/// must beat); round 1 also sets the "before" figures and the chain's folds.
void set_fold_reference(RankingRound& r, const FoldFigures& refit_folds, int round, FoldFigures& current_folds,
                        RankingResult& res) {
  r.refit_validation = refit_folds.total_rms();
  // round 1: the declared model's own figures are not held out (its A, B may
  // have been fitted on these rows), so the reference is its structure re-fitted
  // on each fold; later rounds: the better of that and the chosen model's folds
  r.reference_folds = round == 0 || refit_folds.total_rms() < current_folds.total_rms() ? refit_folds : current_folds;
  if (round == 0) {
    res.before_folds = refit_folds;
    res.before_validation = refit_folds.total_rms();
    r.current_validation = res.before_validation;
    current_folds = refit_folds;
  }
  r.reference_validation = r.reference_folds.total_rms();
}

/// Scores each candidate from its family (fitted[i + 1]), ranks them, and
/// sets r.chosen.
void rank_fold_round(RankingRound& r, const std::vector<EffectCandidate>& cands,
                     const std::vector<FoldedFamily>& fitted, const LpvModel<double>& current,
                     const Experiment<double>& est, const RankingOptions& o) {
  for (size_t i = 0; i < cands.size(); ++i) {
    r.ranked.push_back(scored_from_family(cands[i], fitted[i + 1], current, o.joint_dynamics));
    r.ranked.back().folds_won = folds_won(r.ranked.back().folds, r.reference_folds);
    r.ranked.back().family = i + 1;
  }
  set_explained(r);
  set_estimation_shares(r, est);
  // the best-scored candidate that passes the rule of fold_plan.h and the
  // share floor, unless tied
  std::vector<int> accepted;
  for (size_t i = 0; i < r.ranked.size(); ++i)
    if (accepts(r.ranked[i].folds, r.reference_folds, o.min_gain) &&
        r.ranked[i].estimation_share >= kMinEstimationShare)
      accepted.push_back(static_cast<int>(i));
  r.chosen = effect_tie_rule(r.ranked, accepted, r.tie);
  // physics first: a physical form within the folds' spread of a black-box choice
  std::vector<RankedFigures> figures;
  for (const ScoredCandidate& c : r.ranked) figures.push_back({c.kind, c.folds});
  r.physical = physical_alternative(figures, accepted, r.chosen);
  if (r.physical && r.physical->taken) {
    r.chosen = r.physical->physical;
    r.tie.reset();
  }
}

/// The round's chosen candidate becomes the chain's current model, on the
/// whole record and on each fold, and is appended to res.chosen.
void carry_fold_choice(const RankingRound& r, const std::vector<FoldedFamily>& fitted, FoldChain& chain,
                       RankingResult& res) {
  const ScoredCandidate& c = r.ranked[static_cast<size_t>(r.chosen)];
  chain.current = c.model;
  chain.current_est = c.rms_estimation;
  chain.current_folds = c.folds;
  // each fold carries its own fit of the chosen effect into the next round
  // (a fold whose fit failed keeps its model: its next candidates will not
  // match, and it counts as lost for every one of them)
  const FoldedFamily& f = fitted[c.family];
  for (size_t t = 0; t < chain.current_fold.size(); ++t)
    if (f.per_fold[t].finite) chain.current_fold[t] = f.per_fold[t].model;
  res.chosen.push_back(c);
}

/// Fold mode (val empty): see the header.
RankingResult rank_effects_by_folds(const LpvModel<double>& declared, const Experiment<double>& est,
                                    const RankingOptions& o) {
  RankingResult res;
  res.min_gain = o.min_gain;
  res.fold_blocks = blocked_folds(est.record_lengths(), o.folds, o.fold_warmup);
  // before: the declared unknowns fitted on each training set
  const FitResult before = fit_declared(declared, est, o.fit);
  res.before = before.model;
  res.before_estimation = before.rms;
  FoldChain chain = start_fold_chain(declared, est, res, o.fit);
  for (int round = 0; round < o.max_effects; ++round) {
    RankingRound r;
    r.current = chain.current;
    r.current_validation = chain.current_folds.total_rms();
    FoldRound fr;
    fold_round_families(chain, est, o, fr);
    const std::vector<FoldedFamily> fitted =
        fit_families(fr.families, fr.labels, "round " + std::to_string(round + 1), est, res.fold_blocks, o);
    set_fold_reference(r, fitted[0].figures, round, chain.current_folds, res);
    rank_fold_round(r, fr.cands, fitted, chain.current, est, o);
    if (r.chosen >= 0) carry_fold_choice(r, fitted, chain, res);
    const bool stop = r.chosen < 0;
    res.rounds.push_back(std::move(r));
    if (stop) break;
  }
  res.after = chain.current;
  restate_parameters(res, res.after);
  res.after_estimation = chain.current_est;
  res.after_folds = chain.current_folds;
  res.after_validation = chain.current_folds.total_rms();
  return res;
}

/// One-split mode: ranks the round's scored candidates and sets r.chosen:
/// the best-scored candidate if it lowers the validation RMS by the required
/// share and passes the share floor, unless tied.
void choose_on_validation(RankingRound& r, const Experiment<double>& est, double min_gain) {
  set_explained(r);
  set_estimation_shares(r, est);
  std::vector<int> accepted;
  const auto passes = [&](size_t i) { return r.ranked[i].rms_validation <= (1.0 - min_gain) * r.reference_validation; };
  if (!r.ranked.empty() && passes(0))
    for (size_t i = 0; i < r.ranked.size(); ++i)
      if (passes(i) && r.ranked[i].estimation_share >= kMinEstimationShare) accepted.push_back(static_cast<int>(i));
  r.chosen = effect_tie_rule(r.ranked, accepted, r.tie);
}

}  // namespace

void set_estimation_shares(RankingRound& r, const Experiment<double>& est) {
  const Mat<double> base = simulate_output(r.current, est);
  const Mat<double> residual = est.y - base;
  std::vector<CandidateSignal> sig;
  std::vector<size_t> index;
  for (size_t k = 0; k < r.ranked.size(); ++k) {
    r.ranked[k].estimation_share = 0;
    const Mat<double> added = simulate_output(r.ranked[k].model, est) - base;
    if (!added.allFinite() || added.squaredNorm() == 0) continue;
    sig.push_back({r.ranked[k].label, added});
    index.push_back(k);
  }
  if (!residual.allFinite()) return;
  const std::vector<CandidateShare> sh = candidate_shares(residual, sig);
  for (size_t i = 0; i < sh.size(); ++i) r.ranked[index[i]].estimation_share = sh[i].share;
}

int effect_tie_rule(const std::vector<ScoredCandidate>& ranked, const std::vector<int>& accepted,
                    std::optional<EffectTie>& tie) {
  tie.reset();
  if (accepted.empty()) return -1;
  const double best = ranked[static_cast<size_t>(accepted.front())].rms_validation;
  EffectTie t;
  for (int i : accepted) {
    const double d = (ranked[static_cast<size_t>(i)].rms_validation - best) / best;
    if (std::abs(d) <= kEffectTieTolerance) {
      t.tied.push_back(i);
      t.margin = std::max(t.margin, std::abs(d));
    }
  }
  if (t.tied.size() < 2) return accepted.front();
  const auto key = [&](int i) {
    const ScoredCandidate& c = ranked[static_cast<size_t>(i)];
    return std::tuple(c.effect_parameters, physical_form_rank(c.kind), c.label);
  };
  int chosen = t.tied.front();
  for (int i : t.tied)
    if (key(i) < key(chosen)) chosen = i;
  // the first key that separates the chosen one from the next best of the tie
  int runner = -1;
  for (int i : t.tied)
    if (i != chosen && (runner < 0 || key(i) < key(runner))) runner = i;
  const auto [p0, f0, l0] = key(chosen);
  const auto [p1, f1, l1] = key(runner);
  t.rule = p0 != p1 ? "fewer parameters" : f0 != f1 ? "physical form" : "label order";
  tie = t;
  return chosen;
}

StartChoice choose_start_by_folds(const std::vector<std::vector<double>>& sse, const std::vector<Eigen::Index>& count,
                                  const std::vector<FitResult>& whole) {
  StartChoice c;
  c.starts = whole.size();
  for (const auto& row : sse)
    if (row.size() != whole.size()) return StartChoice{};  // the grids differ: no choice by folds
  double n = 0;
  for (Eigen::Index m : count) n += static_cast<double>(m);
  double lowest_est = std::numeric_limits<double>::infinity();
  for (size_t s = 0; s < whole.size(); ++s) {
    if (whole[s].finite && whole[s].rms < lowest_est) {
      lowest_est = whole[s].rms;
      c.lowest_estimation = static_cast<int>(s);
    }
    if (!whole[s].finite) continue;
    double total = 0;
    for (const auto& row : sse) total += row[s];
    const double rms = n > 0 ? std::sqrt(total / n) : std::numeric_limits<double>::infinity();
    const double score = whole[s].rms * whole[s].rms + rms * rms;
    if (std::isfinite(score) && score < c.score) {
      c.score = score;
      c.held_out = rms;
      c.chosen = static_cast<int>(s);
    }
  }
  if (c.lowest_estimation >= 0) {
    double total = 0;
    for (const auto& row : sse) total += row[static_cast<size_t>(c.lowest_estimation)];
    c.held_out_of_lowest_estimation = n > 0 ? std::sqrt(total / n) : std::numeric_limits<double>::infinity();
  }
  return c;
}

void restate_parameters(RankingResult& res, const LpvModel<double>& final_model) {
  size_t k = 0;
  for (const RankingRound& r : res.rounds) {
    if (r.chosen < 0 || k >= res.chosen.size()) continue;
    ScoredCandidate& c = res.chosen[k++];
    if (c.parameters_at_round.is_null()) c.parameters_at_round = c.parameters;
    c.parameters = effect_parameters(c.kind, c.label, final_model, r.current, &c.model);
  }
}

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
  if (val.n() == 0) return rank_effects_by_folds(declared, est, o);
  RankingResult res;
  res.min_gain = o.min_gain;
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
    const std::vector<EffectCandidate> cands = round_candidates(current, est, o);
    r.ranked.resize(cands.size());
    std::mutex report;
    size_t done = 0;
    parallel_for(cands.size(), o.threads, [&](size_t i) {
      r.ranked[i] = fit_candidate(cands[i], est, val, o, current);
      if (!o.progress) return;
      const std::lock_guard<std::mutex> lock(report);
      o.progress("effects, round " + std::to_string(round + 1) + ": candidate " + std::to_string(++done) + " of " +
                 std::to_string(cands.size()) + " (" + cands[i].label + ")");
    });
    choose_on_validation(r, est, o.min_gain);
    if (r.chosen >= 0) {
      const ScoredCandidate& c = r.ranked[static_cast<size_t>(r.chosen)];
      current = c.model;
      current_est = c.rms_estimation;
      current_val = c.rms_validation;
      res.chosen.push_back(c);
    }
    const bool stop = r.chosen < 0;
    res.rounds.push_back(std::move(r));
    if (stop) break;
  }
  res.after = current;
  restate_parameters(res, res.after);
  res.after_estimation = current_est;
  res.after_validation = current_val;
  return res;
}

ojson effect_parameters(const std::string& kind, const std::string& label, const LpvModel<double>& fitted,
                        const LpvModel<double>& previous, const LpvModel<double>* introduced_by) {
  ojson j = ojson::object();
  const LpvModel<double>& introduced = introduced_by ? *introduced_by : fitted;
  if (kind == "basis_term") {
    basis_term_parameters(fitted, introduced, previous, j);
  } else if (kind == "output_offset" || kind == "abs_value") {
    offset_parameters(fitted, j);
  }
  if (kind == "input_saturation" || kind == "dead_zone" || kind == "input_polynomial")
    j["input_map"] = static_map_json(fitted.statics.input);
  if (kind == "output_saturation" || kind == "abs_value" || kind == "output_polynomial" ||
      kind == "output_piecewise_linear")
    j["output_map"] = static_map_json(fitted.statics.output);
  if (kind == "input_delay") j["delay_samples"] = fitted.statics.input_delay;
  if (kind == "state_nonlinearity") state_nonlinearity_parameters(label, fitted, introduced, previous, j);
  j["label"] = label;
  return j;
}

}  // namespace lpvid
