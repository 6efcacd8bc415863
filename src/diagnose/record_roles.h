#pragma once
/// The records of `lpvid diagnose` in their roles (docs/design.md §9): the estimation
/// record (every fit), the selection record (which effects are kept) and the
/// test records (scored once, at the end), read from the data files and
/// named for the report. One plan, three ways to select:
///
///   folds      K ≥ 2 blocked folds of the estimation record select
///              (diagnose/fold_plan.h); the last block is the record the
///              report's residual analysis shows;
///   separate   another file (or other columns / rows of the data file);
///   holdout    the last `holdout` share of the estimation rows is held out
///              (holdout_cut), the rest is fitted.
///
/// Test records are other files, other columns of the data file, or both,
/// each with an optional window of rows.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "data/column_map.h"
#include "data/data_reference.h"
#include "data/experiment_views.h"
#include "data/experiment.h"
#include "model/lpv_model.h"

namespace lpvid {

/// A record in the role of selection or test.
struct RecordSource {
  std::string path;                  ///< empty: the estimation data file (its names too)
  std::vector<std::string> names;    ///< headerless file
  std::vector<std::string> columns;  ///< replaces the model's u then y columns, in order (empty: as named)
  std::optional<std::pair<long, long>> rows;  ///< a window [begin, end) of its rows
  std::string rows_text;             ///< the window as given ("B:E"), for the description
};

/// A loaded record: the experiment, what it is called in the report (file,
/// columns, rows) and its column names (plot legends, the report's lines).
struct RoleRecord {
  Experiment<double> exp;
  std::string text;
  ColumnMap columns;  ///< its u, y and ρ column names (empty: the estimation record's)
};

enum class SelectionRole { kFolds, kSeparate, kHoldout };

struct RolePlan {
  std::string data_path;                       ///< the estimation data file
  std::vector<std::string> names;              ///< headerless estimation file
  std::optional<std::pair<long, long>> rows;   ///< the estimation window of the file
  SelectionRole selection = SelectionRole::kHoldout;
  int folds = 0;                               ///< kFolds: K
  Eigen::Index warmup = 0;                     ///< kFolds: each block's warm-up
  double holdout = 0.3;                        ///< kHoldout: the held-out share
  RecordSource separate;                       ///< kSeparate: where the selection record is
  std::vector<RecordSource> tests;
  /// Further estimation records (their files with optional `rows`, `names`;
  /// `columns` unused), stacked after the first as records of one
  /// experiment (data/experiment.h: records). Holdout then holds out the last
  /// share of EACH record; folds are made within the records (fold_plan.h).
  std::vector<RecordSource> more_data;
};

/// One estimation record as read: where its rows came from (file, sha256,
/// the window of its rows) and the description the report gives it.
struct EstimationRecord {
  DataReference data;   ///< rows: the window of the file that was fitted
  Eigen::Index samples = 0;
  std::string text;
};

struct RoleRecords {
  ExperimentViews est;               ///< the fitted rows, exactly (exp_q) and as doubles (exp_d)
  RoleRecord selection;              ///< kFolds: the last block (shown, not a separate record)
  std::vector<RoleRecord> tests;
  std::string estimation_text;       ///< "file rows a:b (fit: …)"
  /// Every estimation record in stacking order (at least one), each with its
  /// file rows after any holdout (its sha256 names the certificates' data);
  /// `est` holds them stacked (Experiment::records).
  std::vector<EstimationRecord> records;
};

/// Reads every record of the plan. `declared` names the columns of the
/// estimation record (with its scheduling columns); `renamed_from` is the
/// model whose u and y column names RecordSource::columns replace. Throws
/// InputError naming the option (--rows, --validation-rows, --test-rows,
/// --validation-columns, --test-columns) for a window or renaming that does
/// not fit.
RoleRecords load_role_records(const RolePlan& plan, const LpvModel<double>& declared, const LpvModel<double>& renamed_from);

/// The columns of `m` with the u then y columns of `from` replaced by
/// `renamed` (same count; empty: unchanged). Throws InputError naming `flag`.
ColumnMap renamed_columns(const LpvModel<double>& from, const LpvModel<double>& m, const std::vector<std::string>& renamed,
                          const std::string& flag);

}  // namespace lpvid
