#include "cli/signal_info_options.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"

namespace lpvid::cli {

void add_signal_info_options(CLI::App& app, SignalInfoArgs& a) {
  app.add_option("--sample-time", a.sample_time,
                 "seconds between samples, written into the model file (plots then show time in seconds)");
  app.add_option("--unit", a.units, "COLUMN=UNIT, e.g. uEst=V (repeatable), written into the model file for plots");
}

SignalInfo signal_info_of(const SignalInfoArgs& a, const ColumnMap& columns, SignalInfo base) {
  if (a.sample_time != 0.0) {
    if (!(a.sample_time > 0.0) || !std::isfinite(a.sample_time))
      throw InputError("--sample-time: expected a positive number of seconds, got " + std::to_string(a.sample_time));
    base.sample_time = a.sample_time;
  }
  std::vector<std::string> known = columns.u;
  known.insert(known.end(), columns.y.begin(), columns.y.end());
  known.insert(known.end(), columns.rho.begin(), columns.rho.end());
  for (const std::string& text : a.units) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
      throw InputError("--unit '" + text + "': expected COLUMN=UNIT, e.g. uEst=V");
    const std::string column = text.substr(0, eq), unit = text.substr(eq + 1);
    if (std::find(known.begin(), known.end(), column) == known.end())
      throw InputError("--unit '" + text + "': '" + column + "' is not one of the model's columns");
    auto it = std::find_if(base.units.begin(), base.units.end(), [&](const auto& p) { return p.first == column; });
    if (it != base.units.end())
      it->second = unit;
    else
      base.units.emplace_back(column, unit);
  }
  return base;
}

}  // namespace lpvid::cli
