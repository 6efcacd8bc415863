// The generated analogues of the real records (src/examples/plant_analogues.h)
// through the diagnose pipeline, as a table:
//   linear start  fit-linear --order auto (orders 1..5, scored on the last 30 %)
//   selection     4 blocked folds of the estimation record (diagnose/fold_plan.h)
//   test          a separate record, scored once: x0 from the warm-up, RMS over the rest
// Usage: diagnose_analogues [n] [name ...] [--no-order-variants] [--no-state-functions]
//                           [--one-split] [--threads T]
// Prints progress on stderr and one table row per analogue on stdout.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "core/parallel_for.h"
#include "data/experiment_builder.h"
#include "diagnose/effect_ranking.h"
#include "examples/plant_analogues.h"
#include "fit/linear_fit.h"

using namespace lpvid;

int main(int argc, char** argv) {
  int n = 1000;
  unsigned threads = default_thread_count();
  std::vector<std::string> names;
  bool order_variants = true, state_functions = true, one_split = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--no-order-variants") order_variants = false;
    else if (a == "--no-state-functions") state_functions = false;
    else if (a == "--one-split") one_split = true;
    else if (a == "--threads" && i + 1 < argc) threads = static_cast<unsigned>(std::stoi(argv[++i]));
    else if (!a.empty() && std::isdigit(static_cast<unsigned char>(a[0]))) n = std::stoi(a);
    else names.push_back(a);
  }
  if (names.empty()) names = plant_analogue_names();
  std::printf("%-11s %5s %5s  %-58s %-25s %-25s %8s %8s %6s %7s\n", "analogue", "n", "order", "effects chosen",
              "held-out folds before", "held-out folds after", "test bef", "test aft", "ratio", "time s");
  for (const std::string& name : names) {
    const auto t0 = std::chrono::steady_clock::now();
    const PlantAnalogue p = make_plant_analogue(name, n, 7);
    const ColumnMap cols{{"u1"}, {"y1"}, {}};
    const Eigen::Index cut = n * 7 / 10;
    std::cerr << "[" << name << "] linear order on rows 0:" << cut << ", scored on " << cut << ":" << n << "\n";
    const OrderChoice oc = choose_order(select_rows(p.estimation, 0, cut), select_rows(p.estimation, cut, n), cols, 5,
                                        true, 5);
    RankingOptions o;
    o.threads = threads;
    o.order_variants = order_variants;
    o.candidates.state_functions = state_functions;
    o.fold_warmup = 10;
    const Eigen::Index test_warmup = name == "tanks" ? 50 : 10;
    std::cerr << "[" << name << "] ranking effects (" << (one_split ? "one split" : "4 folds") << ")\n";
    const Experiment<double> none;
    const RankingResult r =
        one_split ? rank_effects(oc.fit.model, select_rows(p.estimation, 0, cut), select_rows(p.estimation, cut, n), o)
                  : rank_effects(oc.fit.model, p.estimation, none, o);
    for (size_t k = 0; k < r.rounds.size(); ++k) {
      const RankingRound& rr = r.rounds[k];
      std::fprintf(stderr, "[%s] round %zu: reference %.4g, chosen %d\n", name.c_str(), k + 1, rr.reference_validation,
                   rr.chosen);
      for (size_t i = 0; i < rr.ranked.size() && i < 6; ++i)
        std::fprintf(stderr, "    %zu. held-out %.4g (wins %d) score %.4g  %s\n", i + 1, rr.ranked[i].rms_validation,
                     rr.ranked[i].folds_won, rr.ranked[i].score, rr.ranked[i].label.c_str());
    }
    const double before = warmup_score(r.before, p.test, test_warmup).rms;
    const double after = warmup_score(r.after, p.test, test_warmup).rms;
    std::string effects;
    for (const ScoredCandidate& c : r.chosen) effects += (effects.empty() ? "" : "; ") + c.label;
    if (effects.empty()) effects = "none";
    const auto folds = [](const FoldFigures& f) {
      std::string t;
      for (size_t j = 0; j < f.sse.size(); ++j) {
        char b[16];
        std::snprintf(b, sizeof b, "%.3g", f.rms(j));
        t += (j ? " " : "") + std::string(b);
      }
      return t.empty() ? std::string("-") : t;
    };
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%-11s %5d %5d  %-58s %-25s %-25s %8.4f %8.4f %6.3f %7.1f\n", name.c_str(), n, oc.order,
                effects.substr(0, 58).c_str(), folds(r.before_folds).c_str(), folds(r.after_folds).c_str(), before,
                after, after / before, secs);
    std::fflush(stdout);
    if (effects.size() > 58) std::printf("            effects in full: %s\n", effects.c_str());
  }
  return 0;
}
