#pragma once
/// Each estimation record's free-run figures of the models before and after,
/// and the pooled figures of all records: the models are simulated record by
/// record (each from its own x0: the fits of several records give each one
/// its own, LpvModel::later_x0) and scored on the record's rows
/// (fit/output_score.h).

#include <vector>

#include "data/experiment.h"
#include "fit/output_score.h"
#include "model/lpv_model.h"

namespace lpvid {

/// One record's (or the pooled records') scores of the two models.
struct EstimationRecordScore {
  Eigen::Index samples = 0;
  OutputScores before, after;
  Vec<double> x0_before, x0_after;  ///< each model's initial state of the record (model/simulate.h record_start_state)
};


struct RecordScores {
  std::vector<EstimationRecordScore> records;  ///< one per record of the experiment, in order
  EstimationRecordScore pooled;                ///< every sample of every record
};

/// The scores of `before` and `after` on each record of `est` and pooled.
RecordScores score_records(const LpvModel<double>& before, const LpvModel<double>& after, const Experiment<double>& est);

}  // namespace lpvid
