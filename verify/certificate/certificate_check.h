#pragma once
/// Exact check of a certificate (docs/design.md §10.2): from the data text to the PSD
/// decision, in rational arithmetic, without tolerance and without solver.
///
///  1. the data file's bytes must hash to the certificate's sha256;
///  2. u, y, ρ are read as exact rationals, the window selected;
///  3. x, ŷ, z, Φ are rebuilt by exact simulation of the certificate's model
///     (docs/design.md §5, model/simulate.h);
///  4. w: form "w" as given; form "delta": w = Δ ∗ z exactly, which requires
///     z_k = 0 for every sample before the Δ horizon (k < n − L);
///  5. (C2): ‖d‖₂² ≤ n·ny·d_max², d = y − ŷ − Φ − w, exactly. This is the
///     LMI [n·ny·d_max², dᵀ; d, I] ⪰ 0 of docs/design.md §7.1 (Schur complement on I ≻ 0);
///  6. (C1): form "w": [T_zᵀT_z, T_wᵀ; T_w, δ²I] ⪰ 0 decided exactly, on
///     its Schur complement δ²T_zᵀT_z − T_wᵀT_w (n × n; w = 0 and δ² = 0
///     apart; verify/certificate/c1_check.h);
///     form "delta": [δ²I, T_Δ; T_Δᵀ, I] ⪰ 0 decided exactly, i.e.
///     ‖T_Δ‖ ≤ δ, on its Schur complement δ²I − T_ΔT_Δᵀ or δ²I − T_ΔᵀT_Δ
///     (size L·min(ny, nz), verify/certificate/c1_delta_form.cc); then T_w = T_Δ T_z and T_wᵀT_w = T_zᵀT_ΔᵀT_ΔT_z ⪯ δ²T_zᵀT_z,
///     which is (C1). (The taps before the horizon multiply zero samples.)
/// Any failure is "invalid" with the constraint, the index and the numbers.
/// Dual claims ("invalidated", "lower_bound") share steps 1–3 and continue in
/// verify/certificate/dual_check.h.

#include <string>

#include "data/data_reference.h"
#include "data/experiment.h"
#include "verify/certificate/certificate_file.h"
#include "verify/certificate/certificate_verdict.h"

namespace lpvid {

/// The data file a check reads: `data_file` when given; else the recorded
/// path (relative to `certificate_dir`) when it exists; else the file of the
/// same name beside the certificate when that exists (a certificate moved
/// together with its data). Any file may be named: only the certificate's
/// sha256 decides whether it is the data.
std::string certificate_data_path(const Certificate& c, const std::string& certificate_dir, const std::string& data_file = "");

/// The verifier's core, steps 3–6 (and the dual claims): checks `c` on the
/// exact rows it certifies — `exp` holds the window's u, y, ρ as read from the
/// data text (the "@x<i>" scheduling columns, if any, are recomputed from the
/// certified model). The data reference (file, sha256, rows) is not looked
/// at: that is the file layer below. Certification runs this on the
/// experiment it was given, before any file exists.
CertificateVerdict check_certificate(const Certificate& c, const Experiment<Rational>& exp);

/// The core on the certificate as a file would carry it: `c` written as its
/// JSON text, read back (parse errors name it `name`) and checked on `exp`.
/// What certification checks before any file exists, so that what is
/// written is what was checked.
CertificateVerdict check_round_trip(const Certificate& c, const Experiment<Rational>& exp, const std::string& name);

/// The file layer, steps 1–2 then the core: the data file's bytes must hash to
/// the certificate's sha256, its exact rows are parsed from those bytes and
/// the recorded window selected. `certificate_dir` resolves a relative data
/// path, `data_file` overrides it (certificate_data_path). Throws InputError
/// for unreadable data (missing file, bad numbers): that is not a verdict.
CertificateVerdict check_certificate(const Certificate& c, const std::string& certificate_dir, const std::string& data_file = "");

/// The file layer on data the caller read once (`lpvid jobs merge`: one
/// record, hundreds of window certificates): `data` is a table parsed from a
/// file's bytes together with their sha256 and the column names it was read
/// with (data/data_reference.h: read_data_table). Every data reference of
/// `c` (its "data", or each of its "records") must carry that sha256, else
/// the verdict is invalid ("has changed"); then its window's rows are taken
/// from the table (a reference naming other column names is read from the
/// file again) and the core checks them. Same verdicts as the path form on
/// that file; throws InputError for unreadable numbers.
CertificateVerdict check_certificate(const Certificate& c, const DataTable& data);

/// Reads the file and checks it.
CertificateVerdict check_certificate_file(const std::string& path, const std::string& data_file = "");

/// `lpvid-verify certificate C.json`: prints the claim that was checked,
/// "consistent", "invalidated" or "lower_bound <value>" (exit 0), or
/// "invalid: <reason>" (exit 1); exit 2 on unreadable input.
int run_certificate_command(const std::string& path, std::ostream& out, std::ostream& err, const std::string& data_file = "");

}  // namespace lpvid
