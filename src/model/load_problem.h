#pragma once
/// The model and the data of one claim read from their files: the model in
/// both views (exact and double, from the same text), each data file read
/// once (the sha256 of the bytes that are parsed), each record's row window
/// and initial state applied, and several records stacked side by side
/// (data/experiment.h: records). What every command of the command line
/// and `lpvid oracle`'s case runner read; the options that name the files
/// and windows are the caller's.

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/scalar.h"
#include "data/data_reference.h"
#include "model/problem.h"

namespace lpvid {

/// The initial state of a record for a model of `nx` states (called once
/// the model is read, after the record's rows: a caller that reads it from
/// text can only check it against the model).
using InitialState = std::function<Vec<Rational>(Eigen::Index nx)>;

/// One record to read: a data file, the window of its rows and its initial state.
struct RecordRequest {
  std::string path;
  /// Rows [b, e) of the file (0 <= b < e); none: every row. A table without
  /// rows ignores it (the experiment then says it has no data rows).
  std::optional<std::pair<long, long>> rows;
  /// The window as the caller names it in the error of a window past the
  /// file's end (e.g. "--rows 0:50"); empty: "rows b:e".
  std::string rows_name;
  /// Unset: the model's x0.
  InitialState x0;
};

/// The model and the stacked data (Problem), and where each record's rows
/// came from (file, sha256, names, rows), one per record in order.
struct LoadedProblem : Problem {
  std::vector<DataReference> records;
};

/// The bytes of the file at a path.
using FileBytes = std::function<std::string(const std::string& path)>;

/// The bytes on disk (core/file_io.h: read_text_file).
FileBytes bytes_on_disk();

/// The bytes held in memory under each path; a path not held is an
/// InputError (the file is never opened).
FileBytes bytes_held(const std::map<std::string, std::string>& held);

/// Reads the model at `model_path` and every record, each file's bytes from
/// `bytes_of` (a file named by several records is read and hashed once),
/// `names` the column names of headerless data files (every record). One
/// record's initial state replaces the model's x0 (in both views); several
/// records' go to Experiment::record_x0. Throws InputError naming the file
/// (a window past its end, records with different columns, ...).
LoadedProblem load_problem(const std::string& model_path, const std::vector<RecordRequest>& records,
                           const std::optional<std::vector<std::string>>& names, const FileBytes& bytes_of);

}  // namespace lpvid
