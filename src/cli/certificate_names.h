#pragma once
/// Where the commands put their certificates: the library computes and
/// checks certificates in memory (certify/certify.h), the command line names
/// and writes them (certify/certificate_files.h writes one certification).
///
///  - diagnose: "<stem>.json" gives <stem>.before.json, <stem>.after.json
///    (".w<i>" before the side when there are several windows; lower ends
///    beside them as ".lower.json") and <stem>.before.thm31.json,
///    <stem>.after.thm31.json;
///  - select-basis: step k → <stem>.step<k>.cert.json (a step names it only
///    when consistent, a repeated basis its first step's file) and, when the
///    step has a class certificate ("cannot explain" over the class or a
///    box), <stem>.step<k>.class.json;
///  - tradeoff: point k (1-based) → <stem>.lambda<k>.cert.json.

#include <string>

#include "diagnose/diagnose.h"
#include "identify/basis_selection.h"
#include "identify/tradeoff.h"

namespace lpvid::cli {

/// The certificate file of one diagnose window and side.
std::string diagnose_certificate_path(const std::string& certificate_path, size_t window, size_t windows, bool after);

/// One diagnose window's certificates; names the file in w.certificate
/// (empty when the bound was not verified). Fits DiagnoseOptions::on_bound,
/// which calls it while the run goes.
void write_window_certificate(WindowBounds& w, const std::string& certificate_path, size_t window, size_t windows, bool after);

/// The certificates of a diagnose run not written yet: the windows not named
/// (write_window_certificate) and the two Theorem 3.1 windows.
void write_diagnose_certificates(DiagnoseResult& result, const std::string& certificate_path);

/// Every step's certificates of a basis selection, named as above.
void write_step_certificates(BasisSelectionResult& result, const std::string& stem);

/// Every trade-off point's certificates, named as above.
void write_tradeoff_certificates(std::vector<TradeoffPoint>& points, const std::string& stem);

}  // namespace lpvid::cli
