#pragma once
/// What `lpvid compare` computes (docs/compare.md): each model's output on
/// each record, scored against the measured output. A record's output is the
/// model's free run, or its k-step-ahead prediction (fit/k_step_prediction.h),
/// from the model's own x0 or from one fitted on the record
/// (fit_initial_state, fit/output_error_fit.h): on the warm-up rows, which
/// are then not scored, or on every compared row without them. The scores
/// are the RMS and fit % per output (fit/output_score.h), per record and
/// over every scored sample of every record (each record from its own x0).

#include <exception>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "data/experiment.h"
#include "fit/output_score.h"
#include "model/lpv_model.h"

namespace lpvid {

struct CompareOptions {
  bool fit_x0 = false;              ///< x0 fitted on each record (else the model's own)
  Eigen::Index warmup = 0;          ///< first rows of each record: x0 fitted there, not scored
  Eigen::Index predict = 0;         ///< K of the K-step-ahead prediction (0: the free run)
  Eigen::Index predict_window = 0;  ///< output rows each prediction's state is fitted on (0: the model's order)
};

/// One record: the table read from its file and the window of its rows
/// compared (none: every row). Each model reads its own columns of the table.
struct CompareRecord {
  std::string file;                           ///< the data file, as messages and results name it
  TextTable table;
  std::optional<std::pair<long, long>> rows;  ///< [begin, end) of the table's rows
  std::string rows_text;                      ///< the window as the user wrote it (messages)
};

/// One model on one record.
struct RecordComparison {
  std::string file;         ///< the record's data file
  long first = 0;           ///< the file row of the compared rows' row 0
  Eigen::Index skip = 0;    ///< warm-up rows (not scored)
  Experiment<double> exp;   ///< the compared rows, in the model's columns
  LpvModel<double> model;   ///< the model with the x0 it ran from (fitted, or its own)
  Mat<double> yhat;         ///< n × ny: the free run or the K-step prediction
  OutputScores scores;      ///< on the rows after the warm-up
};

/// One model on every record, and its scores pooled over them.
struct ModelComparison {
  std::string file;                   ///< the model file
  LpvModel<double> model;
  Eigen::Index state_window = 0;      ///< the K-step prediction's state window
  std::vector<RecordComparison> records;
  OutputScores pooled;                ///< every scored sample of every record
  Eigen::Index samples = 0;           ///< how many
};

/// The models compared, in order. A model that cannot be compared (its data
/// lacks a column it reads, a window outside the data, no initial state that
/// keeps its simulation finite) ends the comparison: `failure` holds why, and
/// `models` the models compared before it, so that a caller can show those
/// before the error.
struct CompareResult {
  std::vector<ModelComparison> models;
  std::exception_ptr failure;  ///< null when every model was compared
};

/// The state window of K-step prediction for `model`: the option, else the
/// model's order (at least 1).
Eigen::Index compare_state_window(const CompareOptions& options, const LpvModel<double>& model);

/// Compares models[i] (from the file model_files[i], named in messages) on
/// every record. The errors it keeps in `failure` are InputErrors naming
/// --rows and --warmup as `lpvid compare` takes them.
CompareResult compare_models(const std::vector<LpvModel<double>>& models, const std::vector<std::string>& model_files,
                             const std::vector<CompareRecord>& records, const CompareOptions& options);

}  // namespace lpvid
