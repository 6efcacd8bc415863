#pragma once
/// Verified bounds of a fitted model on a window of a long record (docs/design.md §7,
/// §7). The LMIs of Theorem 2.1 have blocks of size ~2n, so
/// they are solved on a window [begin, end) of the estimation record, not on
/// all of it. The initial state of the window is the model's own state at
/// `begin` (simulated from the fitted x0 over the whole record): the state is
/// free (fitted), not assumed zero. The model's numbers are rounded to 12
/// significant digits and read as exact decimals; the window is certified by
/// certify/certify.h (Δ form, exact check of the certificate file).
///
/// What a verified bound means: on exactly these samples of this file, the
/// rounded model explains the data with an uncertainty ‖Δ‖ ≤ δ and noise
/// RMS ≤ d_max (Theorem 2.1); nothing is claimed for other samples.

#include <string>
#include <vector>

#include "data/experiment.h"
#include "data/experiment_views.h"
#include "certify/certify.h"
#include "diagnose/bound_windows.h"
#include "model/lpv_model.h"
#include "solvers/sdp_solver.h"

namespace lpvid {

struct WindowBounds {
  Eigen::Index begin = 0, end = 0;    ///< rows of the estimation record (0-based, end exclusive)
  long file_begin = 0, file_end = 0;  ///< the same rows of the data file
  /// A joint window over several records (diagnose/record_windows.h): its
  /// pieces (rows of the stacked estimation data; begin, end are the first
  /// piece's) and where each piece's rows are in its file. Empty: one record.
  std::vector<RowWindow> pieces;
  std::vector<DataReference> records;
  CertifiedBounds bounds;
  LpvModel<Rational> model;           ///< the exact model that was certified
  /// The file the front end wrote bounds.certificate to; empty unless the
  /// bound was verified (a bound stopped by the watchdog or refused by the
  /// exact check is reported with its reason, never with a file name).
  std::string certificate;
  /// A verified bound can still say nothing. The best CONSTANT model
  /// (ŷ = each output's mean on the window, Δ = 0) already meets
  /// d_max = rms_variation, the RMS of the measured output's deviation from
  /// its mean (all n·ny entries, the normalisation of docs/design.md §7.4); so the bound is
  /// informative only when it is verified and d_max < rms_variation. (The
  /// RMS of y itself, rms_output, includes the mean: an output around
  /// 100 °C would make almost any d_max look informative.) `note` says why not.
  double rms_output = 0;
  double rms_variation = 0;
  bool informative = false;
  std::string note;
};

/// Sets rms_output, informative and note from the bounds and the window's
/// measured output `y` (n × ny).
void judge_informative(WindowBounds& w, const Mat<double>& y);

/// The fitted model's slot values rounded to `digits` significant digits.
LpvModel<double> round_fitted_model(const LpvModel<double>& m, int digits = CertifyOptions{}.digits);

/// Exact (decimal) copy of a double model, x0 replaced by `x0`.
LpvModel<Rational> exact_model(const LpvModel<double>& m, const Vec<double>& x0);

/// Certifies `model` (fitted on `est.exp_d` with x0 at sample 0) on the
/// estimation rows [begin, end) of `est.exp_q`, which lie inside one record.
/// `options.records` (one reference per estimation record, each its rows as
/// read; empty: no file) is narrowed to the window's file rows
/// (piece_reference); `objective`, `solver`, `max_taps` are used as given.
WindowBounds certify_window(const LpvModel<double>& model, const ExperimentViews& est, Eigen::Index begin,
                            Eigen::Index end, CertifyOptions options, SdpSolver& solver);

/// Theorem 2.1 on a joint window of stacked records: ONE claim (one Δ, one
/// noise bound) over its pieces, each a record of its own, certified from the
/// model's state at the piece's first row (simulated record by record from
/// the fitted x0). `options.records` is where each estimation record's rows
/// are in its file (the window that was read); the certificate names each
/// piece's file rows. One piece: certify_window.
WindowBounds certify_joint_window(const LpvModel<double>& model, const ExperimentViews& est,
                                  const std::vector<RowWindow>& pieces, CertifyOptions options, SdpSolver& solver);

}  // namespace lpvid
