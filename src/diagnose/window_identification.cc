#include "diagnose/window_identification.h"

#include <cstdio>

#include "core/deadline.h"
#include "data/experiment_builder.h"
#include "diagnose/record_windows.h"
#include "toeplitz/affine_residual.h"
#include "identify/fix_and_certify.h"
#include "model/problem.h"
#include "model/simulate.h"

namespace lpvid {

namespace {

/// The stage on rows [begin, end) (`rows` in their file), failed for `reason`:
/// no bound, no certificate.
WindowIdentification failed_stage(Eigen::Index begin, Eigen::Index end, const DataReference& rows,
                                  const std::string& reason, const std::vector<std::string>& basis) {
  WindowIdentification failed;
  failed.applicable = true;
  failed.failed = reason;
  failed.basis = basis;
  failed.rows = rows;
  failed.bounds.begin = begin;
  failed.bounds.end = end;
  failed.bounds.file_begin = rows.row_begin;
  failed.bounds.file_end = rows.row_end;
  failed.bounds.bounds.reason = reason;
  return failed;
}

}  // namespace

WindowIdentification identify_on_window(const LpvModel<double>& fitted, const ExperimentViews& est, Eigen::Index begin,
                                        Eigen::Index end, const CertifyOptions& options,
                                        SdpSolver& solver) {
  const auto& [est_q, est_d] = est;
  WindowIdentification out;
  if (fitted.statics.has_output()) {
    out.why_not = std::string("the model has a static output map (") + to_string(fitted.statics.output.kind) +
                  "): its output is not affine in the correction, so Theorem 3.1 does not apply";
    return out;
  }
  // basis {1} ∪ the model's C, D terms (their C_i, D_i move on top of the fitted values)
  std::vector<Monomial> basis = {constant_monomial(fitted.scheduling.size())};
  for (const auto* pm : {&fitted.C, &fitted.D})
    for (const auto& t : pm->terms)
      if (std::find(basis.begin(), basis.end(), t.basis) == basis.end()) basis.push_back(t.basis);
  for (const Monomial& f : basis) out.basis.push_back(f.text(fitted.scheduling));

  const Simulation<double> sim = simulate(fitted, est_d);
  const Vec<double> xb = fitted.nx > 0 ? Vec<double>(sim.x.row(begin).transpose()) : Vec<double>();
  LpvModel<Rational> mq = exact_model(fitted, xb);
  mq.correction = zero_correction<Rational>(basis, mq.nx, mq.nu);
  // the window's problem: the double model is the exact one converted; the data are the window's rows of each view
  const Problem window{mq, convert_model<double>(mq), select_rows(est_q, begin, end), select_rows(est_d, begin, end)};

  IdentifyOptions io;
  io.objective = options.objective;
  io.method = IdentifyMethod::kAlternating;
  io.solver = options.solver;
  io.unknowns.correction = true;
  io.unknowns.offset = false;
  io.unknowns.x0 = true;
  out.applicable = true;
  out.bounds.begin = begin;
  out.bounds.end = end;
  const DataReference rows = piece_reference(options.records, est_q.record_lengths(), {begin, end});
  out.bounds.file_begin = rows.row_begin;
  out.bounds.file_end = rows.row_end;
  out.rows = rows;
  CertifyOptions co = options;
  if (!co.records.empty()) co.records = {rows};  // the certificate names the window's file rows
  co.lower_end = false;  // the diagnose report states δ, d_max here, not the interval
  IdentifiedModel id = identify_and_certify(window, io, co, solver);
  out.result = std::move(id.fit);
  if (!has_solution(out.result.status)) {
    out.bounds.bounds.reason = "identification ended with " + std::string(to_string(out.result.status));
    return out;
  }
  out.bounds.model = std::move(id.fixed.model);
  out.bounds.bounds = std::move(id.bounds);
  judge_informative(out.bounds, window.exp_d.y);
  return out;
}

WindowIdentification try_identify_on_window(const LpvModel<double>& fitted, const ExperimentViews& est,
                                            Eigen::Index begin, Eigen::Index end,
                                            const CertifyOptions& options, SdpSolver& solver) {
  const DataReference rows = piece_reference(options.records, est.exp_q.record_lengths(), {begin, end});
  try {
    return identify_on_window(fitted, est, begin, end, options, solver);
  } catch (const RunStopped&) {
    throw;  // the user's --timeout or a requested stop ends the run, not a window or a stage
  } catch (const std::exception& e) {
    return failed_stage(begin, end, rows, std::string("the optional Theorem 3.1 stage failed: ") + e.what(), {});
  }
}

void judge_against_window(WindowIdentification& id, const WindowBounds& own) {
  const CertifiedBounds& b = id.bounds.bounds;
  const CertifiedBounds& w = own.bounds;
  if (!id.failed.empty() || !b.verified() || !w.verified()) return;
  const bool same_rows = own.pieces.size() <= 1 && own.begin == id.bounds.begin && own.end == id.bounds.end;
  if (!same_rows) return;  // a joint window's bound is over other rows too
  const bool worse = b.delta > kReidentificationWorseFactor * w.delta || b.dmax > kReidentificationWorseFactor * w.dmax;
  if (!worse) return;
  char text[400];
  std::snprintf(text, sizeof text,
                "the optional Theorem 3.1 stage failed: its verified bounds (delta <= %.4g, dmax <= %.4g) are more "
                "than %g times the window's own Theorem 2.1 bounds on the same rows (delta <= %.4g, dmax <= %.4g), "
                "which its start already meets; the window's bounds stand",
                b.delta, b.dmax, kReidentificationWorseFactor, w.delta, w.dmax);
  id = failed_stage(id.bounds.begin, id.bounds.end, id.rows, text, id.basis);
}

}  // namespace lpvid
