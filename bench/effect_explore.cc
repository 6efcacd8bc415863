// effect_explore: which effect does the linear model miss on real data
// (cascaded tanks, dryer)? Fits the linear starting model (fit/linear_fit.h)
// on the estimation data, adds each candidate effect of docs/design.md §9.2 (and chosen
// combinations) around it (explore/block_model.h), fits on estimation data
// only and prints the free-run RMS on estimation and validation data:
//   "A,B fixed": the denominator a and B of the linear fit stay, D, x0, c and
//                the effect parameters are fitted (output error; for
//                in_pathsR the extra B columns are effect parameters);
//   "full OE":   then everything is refitted by output error (A kept stable).
// Effect names: offset, delayD, in_polyP, in_pathsR, in_sat, dead_zone,
// lpv_u, lpv_y (ρ = own output one sample back), out_polyQ, out_sat, joined
// by '+' (see explore/block_model.h for the equations).
// Levels of input saturation and dead-zone are chosen on a 1-D grid by the
// estimation RMS. Validation x0 comes from the first --init-samples samples.
//
//   build/bench/effect_explore --data "$LPVID_DATA"/cascaded-tanks/dataBenchmark.csv
//       --u uEst --y yEst --val-u uVal --val-y yVal --order 2
//   build/bench/effect_explore --data "$LPVID_DATA"/dryer/dryer.dat --names u,y
//       --rows 0:500 --val-rows 500:1000 --order 3
#include <algorithm>
#include <cstdio>
#include <limits>
#include <sstream>

#include <CLI/CLI.hpp>

#include "core/input_error.h"
#include "data/csv_reader.h"
#include "data/experiment_builder.h"
#include "explore/block_model.h"
#include "fit/linear_fit.h"

using namespace lpvid;

