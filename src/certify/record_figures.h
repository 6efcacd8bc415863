#pragma once
/// The figures of each record of a several-record run (docs/several_records.md)
/// and of all records pooled: the residual r_k = y_k − (model output)_k of
/// record k (ŷ_k + Φ_k through the model's static output block, the residual
/// the certification bounds), its RMS and fit %, and, with a consistency
/// certificate, the noise d_k = r_k − w_k left by the certificate's Δ
/// (w_k = Δ ∗ z_k record by record, from rest), its RMS and its share of the
/// pooled noise energy.

#include <optional>
#include <vector>

#include "certify/certify_types.h"
#include "data/experiment.h"
#include "model/lpv_model.h"

namespace lpvid {

struct RecordFigures {
  long samples = 0;
  double rms_residual = 0;  ///< sqrt(‖r‖² / (samples·ny))
  double fit_percent = 0;   ///< 100·(1 − ‖r‖/‖y − mean(y)‖), mean per output column
  std::optional<double> rms_noise;   ///< sqrt(‖d‖² / (samples·ny)), d = r − w
  std::optional<double> dmax_share;  ///< ‖d_k‖²/‖d‖² (the pooled line: 1)
};

struct RecordTable {
  std::vector<RecordFigures> records;  ///< one per record, in order
  RecordFigures pooled;                ///< every sample of every record
};

/// The figures of y, r (and w when given), stacked n × ny, cut into records of
/// `lengths` (empty: one record).
RecordTable record_figures(const Mat<double>& y, const Mat<double>& r, const std::vector<Eigen::Index>& lengths,
                           const std::optional<Mat<double>>& w);

/// The figures of `model` on `exp` (simulated record by record) with the noise
/// of `b`'s consistency certificate (Δ form) when there is one.
RecordTable record_figures(const LpvModel<double>& model, const Experiment<double>& exp, const CertifiedBounds& b);

}  // namespace lpvid
