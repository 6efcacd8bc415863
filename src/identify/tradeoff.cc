#include "identify/tradeoff.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "core/deadline.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "identify/fix_and_certify.h"
#include "identify/identify.h"
#include "model/model_file.h"

namespace lpvid {
namespace {

bool has_unknowns(const LpvModel<double>& m, const Unknowns& u) {
  return (u.correction && !m.correction.basis.empty()) ||
         (u.offset && m.offset.values.empty() && !m.offset.basis.empty()) || u.x0;
}

std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

std::string lambda_text(double l) {
  std::ostringstream s;
  s << l;
  return s.str();
}

std::vector<double> default_lambda_grid() {
  std::vector<double> g;
  for (int i = 0; i <= 10; ++i) g.push_back(std::round((0.02 + 0.096 * i) * 1000.0) / 1000.0);
  return g;
}

namespace {

/// The point's identification at λ (Theorem 3.1, relaxed or iterated): the
/// relaxation's values and the model with the rounded θ folded in (and, for
/// several records with free x0, each record's initial state in `exp_fixed`);
/// false (with the reason in pt.bounds) when no iterate solved.
bool identify_point(const LpvModel<Rational>& model_q, const LpvModel<double>& model_d, const Experiment<double>& exp_d,
                    const TradeoffOptions& o, const BoundObjective& obj, int digits, SdpSolver& solver, TradeoffPoint& pt,
                    LpvModel<Rational>& fixed, Experiment<Rational>& exp_fixed) {
  IdentifyOptions io;
  io.objective = obj;
  io.iterate = o.iterate;
  io.max_iterations = o.max_iterations;
  io.rel_tol = o.rel_tol;
  io.unknowns = o.unknowns;
  io.solver = o.solver;
  const IdentifyResult res = identify(model_d, exp_d, io, solver);
  pt.status = res.status;
  pt.relaxation = res.relaxation;
  pt.solves = static_cast<int>(res.iterates.size());
  if (res.iterates.empty() || !has_solution(res.iterates.front().status)) {
    pt.bounds.reason = std::string("the identification solve ended with status ") + to_string(res.status) +
                       (res.message.empty() ? "" : ": " + res.message);
    return false;
  }
  // The accepted iterate is the one with the smallest objective.
  const IterateRecord* best = nullptr;
  for (const IterateRecord& it : res.iterates)
    if (has_solution(it.status) && (!best || it.objective < best->objective)) best = &it;
  pt.delta_solver = std::sqrt(std::max(0.0, best->delta2));
  pt.dmax_solver = std::sqrt(std::max(0.0, best->dmax2));
  FixedParameters fp = fix_parameters(model_q, res.layout, res.p, digits, exp_fixed.record_x0);
  pt.p = fp.value;
  pt.layout = res.layout;
  exp_fixed = with_fixed_initial_states(exp_fixed, fp);
  fixed = std::move(fp.model);
  return true;
}

}  // namespace

std::vector<TradeoffPoint> tradeoff_curve(const Problem& problem, const TradeoffOptions& o, SdpSolver& solver) {
  const auto& [model_q, model_d, exp_q, exp_d] = problem;
  const std::vector<double> lambdas = o.lambdas.empty() ? default_lambda_grid() : o.lambdas;
  for (double l : lambdas)
    if (!(l >= 0.0 && l <= 1.0)) throw InputError("tradeoff: lambda " + lambda_text(l) + " is outside [0, 1]");
  const bool unknowns = has_unknowns(model_d, o.unknowns);
  std::vector<TradeoffPoint> out;
  for (size_t k = 0; k < lambdas.size(); ++k) {
    check_deadline("the trade-off curve was traced");  // the user's --timeout or a requested stop, between points
    const auto t0 = std::chrono::steady_clock::now();
    TradeoffPoint pt;
    pt.lambda = lambdas[k];
    BoundObjective obj;
    obj.kind = BoundObjective::Kind::kWeighted;
    obj.lambda = pt.lambda;
    CertifyOptions co = o.certify;
    co.objective = obj;
    co.solver = o.solver;
    LpvModel<Rational> fixed = model_q;
    Experiment<Rational> exp_fixed = exp_q;
    bool have_model = true;
    if (unknowns) {
      have_model = identify_point(model_q, model_d, exp_d, o, obj, co.digits, solver, pt, fixed, exp_fixed);
    } else {
      pt.status = SolveStatus::kOptimal;
      pt.relaxation = "none (fixed model: Theorem 2.1)";
    }
    if (have_model) pt.bounds = certify_fixed_model(fixed, exp_fixed, co, solver);
    pt.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out.push_back(pt);
    if (o.on_point) o.on_point(out.back());
  }
  return out;
}

std::string tradeoff_csv(const std::vector<TradeoffPoint>& points) {
  std::ostringstream s;
  s << "lambda,verified,delta,dmax,delta2_exact,dmax2_exact,delta_solver,dmax_solver,status,certificate\n";
  auto num = [](double x) { return x < 0 ? std::string() : double_to_text(x); };
  for (const TradeoffPoint& p : points) {
    const bool v = p.bounds.verified();
    s << lambda_text(p.lambda) << "," << (v ? "true" : "false") << "," << (v ? double_to_text(p.bounds.delta) : "")
      << "," << (v ? double_to_text(p.bounds.dmax) : "") << ","
      << (v ? csv_cell(exact_decimal_or_fraction(p.bounds.delta2)) : "") << ","
      << (v ? csv_cell(exact_decimal_or_fraction(p.bounds.dmax2)) : "") << "," << num(p.delta_solver) << ","
      << num(p.dmax_solver) << "," << to_string(p.status) << "," << csv_cell(p.certificate) << "\n";
  }
  return s.str();
}

std::string tradeoff_monotonicity_violation(const std::vector<TradeoffPoint>& points, double rel, double abs) {
  std::vector<const TradeoffPoint*> v;
  for (const TradeoffPoint& p : points)
    if (p.bounds.verified()) v.push_back(&p);
  std::stable_sort(v.begin(), v.end(), [](const TradeoffPoint* a, const TradeoffPoint* b) { return a->lambda < b->lambda; });
  for (size_t i = 1; i < v.size(); ++i) {
    const TradeoffPoint &a = *v[i - 1], &b = *v[i];
    if (b.bounds.delta > a.bounds.delta + rel * a.bounds.delta + abs)
      return "delta grows from " + double_to_text(a.bounds.delta) + " (lambda " + lambda_text(a.lambda) + ") to " +
             double_to_text(b.bounds.delta) + " (lambda " + lambda_text(b.lambda) + ")";
    if (b.bounds.dmax < a.bounds.dmax - rel * a.bounds.dmax - abs)
      return "dmax falls from " + double_to_text(a.bounds.dmax) + " (lambda " + lambda_text(a.lambda) + ") to " +
             double_to_text(b.bounds.dmax) + " (lambda " + lambda_text(b.lambda) + ")";
  }
  return "";
}

}  // namespace lpvid
