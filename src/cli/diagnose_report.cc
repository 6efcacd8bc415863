#include "cli/diagnose_report.h"

namespace lpvid::cli {

std::string test_rule_text(const FreeRunScore& score) {
  return "free run; x0 from the first " + std::to_string(score.warmup) +
         " samples (warm-up), RMS and fit % over the remaining " + std::to_string(score.scored);
}

}  // namespace lpvid::cli
