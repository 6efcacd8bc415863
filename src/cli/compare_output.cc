#include "cli/compare_output.h"

#include <algorithm>

#include "cli/inputs.h"
#include "core/number_text.h"
#include "data/csv_writer.h"
#include "plot/gnuplot.h"
#include "plot/model_colours.h"
#include "plot/palette.h"
#include "plot/plot_labels.h"

namespace lpvid::cli {
namespace {


std::vector<double> column_of(const Mat<double>& m, Eigen::Index j, Eigen::Index from, Eigen::Index to) {
  std::vector<double> v;
  for (Eigen::Index k = from; k < to; ++k) v.push_back(m(k, j));
  return v;
}

}  // namespace

std::vector<std::string> model_names(const std::vector<std::string>& paths) {
  std::vector<std::string> out;
  for (const std::string& p : paths) {
    std::string stem = stem_of(p, {".json"});
    const auto slash = stem.find_last_of('/');
    if (slash != std::string::npos) stem = stem.substr(slash + 1);
    std::string name = stem;
    for (int k = 2; std::find(out.begin(), out.end(), name) != out.end(); ++k) name = stem + "_" + std::to_string(k);
    out.push_back(name);
  }
  return out;
}

void write_compare_series(const std::string& path, const ComparedRows& r, const std::vector<ComparedSeries>& models) {
  const Eigen::Index n = r.y.rows();
  std::vector<TextColumn> cols;
  std::vector<std::string> row, time, scored;
  for (Eigen::Index k = 0; k < n; ++k) {
    row.push_back(std::to_string(r.first + k));
    time.push_back(double_to_text(r.info.time_of(static_cast<double>(r.first + k))));
    scored.push_back(k < r.warmup ? "0" : "1");
  }
  cols.push_back({"row", row});
  if (r.info.sample_time > 0) cols.push_back({"time_s", time});
  cols.push_back({"scored", scored});
  const bool one = models.size() == 1;
  for (Eigen::Index i = 0; i < r.y.cols(); ++i) {
    const std::string& out = r.outputs[static_cast<size_t>(i)];
    cols.push_back({out, column_text(r.y, i)});
    for (const ComparedSeries& m : models) {
      const Mat<double> resid = r.y - m.yhat;
      cols.push_back({one ? out + "_model" : m.name + ".yhat." + out, column_text(m.yhat, i)});
      cols.push_back({one ? out + "_residual" : m.name + ".residual." + out, column_text(resid, i)});
    }
  }
  write_csv(path, cols);
}

std::string plot_compare(const std::string& path, const ComparedRows& r, const std::vector<ComparedSeries>& models,
                         const std::string& title) {
  if (path.empty()) return "";
  const Eigen::Index n = r.y.rows();
  std::vector<double> t;
  for (Eigen::Index k = 0; k < n; ++k) t.push_back(r.info.time_of(static_cast<double>(r.first + k)));
  PlotSpec fig;
  fig.title = title;
  fig.height = 300 + 300 * static_cast<int>(r.y.cols());
  std::vector<std::string> names;
  for (const ComparedSeries& m : models) names.push_back(m.name);
  const std::vector<std::string> colours = model_colours(names);
  for (Eigen::Index i = 0; i < r.y.cols(); ++i) {
    PlotSpec p;
    p.xlabel = r.info.time_label();
    const std::string& output = r.outputs[static_cast<size_t>(i)];
    p.ylabel = output + unit_suffix(r.info.unit_of(output));
    if (r.warmup > 0) {
      PlotSeries w{"measured, warm-up rows (x0 fit, not scored)", {}, {}, {}, "lines", {}, palette::kWarmup};
      w.x.assign(t.begin(), t.begin() + r.warmup);
      w.y = column_of(r.y, i, 0, r.warmup);
      p.series.push_back(w);
    }
    PlotSeries m{"measured", {}, {}, {}, "lines", {}, palette::kMeasured};
    m.x.assign(t.begin() + r.warmup, t.end());
    m.y = column_of(r.y, i, r.warmup, n);
    p.series.push_back(m);
    for (size_t j = 0; j < models.size(); ++j) {
      PlotSeries s{models[j].name, t, column_of(models[j].yhat, i, 0, n), {}, "lines", {}, colours[j]};
      p.series.push_back(s);
    }
    fig.panels.push_back(p);
  }
  const PlotOutcome po = plot_png(fig, path);
  return po.ok ? po.message : "no plot: " + po.message + " (the numbers are in the CSV and the report)";
}

}  // namespace lpvid::cli
