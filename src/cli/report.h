#pragma once
/// The report (docs/design.md §11.4): JSON (written by --report) and a readable form.

#include <string>

#include <nlohmann/json.hpp>

#include "core/exit_codes.h"
#include "toeplitz/affine_residual.h"
#include "certify/certificate_files.h"
#include "certify/certify.h"
#include "lmi/bound_objective.h"
#include "model/lpv_model.h"

namespace lpvid::cli {

/// Exit codes: core/exit_codes.h (one table for both programs).
using lpvid::ExitCode;
using lpvid::kExitOk;
using lpvid::kExitInvalidated;
using lpvid::kExitBadInput;
using lpvid::kExitSolver;
using lpvid::kExitNotVerified;
using lpvid::kExitUndecided;
using lpvid::kExitIo;

/// The exit code of a certification's outcome (0, 1, 5, 3, 4).
int exit_code(CertifyOutcome outcome);

/// The common fields: status, delta, dmax (only when verified), the exact
/// δ²/d_max², noise_normalisation, toeplitz_mode, solver, certificate, verified.
nlohmann::ordered_json bounds_json(const CertifiedBounds& b, const std::string& toeplitz_mode,
                                   const std::string& solver, const CertificateFiles& files);

/// θ (the correction matrices) by basis term, φ and x0, from parameters p.
nlohmann::ordered_json theta_json(const LpvModel<double>& model, const ParameterLayout& layout, const Vec<double>& p);

/// Writes JSON to path (if non-empty); throws InputError when it cannot.
void write_json(const std::string& path, const nlohmann::ordered_json& j);

/// The certified interval of the objective (the upper end from a primal
/// certificate, the lower end from a dual one): lower, upper, relative_gap,
/// lower_verified, upper_verified, the lower end's certificate.
nlohmann::ordered_json interval_json(const CertifiedBounds& b, const BoundObjective& objective, const CertificateFiles& files);

/// Readable lines for the bounds ("delta <= ... (verified)").
/// `scope`, when not empty, says what the interval's lower end is a bound
/// FOR (identify: the model with the identified θ fixed, not the class).
/// What the commands print when no certificate file was named.
inline constexpr const char* kNoCertificateFile = "no certificate file written (name one with --certificate FILE)";

/// write_certificates at `path`, or nothing (empty names) when `path` is ""
/// (named_certificate_path: the user named no file).
CertificateFiles write_named_certificates(const CertifiedBounds& b, const std::string& path);

std::string bounds_text(const CertifiedBounds& b, const CertificateFiles& files, const std::string& scope = "");

/// A table cell of the tradeoff and select-basis tables: x with 6
/// significant digits, "-" for a negative x (not computed).
std::string cell_text(double x);

}  // namespace lpvid::cli
