#include "oracle/random_task.h"

#include <algorithm>

#include "core/decimal_rounding.h"
#include "core/input_error.h"
#include "core/number_text.h"

namespace lpvid {
namespace {

/// x rounded up to 6 significant digits, as exact decimal text (a fixed
/// bound at least the generating one keeps the truth a witness).
std::string bound_text(double x) { return exact_decimal_or_fraction(round_up_to_digits(exact_rational_of_double(x), 6)); }

}  // namespace

GeneratedCase random_oracle_case(uint64_t seed, const RandomTaskOptions& o) {
  if (o.kinds.empty()) throw InputError("no task kinds to choose from");
  GeneratedCase g;
  g.seed = seed;
  SeededDraw draw(seed);
  OracleTask& t = g.task;
  t.kind = o.kinds[static_cast<size_t>(draw.integer(0, static_cast<int>(o.kinds.size()) - 1))];
  RandomCaseOptions cases = o.cases;
  if (t.kind == TaskKind::kIdentify) {
    // a correction basis with a true θ to find; θ of the output only (docs/design.md §8)
    cases.model.min_correction = std::max(cases.model.min_correction, 1);
    cases.model.max_correction = std::max(cases.model.max_correction, 2);
    cases.model.allow_general = false;
    cases.true_correction = true;
  }
  g.random = random_case(cases, draw);
  const RandomCase& r = g.random;
  t.tolerance = o.tolerance;
  bool tight = false;
  switch (t.kind) {
    case TaskKind::kMinDmax:
    case TaskKind::kIdentify: t.delta = bound_text(r.delta); break;
    case TaskKind::kMinDelta: t.dmax = bound_text(r.dmax); break;
    case TaskKind::kWeighted: t.lambda = "0.5"; break;
    case TaskKind::kDecide:
      tight = draw.coin();
      t.delta = bound_text(tight ? r.delta / 4 : r.delta);
      t.dmax = bound_text(tight ? r.dmax / 4 : r.dmax);
      break;
  }
  t.info["seed"] = seed;
  t.info["generator"] = "examples/random_case.h (the property tests' generator)";
  t.info["samples"] = r.exp.n();
  t.info["states"] = r.model.nx;
  t.info["inputs"] = r.model.nu;
  t.info["outputs"] = r.model.ny;
  t.info["true_delta"] = r.delta;
  t.info["true_dmax"] = r.dmax;
  t.info["true_taps"] = r.taps.rows();
  if (t.kind == TaskKind::kDecide) t.info["decide_at"] = tight ? "a quarter of the true bounds" : "the true bounds (consistent)";
  return g;
}

}  // namespace lpvid
