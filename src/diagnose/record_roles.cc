#include "diagnose/record_roles.h"

#include <cstdio>

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
  RoleRecord r{make_experiment<double>(table.table, columns), path, columns};
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

/// One estimation record as read, both scalars, with the file row of its first sample.
struct ReadRecord {
  DataReference file;  ///< the whole file
  long offset = 0;
  Experiment<Rational> q;
  Experiment<double> d;
};

ReadRecord read_estimation(const std::string& path, const std::vector<std::string>& names,
                           const std::optional<std::pair<long, long>>& rows, const LpvModel<double>& declared) {
  const DataTable data = names.empty() ? read_data_table(path) : read_data_table(path, names);
  ReadRecord r{data.reference, 0, make_experiment<Rational>(data.table, declared.columns),
               make_experiment<double>(data.table, declared.columns)};
  if (rows) {
    const auto [b, e] = *rows;
    if (e > r.q.n())
      throw InputError("--rows " + rows_text(b, e) + ": " + path + " has only " + std::to_string(r.q.n()) + " rows");
    r.q = select_rows(r.q, b, e);
    r.d = select_rows(r.d, b, e);
    r.offset = b;
  }
  return r;
}

/// The held-out tail of every record (holdout_cut of each), removed from the fit.
RoleRecord hold_out_tails(const RolePlan& plan, std::vector<ReadRecord>& recs) {
  RoleRecord r;
  std::vector<Experiment<double>> tails;
  for (size_t k = 0; k < recs.size(); ++k) {
    ReadRecord& rec = recs[k];
    const Eigen::Index n = rec.q.n(), cut = holdout_cut(n, plan.holdout);
    tails.push_back(select_rows(rec.d, cut, n));
    rec.q = select_rows(rec.q, 0, cut);
    rec.d = select_rows(rec.d, 0, cut);
    r.text += (k ? "; " : "") + rec.file.file + " rows " + rows_text(rec.offset + cut, rec.offset + n);
    if (recs.size() == 1)
      r.text += " (held out: the last " + std::to_string(n - cut) + " samples, not used to fit)";
  }
  if (recs.size() > 1) {
    char share[32];
    std::snprintf(share, sizeof share, "%g", 100.0 * plan.holdout);
    r.text += std::string(" (held out: the last ") + share + " % of each record, not used to fit)";
  }
  r.exp = tails.size() == 1 ? tails[0] : stack_records(tails);
  return r;
}

/// The selection record taken from the estimation rows in fold mode: the
/// last block (shown, not a separate record).
RoleRecord last_fold_block(const RolePlan& plan, const RoleRecords& out) {
  RoleRecord r;
  const std::vector<FoldBlock> blocks = blocked_folds(out.est.exp_d.record_lengths(), plan.folds, plan.warmup);
  r.exp = select_rows(out.est.exp_d, blocks.back().first, blocks.back().last);
  const EstimationRecord& last = out.records.back();
  const long first_row = static_cast<long>(blocks.back().first - (out.est.exp_d.n() - last.samples));
  r.text = last.data.file + " rows " + rows_text(last.data.row_begin + first_row,
                                                 last.data.row_begin + first_row + (blocks.back().last - blocks.back().first));
  return r;
}

/// The estimation records stacked into `out` (est_q, est_d, records, texts).
void stack_estimation(const std::vector<ReadRecord>& recs, RoleRecords& out) {
  std::vector<Experiment<Rational>> q;
  std::vector<Experiment<double>> d;
  for (const ReadRecord& r : recs) {
    q.push_back(r.q);
    d.push_back(r.d);
    const long b = r.offset, e = r.offset + static_cast<long>(r.q.n());
    out.records.push_back({r.file.rows(b, e), r.q.n(), r.file.file + " rows " + rows_text(b, e)});
    out.estimation_text += (out.estimation_text.empty() ? "" : "; ") + out.records.back().text;
  }
  out.est.exp_q = stack_records(q);
  out.est.exp_d = stack_records(d);
  out.estimation_text += " (fit: every model and candidate)";
}

}  // namespace

RoleRecords load_role_records(const RolePlan& plan, const LpvModel<double>& declared, const LpvModel<double>& renamed_from) {
  RoleRecords out;
  std::vector<ReadRecord> recs{read_estimation(plan.data_path, plan.names, plan.rows, declared)};
  for (const RecordSource& m : plan.more_data) recs.push_back(read_estimation(m.path, m.names, m.rows, declared));
  if (plan.selection == SelectionRole::kHoldout) out.selection = hold_out_tails(plan, recs);
  stack_estimation(recs, out);
  if (plan.selection == SelectionRole::kFolds) out.selection = last_fold_block(plan, out);
  if (plan.selection == SelectionRole::kSeparate)
    out.selection = load_other(plan.separate, plan, declared, renamed_from, "validation");
  for (const RecordSource& t : plan.tests) out.tests.push_back(load_other(t, plan, declared, renamed_from, "test"));
  return out;
}

}  // namespace lpvid
