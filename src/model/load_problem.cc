#include "model/load_problem.h"

#include <algorithm>

#include "core/file_io.h"
#include "core/input_error.h"
#include "data/experiment_builder.h"
#include "model/model_file.h"

namespace lpvid {

FileBytes bytes_on_disk() {
  return [](const std::string& path) { return read_text_file(path); };
}

FileBytes bytes_held(const std::map<std::string, std::string>& held) {
  return [&held](const std::string& path) {
    const auto it = held.find(path);
    if (it == held.end()) throw InputError(path + ": not among the files held in memory");
    return it->second;
  };
}

namespace {

/// One record read (its file once) and its window applied.
struct LoadedRecord {
  Experiment<Rational> q;
  Experiment<double> d;
  DataReference ref;
  std::vector<std::string> header;
  Vec<Rational> x0;  ///< empty: the model's
};

/// One record from `data`: with a window only the window's cells are read
/// as numbers (a job of `lpvid jobs` reads 200 rows of a long record, not
/// all of them). `several`: the window's error names the record's file.
LoadedRecord load_record(const RecordRequest& r, bool several, const DataTable& data, const Problem& model) {
  TextTable window;
  DataReference ref = data.reference;
  const long rows = static_cast<long>(data.table.rows.size());
  const bool windowed = r.rows && rows > 0;  // an empty table: make_experiment says "no data rows"
  if (windowed) {
    const auto [b, e] = *r.rows;
    const std::string name = r.rows_name.empty() ? "rows " + std::to_string(b) + ":" + std::to_string(e) : r.rows_name;
    if (e > rows)
      throw InputError(name + ": " + (several ? r.path + " has" : std::string("the data has")) + " only " +
                       std::to_string(rows) + " rows");
    window = select_table_rows(data.table, b, e);
    ref = ref.rows(b, e);
  }
  const TextTable& table = windowed ? window : data.table;
  LoadedRecord rec{make_experiment<Rational>(table, model.model_q.columns), make_experiment<double>(table, model.model_d.columns),
                   ref, data.table.header, {}};
  if (r.x0) {
    rec.x0 = r.x0(model.model_q.nx);
    if (rec.x0.size() != model.model_q.nx)
      throw InputError(r.path + ": an initial state of " + std::to_string(rec.x0.size()) + " value(s), the model has " +
                       std::to_string(model.model_q.nx) + " state(s)");
  }
  return rec;
}

Vec<double> nearest_double_vec(const Vec<Rational>& v) {
  return v.size() ? Vec<double>(nearest_double(Mat<Rational>(v)).col(0)) : Vec<double>();
}

/// The initial states of the records: one record's replaces the model's x0
/// (its certificate keeps the one-record form); several records' go to
/// Experiment::record_x0 (an empty entry: the model's x0).
void set_initial_states(const std::vector<LoadedRecord>& recs, LoadedProblem& p) {
  const bool any = std::any_of(recs.begin(), recs.end(), [](const LoadedRecord& r) { return r.x0.size() != 0; });
  if (!any) return;
  if (recs.size() == 1) {
    p.model_q.x0 = recs.front().x0;
    p.model_d.x0 = nearest_double_vec(recs.front().x0);
    return;
  }
  for (const LoadedRecord& r : recs) {
    p.exp_q.record_x0.push_back(r.x0);
    p.exp_d.record_x0.push_back(nearest_double_vec(r.x0));
  }
}

/// The records side by side in `p` (exp_q, exp_d stacked; one reference each).
void stack_into(const std::vector<LoadedRecord>& recs, LoadedProblem& p) {
  std::vector<Experiment<Rational>> qs;
  std::vector<Experiment<double>> ds;
  for (const LoadedRecord& r : recs) {
    if (r.header.size() != recs[0].header.size())
      throw InputError(r.ref.file + ": " + std::to_string(r.header.size()) + " columns, but " + recs[0].ref.file + " has " +
                       std::to_string(recs[0].header.size()) + ": the records of one claim need the same columns");
    qs.push_back(r.q);
    ds.push_back(r.d);
    p.records.push_back(r.ref);
  }
  p.exp_q = stack_records(qs);
  p.exp_d = stack_records(ds);
  set_initial_states(recs, p);
}

}  // namespace

LoadedProblem load_problem(const std::string& model_path, const std::vector<RecordRequest>& records,
                           const std::optional<std::vector<std::string>>& names, const FileBytes& bytes_of) {
  LoadedProblem p;
  const std::string model_text = bytes_of(model_path);
  p.model_q = parse_model_json<Rational>(model_text, model_path);
  p.model_d = parse_model_json<double>(model_text, model_path);
  std::vector<LoadedRecord> recs;
  std::map<std::string, DataTable> files;  // several windows of one file (a joint job): read and hashed once
  for (const RecordRequest& r : records) {
    auto it = files.find(r.path);
    if (it == files.end()) it = files.emplace(r.path, parse_data_table(bytes_of(r.path), r.path, names)).first;
    recs.push_back(load_record(r, records.size() > 1, it->second, p));
  }
  stack_into(recs, p);
  return p;
}

}  // namespace lpvid
