#include "diagnose/effect_reading.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/finite_range.h"
#include "diagnose/effect_ranking.h"
#include "model/simulate.h"
#include "model/state_scheduling.h"

namespace lpvid {

namespace {

std::string g4(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

/// The finite values a static map sees on the record.
struct ArgumentRange {
  double lo = 0, hi = 0;
  bool any = false;
  double range() const { return hi - lo; }
  std::string text() const { return g4(lo) + " to " + g4(hi); }
};

ArgumentRange range_of(const Mat<double>& m) {
  const FiniteRange f = finite_range(m);
  return f.any() ? ArgumentRange{f.lo, f.hi, true} : ArgumentRange{};
}

/// "x' = x - c" for an offset c (as the map's output is the argument minus c).
std::string shifted(const std::string& x, double c) {
  return x + "' = " + x + (c > 0 ? " - " : " + ") + g4(std::abs(c));
}

std::string dead_zone_reading(const StaticMap<double>& g, const ArgumentRange& a, const std::string& what,
                              const std::string& x) {
  const double width = g.upper - g.lower;
  if (a.lo > g.upper)
    return "an " + what + " offset: " + shifted(x, g.upper) + " (no sample enters the dead band [" + g4(g.lower) + ", " +
           g4(g.upper) + "]; the " + what + " ranges " + a.text() + ")";
  if (a.hi < g.lower)
    return "an " + what + " offset: " + shifted(x, g.lower) + " (no sample enters the dead band [" + g4(g.lower) + ", " +
           g4(g.upper) + "]; the " + what + " ranges " + a.text() + ")";
  // |g(v) - (v - mid)| <= width / 2 everywhere
  if (width / 2 <= kNegligibleShare * a.range())
    return "an " + what + " offset: " + shifted(x, 0.5 * (g.lower + g.upper)) + " (the dead band, " + g4(width) +
           " wide, is negligible against the " + what + "'s range " + a.text() + ")";
  return "";
}

std::string map_reading(const StaticMap<double>& g, const ArgumentRange& a, const std::string& what,
                        const std::string& x) {
  if (!a.any) return "";
  switch (g.kind) {
    case StaticKind::kDeadZone: return dead_zone_reading(g, a, what, x);
    case StaticKind::kSaturation:
      if (a.lo >= g.lower && a.hi <= g.upper)
        return "the identity: the saturation limits [" + g4(g.lower) + ", " + g4(g.upper) + "] are never reached (the " +
               what + " ranges " + a.text() + ")";
      return "";
    case StaticKind::kAbs:
      if (a.lo >= 0)
        return "the identity: |.| of an argument that is never negative (" + a.text() +
               "); the fit's gain comes from what was fitted beside it";
      if (a.hi <= 0)
        return "a sign change: |.| of an argument that is never positive (" + a.text() +
               "); the fit's gain comes from what was fitted beside it";
      return "";
    default: return "";
  }
}

/// "x2 - 6.18" for the argument of a state function.
std::string argument_text(const StateScheduled<double>& f) {
  const std::string x = "x" + std::to_string(f.i + 1);
  if (f.shift == 0) return x;
  return x + (f.shift > 0 ? " - " : " + ") + g4(std::abs(f.shift));
}

/// The reading of one state function f(x_i − c) from the range of its
/// argument a = x_i − c on the record (`below`: samples with a < 0).
std::string state_function_reading(const StateScheduled<double>& f, const ArgumentRange& a, Eigen::Index below,
                                   Eigen::Index n) {
  const std::string arg = argument_text(f);
  const std::string seen = " (" + arg + " ranges " + a.text() + " on the estimation record)";
  const bool never_below = a.lo >= 0, never_above = a.hi <= 0;
  switch (f.function) {
    case StateFunction::kAbs:
      if (never_below) return "a linear term: |" + arg + "| = " + arg + " on every sample" + seen + "; no V is seen";
      if (never_above)
        return "a linear term: |" + arg + "| = -(" + arg + ") on every sample" + seen + "; no V is seen";
      break;
    case StateFunction::kHinge:
      if (never_above) return "zero: max(" + arg + ", 0) = 0 on every sample" + seen + "; the gain comes from the re-fit beside it";
      if (never_below) return "a linear term: max(" + arg + ", 0) = " + arg + " on every sample" + seen + "; no kink is seen";
      break;
    case StateFunction::kSqrtPos:
      if (never_above) return "zero: sqrt(max(" + arg + ", 0)) = 0 on every sample" + seen;
      if (never_below)
        return "a square root on every sample: sqrt(max(" + arg + ", 0)) = sqrt(" + arg + ")" + seen +
               "; its cut-off is never reached";
      break;
    case StateFunction::kSqrt:
      if (never_below || never_above) return "a square root of one sign: " + arg + " ranges " + a.text() + ", never crossing 0";
      break;
    case StateFunction::kState: return "";
  }
  char share[32];
  std::snprintf(share, sizeof share, "%.3g", 100.0 * static_cast<double>(below) / static_cast<double>(n));
  return "the kink is used: " + arg + " is below 0 on " + share + " % of the samples" + seen;
}

}  // namespace

std::string state_nonlinearity_reading(const LpvModel<double>& fitted, const Experiment<double>& est,
                                       const std::vector<std::string>& columns) {
  if (est.n() == 0 || columns.empty()) return "";
  Simulation<double> sim;
  std::vector<StateScheduled<double>> functions;
  try {
    functions = state_functions<double>(columns, fitted.nx);
    sim = simulate(fitted, est);
  } catch (const std::exception&) {
    return "";  // a model that does not simulate on the record has no reading; its RMS already says so
  }
  std::string out;
  for (const StateScheduled<double>& f : functions) {
    if (f.function == StateFunction::kState) continue;
    const Mat<double> a = sim.x.col(f.i).array() - f.shift;
    const ArgumentRange r = range_of(a);
    if (!r.any) continue;
    const Eigen::Index below = (a.array() < 0).count();
    out += (out.empty() ? "" : "; ") + state_function_reading(f, r, below, a.rows());
  }
  return out;
}

std::string effect_reading(const std::string& kind, const LpvModel<double>& fitted, const Experiment<double>& est) {
  const bool input_map = kind == "input_saturation" || kind == "dead_zone";
  const bool output_map = kind == "output_saturation" || kind == "abs_value";
  if (input_map) return map_reading(fitted.statics.input, range_of(est.u), "input", "u");
  if (!output_map || est.n() == 0) return "";
  try {
    const Simulation<double> sim = simulate(fitted, est);
    return map_reading(fitted.statics.output, range_of(Mat<double>(sim.yhat + sim.offset)), "output map's argument",
                       "v");
  } catch (const std::exception&) {
    return "";  // a model that does not simulate on the record has no reading; its RMS already says so
  }
}

void read_effects(RankingResult& res, const Experiment<double>& est) {
  // a state nonlinearity is read from the columns it introduced (its parameters)
  const auto read = [&](const ScoredCandidate& c, const LpvModel<double>& model) {
    if (c.kind != "state_nonlinearity") return effect_reading(c.kind, model, est);
    std::vector<std::string> columns;
    if (c.parameters.contains("new_scheduling"))
      for (const auto& [name, column] : c.parameters["new_scheduling"].items()) columns.push_back(column.get<std::string>());
    return state_nonlinearity_reading(model, est, columns);
  };
  for (RankingRound& r : res.rounds)
    for (ScoredCandidate& c : r.ranked) c.reading = read(c, c.model);
  for (ScoredCandidate& c : res.chosen) c.reading = read(c, res.after);
}

}  // namespace lpvid
