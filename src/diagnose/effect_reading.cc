#include "diagnose/effect_reading.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "diagnose/effect_ranking.h"
#include "model/simulate.h"

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
  ArgumentRange r;
  for (Eigen::Index i = 0; i < m.size(); ++i) {
    const double v = m.data()[i];
    if (!std::isfinite(v)) continue;
    r.lo = r.any ? std::min(r.lo, v) : v;
    r.hi = r.any ? std::max(r.hi, v) : v;
    r.any = true;
  }
  return r;
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

}  // namespace

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
  for (RankingRound& r : res.rounds)
    for (ScoredCandidate& c : r.ranked) c.reading = effect_reading(c.kind, c.model, est);
  for (ScoredCandidate& c : res.chosen) c.reading = effect_reading(c.kind, res.after, est);
}

}  // namespace lpvid
