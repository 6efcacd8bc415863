#include "diagnose/record_roles.h"

#include "core/input_error.h"
#include "data/experiment_builder.h"
#include "diagnose/fold_plan.h"

namespace lpvid {

ColumnMap renamed_columns(const LpvModel<double>& from_model, const LpvModel<double>& m, const std::vector<std::string>& renamed,
                          const std::string& flag) {
  if (renamed.empty()) return m.columns;
  std::vector<std::string> from = from_model.columns.u;
  from.insert(from.end(), from_model.columns.y.begin(), from_model.columns.y.end());
  if (renamed.size() != from.size())
    throw InputError(flag + ": expected " + std::to_string(from.size()) +
                     " names (the model's u columns then y columns), got " + std::to_string(renamed.size()));
  auto rename = [&](const std::string& c) {
    for (size_t i = 0; i < from.size(); ++i)
      if (from[i] == c) return renamed[i];
    return c;
  };
  ColumnMap out = m.columns;
  for (auto* v : {&out.u, &out.y, &out.rho})
    for (auto& c : *v) c = rename(c);
  return out;
}

namespace {

std::string rows_text(long begin, long end) { return std::to_string(begin) + ":" + std::to_string(end); }

/// A selection or test record: a file (or the data file) with the model's
/// columns renamed, optionally a window of rows.
RoleRecord load_other(const RecordSource& src, const RolePlan& plan, const LpvModel<double>& declared,
                      const LpvModel<double>& renamed_from, const std::string& role) {
  const std::string& path = src.path.empty() ? plan.data_path : src.path;
  const std::vector<std::string>& names = src.path.empty() ? plan.names : src.names;
  const DataTable table = names.empty() ? read_data_table(path) : read_data_table(path, names);
  const ColumnMap columns = renamed_columns(renamed_from, declared, src.columns, "--" + role + "-columns");
  RoleRecord r{make_experiment<double>(table.table, columns), path, columns.y};
  if (!src.columns.empty()) {
    r.text += " columns ";
    for (size_t i = 0; i < src.columns.size(); ++i) r.text += (i ? "," : "") + src.columns[i];
  }
  if (src.rows) {
    const auto [b, e] = *src.rows;
    if (e > r.exp.n())
      throw InputError("--" + role + "-rows: the " + role + " data has " + std::to_string(r.exp.n()) + " rows");
    r.exp = select_rows(r.exp, b, e);
    r.text += " rows " + (src.rows_text.empty() ? rows_text(b, e) : src.rows_text);
  }
  return r;
}

/// The selection record taken from the estimation rows (folds: the last
/// block, shown only; holdout: the held-out tail, removed from the fit).
RoleRecord selection_from_estimation(const RolePlan& plan, RoleRecords& out) {
  RoleRecord r;
  if (plan.selection == SelectionRole::kFolds) {
    const std::vector<FoldBlock> blocks = blocked_folds(out.est_d.n(), plan.folds, plan.warmup);
    r.exp = select_rows(out.est_d, blocks.back().first, blocks.back().last);
    r.text = plan.data_path + " rows " + rows_text(out.file_offset + blocks.back().first, out.file_offset + blocks.back().last);
    return r;
  }
  const Eigen::Index n = out.est_d.n();
  const Eigen::Index cut = holdout_cut(n, plan.holdout);
  r.exp = select_rows(out.est_d, cut, n);
  out.est_d = select_rows(out.est_d, 0, cut);
  out.est_q = select_rows(out.est_q, 0, cut);
  r.text = plan.data_path + " rows " + rows_text(out.file_offset + cut, out.file_offset + n) + " (held out: the last " +
           std::to_string(n - cut) + " samples, not used to fit)";
  return r;
}

}  // namespace

RoleRecords load_role_records(const RolePlan& plan, const LpvModel<double>& declared, const LpvModel<double>& renamed_from) {
  RoleRecords out;
  const DataTable data = plan.names.empty() ? read_data_table(plan.data_path) : read_data_table(plan.data_path, plan.names);
  out.data = data.reference;
  out.est_q = make_experiment<Rational>(data.table, declared.columns);
  out.est_d = make_experiment<double>(data.table, declared.columns);
  if (plan.rows) {
    const auto [b, e] = *plan.rows;
    if (e > out.est_q.n())
      throw InputError("--rows " + rows_text(b, e) + ": the data has only " + std::to_string(out.est_q.n()) + " rows");
    out.est_q = select_rows(out.est_q, b, e);
    out.est_d = select_rows(out.est_d, b, e);
    out.file_offset = b;
  }
  out.selection = plan.selection == SelectionRole::kSeparate
                      ? load_other(plan.separate, plan, declared, renamed_from, "validation")
                      : selection_from_estimation(plan, out);
  for (const RecordSource& t : plan.tests) out.tests.push_back(load_other(t, plan, declared, renamed_from, "test"));
  out.estimation_text = plan.data_path + " rows " + rows_text(out.file_offset, out.file_offset + out.est_d.n()) +
                        " (fit: every model and candidate)";
  return out;
}

}  // namespace lpvid
