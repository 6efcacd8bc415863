#pragma once
// A bench case's data as a CSV file under the model's column names, so that
// its certificates name a file `lpvid-verify` can read.
#include <string>
#include <vector>

#include "data/csv_writer.h"
#include "data/experiment.h"
#include "model/lpv_model.h"

namespace lpvid::bench {

inline void write_case_data(const std::string& path, const LpvModel<Rational>& m, const Experiment<Rational>& e) {
  std::vector<TextColumn> cols;
  for (Eigen::Index i = 0; i < e.nu(); ++i) cols.push_back({m.columns.u[static_cast<size_t>(i)], column_text(e.u, i)});
  for (Eigen::Index i = 0; i < e.ny(); ++i) cols.push_back({m.columns.y[static_cast<size_t>(i)], column_text(e.y, i)});
  for (Eigen::Index i = 0; i < e.n_rho(); ++i) cols.push_back({m.columns.rho[static_cast<size_t>(i)], column_text(e.rho, i)});
  write_csv(path, cols);
}

}  // namespace lpvid::bench
