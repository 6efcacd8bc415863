#pragma once
/// The certificate file (SPEC §7), JSON, "format": "lpvid-certificate/1".
///
///   {
///     "format": "lpvid-certificate/1",
///     "claim": "consistent",
///     "data": {"file": "D.csv",              // relative to the certificate's folder, or absolute
///              "sha256": "…",                // of the file's bytes
///              "names": ["u", "y"],          // only for headerless whitespace files
///              "rows": [begin, end]},        // optional window [begin, end) of the data rows
///     "model": { … lpvid-model/1, with θ, φ and x0 folded in: no unknowns … },
///     "toeplitz_mode": "signal" | "paper",
///     "noise_normalisation": "rms",          // ‖d‖₂² ≤ n·ny·d_max²  (SPEC §4)
///     "delta2": "p/q" | decimal,  "dmax2": "p/q" | decimal,
///     "form": "delta" | "w",
///     "delta_taps": [[h_0 row-major], …, [h_{K−1}]]   // form "delta": K rows of ny·nz
///     "delta_horizon": L,                    // form "delta": taps act on z_{n−L} … z_{n−1}; K ≤ L
///     "w": [[w_0], …, [w_{n−1}]]                       // form "w": n rows of ny
///     "info": { … }                          // free, never read by the verifier
///   }
///
/// Every number is exact text (JSON number or string with a decimal or p/q).
/// Form "delta" (signal mode only) carries the causal FIR Δ of the Poolla
/// form: w = Δ ∗ z, and (C1) follows from ‖T_Δ‖ ≤ δ (see certificate_check.h).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/scalar.h"
#include "model/lpv_model.h"
#include "toeplitz/uncertainty_toeplitz.h"

namespace lpvid {

inline constexpr const char* kCertificateFormat = "lpvid-certificate/1";

enum class CertificateForm { kDelta, kW };

struct Certificate {
  std::string data_file;                ///< as written in the file
  std::string data_sha256;
  std::vector<std::string> data_names;  ///< headerless files only
  long row_begin = 0, row_end = -1;     ///< window [begin, end); end = -1: to the last row
  LpvModel<Rational> model;
  ToeplitzMode mode = ToeplitzMode::kSignal;
  CertificateForm form = CertificateForm::kDelta;
  Rational delta2, dmax2;
  Mat<Rational> taps;  ///< K × (ny·nz), form kDelta (h_K … h_{L−1} = 0)
  long horizon = 0;    ///< L, form kDelta
  Mat<Rational> w;     ///< n × ny, form kW
  nlohmann::ordered_json info = nlohmann::ordered_json::object();
};

/// Reads and checks the structure (not the claim). Throws InputError with
/// "file:line: json.path: reason".
Certificate read_certificate(const std::string& path);
Certificate parse_certificate(std::string_view text, const std::string& name);

/// The JSON text of a certificate (exact numbers).
std::string certificate_json(const Certificate& c);
void write_certificate(const std::string& path, const Certificate& c);

}  // namespace lpvid
