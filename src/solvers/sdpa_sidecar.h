#pragma once
/// The JSON file written beside an SDPA file: what an
/// outside solver's variables mean, so that its answer can be read without
/// lpvid's source.
///
///     <file>.dat-s.json = {
///       "format": "lpvid-sdpa-sidecar/1",
///       "sdpa_file": "<file>.dat-s",               (name only: it sits beside)
///       "convention": "...",                       (SDPA's sign convention)
///       "about": { "kind": ..., "sigma_z": ..., ... },   (LmiProgram::about)
///       "variables": [ {"index": 1, "name": "h0[0,0]", "cost": ...}, ... ],
///       "blocks": [ {"index": 1, "name": "C1_delta_form", "size": 42, "diagonal": false}, ... ]
///     }
///
/// Indices are 1-based, as in the SDPA file. The same "about" pairs are also
/// comment lines of the SDPA file itself (sdpa_file.h), which is what
/// `lpvid certify --solution` reads; the sidecar is for people and other tools.

#include <string>

#include "solvers/lmi_program.h"

namespace lpvid {

/// "<sdpa_path>.json".
std::string sdpa_sidecar_path(const std::string& sdpa_path);

/// The sidecar's text for `program` written to `sdpa_path`.
std::string sdpa_sidecar_text(const LmiProgram& program, const std::string& sdpa_path);

/// Writes the SDPA file and its sidecar (write_sdpa_file + sdpa_sidecar_text).
void write_sdpa_with_sidecar(const LmiProgram& program, const std::string& sdpa_path);

}  // namespace lpvid
