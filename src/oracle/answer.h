#pragma once
/// The answer an outside implementation writes for a task (JSON,
/// "format": "lpvid-oracle-answer/1", docs/oracle_answer.schema.json):
///
///   {"format": "lpvid-oracle-answer/1",
///    "status": "ok",             // or "failed" (with "message"): no claim
///    "delta": "0.25",            // min_delta, weighted: the claimed optimal δ
///    "dmax": 0.0312,             // min_dmax, weighted, identify: the claimed optimal d_max
///    "theta": {"rho1": {"C": [[…]], "D": [[…]]}, …},  // identify: C_i, D_i per
///                                // correction basis function (as `lpvid identify` reports θ)
///    "verdict": "consistent",    // decide: "consistent" or "invalidated"
///    "witness": {"delta_taps": [[h_0 row-major ny·nz], …], "delta_horizon": L}
///            or {"w": [[w_0 (ny)], …, [w_{n−1}]]},
///    "message": "…"}             // free text
///
/// Numbers are read exactly (a JSON number or a string holding a decimal or
/// p/q). The witness is optional; with it, a claim is checked at the claimed
/// values themselves (verify/certificate/certificate_check.h), not only against lpvid's
/// interval.

#include <optional>
#include <string>

#include "core/scalar.h"
#include "model/lpv_model.h"
#include "oracle/task.h"

namespace lpvid {

inline constexpr const char* kOracleAnswerFormat = "lpvid-oracle-answer/1";

/// The primal point an answer may carry: the causal FIR Δ (taps, horizon) or w.
struct Witness {
  bool taps_form = true;
  Mat<Rational> taps;  ///< K × (ny·nz)
  long horizon = 0;    ///< L
  Mat<Rational> w;     ///< n × ny
};

struct OracleAnswer {
  bool failed = false;                  ///< "status": "failed": the implementation gave no claim
  std::optional<Rational> delta, dmax;  ///< the claimed values (as needed by the task kind)
  std::string verdict;                  ///< decide: "consistent" or "invalidated"
  std::optional<Witness> witness;
  Vec<Rational> theta;  ///< identify: C_i, D_i in output_correction_layout order (model/simulate.h)
  std::string message;
};

/// Reads and checks an answer to `task` on `model` (sizes, correction basis)
/// (throws InputError "file:line: field: reason").
OracleAnswer parse_answer(std::string_view text, const std::string& file, const OracleTask& task,
                          const LpvModel<Rational>& model);

}  // namespace lpvid