namespace {

struct Spec {
  bool offset = false;
  EffectSet effects;
};

Spec parse_spec(const std::string& text) {
  Spec s;
  std::stringstream in(text);
  std::string t;
  while (std::getline(in, t, '+')) {
    if (t == "linear") continue;
    else if (t == "offset") s.offset = true;
    else if (t.rfind("delay", 0) == 0) s.effects.delay = std::stoi(t.substr(5));
    else if (t.rfind("in_poly", 0) == 0) s.effects.input_degree = std::stoi(t.substr(7));
    else if (t.rfind("in_paths", 0) == 0) s.effects.input_paths = std::stoi(t.substr(8));
    else if (t == "in_sat") s.effects.input_saturation = true;
    else if (t == "dead_zone") s.effects.dead_zone = true;
    else if (t == "lpv_u") s.effects.lpv = Scheduling::kInput;
    else if (t == "lpv_y") s.effects.lpv = Scheduling::kOutputLag;
    else if (t.rfind("out_poly", 0) == 0) s.effects.output_degree = std::stoi(t.substr(8));
    else if (t == "out_sat") s.effects.output_saturation = true;
    else throw InputError("effect_explore: unknown effect '" + t + "'");
  }
  return s;
}

// Single effects on top of the affine (offset) linear model, then the
// combinations that the single-effect table points to.
const char* kDefaultSpecs =
    "linear offset offset+delay1 offset+delay2 offset+delay3 offset+in_poly2 offset+in_poly3 offset+in_paths2 "
    "offset+in_paths3 offset+in_sat offset+dead_zone offset+out_poly2 offset+out_poly3 offset+out_sat offset+lpv_u "
    "offset+lpv_y "
    "offset+in_poly3+out_sat offset+in_paths2+out_sat offset+in_paths3+out_sat offset+lpv_y+out_sat "
    "offset+in_paths2+lpv_y+out_sat offset+in_paths3+lpv_y+out_sat offset+in_paths3+lpv_u+out_sat "
    "offset+in_paths3+out_poly3+out_sat";

Experiment<double> load(const std::string& path, const std::vector<std::string>& names, const std::string& rows,
                        const std::string& u, const std::string& y) {
  const TextTable t = names.empty() ? read_table(path) : read_table(path, names);
  Experiment<double> e = make_experiment<double>(t, ColumnMap{{u}, {y}, {}});
  if (rows.empty()) return e;
  const size_t colon = rows.find(':');
  return select_rows(e, std::stol(rows.substr(0, colon)), std::stol(rows.substr(colon + 1)));
}

struct Row {
  std::string name, levels;
  int parameters = 0;
  double est_fixed = 0, val_fixed = 0, est_full = 0, val_full = 0;
};

/// Grid of fixed levels for the input saturation / dead-zone (one value when
/// neither is present).
std::vector<double> level_grid(const EffectSet& e, const Vec<double>& u) {
  std::vector<double> grid;
  Vec<double> sorted = u;
  std::sort(sorted.begin(), sorted.end());
  const double span = u.cwiseAbs().maxCoeff();
  if (e.input_saturation)  // quantiles 0.70 … 0.98 of the estimation input
    for (double q = 0.70; q < 0.99; q += 0.04) grid.push_back(sorted(Eigen::Index(q * double(u.size() - 1))));
  else if (e.dead_zone)
    for (double f = 0.02; f < 0.41; f += 0.04) grid.push_back(f * span);
  else
    grid.push_back(0);
  return grid;
}

Row run_spec(const std::string& text, const Experiment<double>& est, const Experiment<double>& val, int order,
             int init_samples) {
  const Spec spec = parse_spec(text);
  const LinearFit lin = fit_linear(est, ColumnMap{{"u"}, {"y"}, {}}, LinearFitOptions{order, spec.offset, {}});
  const Vec<double> u = est.u.col(0), y = est.y.col(0), uv = val.u.col(0), yv = val.y.col(0);
  Row row;
  row.name = spec.effects.name(spec.offset);
  BlockModel best;
  double best_est = std::numeric_limits<double>::infinity();
  for (double level : level_grid(spec.effects, u)) {
    EffectSet e = spec.effects;
    e.input_level = level;
    e.dead_zone_width = level;
    BlockModel m = neutral_block_model(lin.form, e, u, y);
    const double r = fit_block_model(m, u, y, /*fix_dynamics=*/true);
    if (r < best_est) best_est = r, best = m;
  }
  row.est_fixed = best_est;
  row.val_fixed = block_validation_rms(best, uv, yv, init_samples);
  row.est_full = fit_block_model(best, u, y, /*fix_dynamics=*/false);
  row.val_full = block_validation_rms(best, uv, yv, init_samples);
  row.parameters = best.parameter_count() - order;  // x0 is not a model parameter
  char buf[160];
  std::string levels;
  if (spec.effects.input_saturation) std::snprintf(buf, sizeof buf, "L_in=%.3g ", best.effects.input_level), levels += buf;
  if (spec.effects.dead_zone) std::snprintf(buf, sizeof buf, "w=%.3g ", best.effects.dead_zone_width), levels += buf;
  if (spec.effects.output_saturation) {
    std::snprintf(buf, sizeof buf, "L_out=%.4g ", best.output_level + (best.linear.has_offset ? best.linear.offset : 0));
    levels += buf;
  }
  if (spec.offset) std::snprintf(buf, sizeof buf, "c=%.3g ", best.linear.offset), levels += buf;
  std::snprintf(buf, sizeof buf, "|λ|max=%.4f", spectral_radius(best.linear.a));
  row.levels = levels + buf;
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"effect_explore: which effect around the linear model lowers the free-run validation RMS"};
  std::string data, val_data, rows, val_rows, u = "u", y = "y", val_u, val_y, specs = kDefaultSpecs;
  std::vector<std::string> names;
  int order = 2, init_samples = 5;
  app.add_option("--data", data, "data file")->required();
  app.add_option("--names", names, "column names of a headerless file")->delimiter(',');
  app.add_option("--rows", rows, "estimation rows B:E");
  app.add_option("--val-data", val_data, "validation file (default: --data)");
  app.add_option("--val-rows", val_rows, "validation rows B:E");
  app.add_option("--u", u, "estimation input column");
  app.add_option("--y", y, "estimation output column");
  app.add_option("--val-u", val_u, "validation input column (default --u)");
  app.add_option("--val-y", val_y, "validation output column (default --y)");
  app.add_option("--order", order, "order of the linear part");
  app.add_option("--init-samples", init_samples, "validation x0 from this many first samples");
  app.add_option("--effects", specs, "space-separated effect sets, e.g. 'offset offset+in_poly3+out_sat'");
  CLI11_PARSE(app, argc, argv);
  try {
    const Experiment<double> est = load(data, names, rows, u, y);
    const Experiment<double> val = load(val_data.empty() ? data : val_data, names, val_rows,
                                        val_u.empty() ? u : val_u, val_y.empty() ? y : val_y);
    std::printf("estimation %s (%ld samples), validation (%ld samples), linear order %d, x0(val) from %d samples\n",
                data.c_str(), long(est.n()), long(val.n()), order, init_samples);
    std::printf("%-40s %4s %10s %10s %10s %10s  %s\n", "effects", "par", "est(AB)", "val(AB)", "est(OE)", "val(OE)",
                "levels");
    std::stringstream list(specs);
    std::string s;
    while (list >> s) {
      const Row r = run_spec(s, est, val, order, init_samples);
      std::printf("%-40s %4d %10.4f %10.4f %10.4f %10.4f  %s\n", r.name.c_str(), r.parameters, r.est_fixed,
                  r.val_fixed, r.est_full, r.val_full, r.levels.c_str());
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "effect_explore: %s\n", e.what());
    return 2;
  }
  return 0;
}
