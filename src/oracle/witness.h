#pragma once
/// The exact check of the witness an outside answer may carry (oracle/answer.h):
/// the primal point of Theorem 2.1 of "Robust identification and invalidation
/// of LPV systems" — the causal FIR Δ (taps, horizon) or the disturbance w —
/// is checked by the verifier's own code (verify/certificate/certificate_check.h)
/// at the claimed values δ and d_max (the task's fixed ones for the others),
/// on lpvid's exact copy of the data. A witness that holds shows the claim
/// attained; one that fails is shown to fail by a "not_a_witness"
/// certificate, itself checked, which the verdict names as its evidence
/// (oracle/judge.h, bad_witness).

#include <string>

#include "certify/certificate_files.h"
#include "core/scalar.h"
#include "data/data_reference.h"
#include "data/experiment.h"
#include "model/lpv_model.h"
#include "oracle/answer.h"
#include "oracle/task.h"

namespace lpvid {

/// The exact check of the answer's witness at the claimed values.
struct WitnessResult {
  enum Status { kNone, kHolds, kFails, kMalformed } status = kNone;
  std::string text;         ///< the verifier's words
  std::string certificate;  ///< kFails: the "not_a_witness" certificate (checked)
};

/// Checks `answer`'s witness (kNone without one) on `model` (identify: the
/// model with the claimed θ folded in) and the exact rows `exp` read from
/// `data`. A failing witness leaves its "not_a_witness" certificate in
/// `folder` as witness.not_a_witness.json, its bytes added to `written`.
WitnessResult judge_witness(const OracleTask& task, const OracleAnswer& answer, const LpvModel<Rational>& model,
                            const DataReference& data, const Experiment<Rational>& exp, const std::string& folder,
                            WrittenFiles& written);

}  // namespace lpvid
