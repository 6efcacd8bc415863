#pragma once
/// The certificate file (docs/design.md §10.1), JSON, "format": "lpvid-certificate/1".
///
///   {
///     "format": "lpvid-certificate/1",
///     "claim": "consistent",
///     "data": {"file": "D.csv",              // relative to the certificate's folder, or absolute
///              "sha256": "…",                // of the file's bytes
///              "names": ["u", "y"],          // only for headerless whitespace files
///              "rows": [begin, end]},        // optional window [begin, end) of the data rows
///     — or, for several records of one system under one Δ (docs/several_records.md),
///     "records": [{"file", "sha256", "names", "rows" as in "data", "x0": [record's own initial state,
///                  optional]}, …]  (two or more, instead of "data"),
///     "model": { … lpvid-model/1, with θ, φ and x0 folded in: no unknowns … },
///     "toeplitz_mode": "signal" | "paper",
///     "noise_normalisation": "rms",          // ‖d‖₂² ≤ n·ny·d_max²  (docs/design.md §7.4)
///     "delta2": "p/q" | decimal,  "dmax2": "p/q" | decimal,
///     "form": "delta" | "w",
///     "delta_taps": [[h_0 row-major], …, [h_{K−1}]]   // form "delta": K rows of ny·nz
///     "delta_horizon": L,                    // form "delta": taps act on z_{n−L} … z_{n−1}; K ≤ L
///     "w": [[w_0], …, [w_{n−1}]]                       // form "w": n rows of ny
///     "info": { … }                          // free, never read by the verifier
///   }
///
/// "claim": "not_a_witness" has the fields of "consistent" (the point under
/// judgement) and claims that this point fails (C1) or (C2).
///
/// Dual claims (docs/dual_certificates.md) use the same file:
///
///   "claim": "invalidated" | "lower_bound",
///   "toeplitz_mode": "signal",
///   "objective": "feasibility" | "min_delta" | "min_dmax" | "weighted",
///   "delta2": fixed δ² (feasibility, min_dmax), "dmax2": fixed d_max² (feasibility, min_delta),
///   "lambda": λ (weighted),
///   "lower_bound": the claimed lower end (lower_bound only): on δ² (min_delta),
///                  d_max² (min_dmax) or λδ² + (1−λ)d_max² (weighted),
///   "form": "dual_delta",
///   "dual": {"horizon": L,                   // must be n − (leading zero samples of z)
///            "sigma": σ,                     // > 0
///            "g": [[g_0 (ny)], …, [g_{n−1}]],
///            "Y1": [[row 0, columns 0…P−1], [row 1, columns 1…P−1], …]}  // upper triangle, P = L·(ny+nz)
///
/// or, linear in the record's length, "form": "dual_delta_path" with
///   "dual": {"horizon", "sigma", "g" as above,
///            "taps": [[h_0 row-major (ny·nz)], …, [h_{L−1}]],   // dyadic rationals
///            "t": t > 0, "mu": μ > 0, "u_exponent": e, "x": x > 0, "u_floor": γ ≥ 0}
/// (Y1 rebuilt by the verifier from U = round(μ(t·I − T Tᵀ)⁻¹·2^−e)·2^e:
/// verify/certificate/path_dual.h),
/// or, decided in closed form with no "dual" (verify/certificate/closed_form_check.h),
///   "form": "zero_delta"   (toeplitz_mode "signal" or "paper"; "delta2": 0): "lower_bound"
///                          with objective "min_dmax", or "invalidated" with "feasibility";
///   "form": "nonnegative"  "lower_bound" ≤ 0 with any of the three objectives.
///
/// Class claims (docs/class_lower_bound.md): a lower end of Theorem 3.1's
/// objective over every correction θ of a region (or "the data cannot be
/// explained at (δ, d_max) by any θ of the region"):
///
///   "claim": "class_lower_bound" | "class_invalidated",
///   "model": the INITIAL model with its correction basis (and unknown offsets),
///   "objective", "delta2", "dmax2", "lambda", "lower_bound" as for the dual claims,
///   "form": "dual_delta_path",
///   "class": {"unknowns": {"correction": b, "offset": b, "x0": b},
///             "parameters": [names of p, in order],        // checked against the exact build
///             "free": [indices: range over all reals; they must not move z],
///             "center": [P numbers], "radius": [P numbers],  // the box of the others
///             "horizon": L,                                  // n − (samples where z is 0 for every θ)
///             "nodes": [preorder tree: {"split": i} halves the box in coordinate i,
///                       {"leaf": {"epsilon": ε > 0, "expansion": [P numbers, optional], "horizon", "sigma", "g", "taps", "t", "mu",
///                                 "u_exponent", "x", "u_floor"}}]}
///
/// Every number is exact text (JSON number or string with a decimal or p/q).
/// Form "delta" (signal mode only) carries the causal FIR Δ of the Poolla
/// form: w = Δ ∗ z, and (C1) follows from ‖T_Δ‖ ≤ δ (see certificate_check.h).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/scalar.h"
#include "data/data_reference.h"
#include "model/lpv_model.h"
#include "toeplitz/affine_residual.h"
#include "toeplitz/delta_form_dual.h"
#include "toeplitz/uncertainty_toeplitz.h"
#include "verify/certificate/certificate.h"

namespace lpvid {

/// Reads and checks the structure (not the claim). Throws InputError with
/// "file:line: json.path: reason".
Certificate read_certificate(const std::string& path);
Certificate parse_certificate(std::string_view text, const std::string& name);

/// The JSON text of a certificate (exact numbers).
std::string certificate_json(const Certificate& c);
/// Writes the certificate as it is (its data file as recorded).
void write_certificate(const std::string& path, const Certificate& c);

/// Names the data in the certificate: file, sha256, names, rows of `data`
/// (data/data_reference.h). The file stays as it was opened until the
/// certificate is placed in a folder (placed_at).
void set_data_reference(Certificate& c, const DataReference& data);
/// Names the records (at least one; two or more: `x0` empty or one entry
/// per record, an empty entry meaning the model's x0; one record: its x0 is
/// the model's and `x0` is not used).
void set_record_references(Certificate& c, const std::vector<DataReference>& records,
                           const std::vector<Vec<Rational>>& x0 = {});
/// The certificate as it is written at `certificate_path`: its data file
/// relative to that file's folder (absolute when there is no relative path).
Certificate placed_at(Certificate c, const std::string& certificate_path);

}  // namespace lpvid
