#pragma once
/// Progress lines of a long check under `lpvid-verify`
/// ("[lpvid-verify   12.3 s] the exact simulation of 10000 rows"), on the
/// progress sink (core/progress_sink.h: standard error by default).
///
/// Only checks that run under lpvid-verify's work limits talk (the library's
/// own callers check the certificates they write unlimited, and stay
/// quiet: verify/psd/work_limits.h). A stage is announced when the step it
/// belongs to is estimated at kAnnouncedWork operations or more (about a
/// second on a 2-core machine) or when 5 s have passed since the last line,
/// so that a check of a few seconds prints nothing and a class tree of many
/// small leaves still says where it is. The clock only times the lines: no
/// decision reads it.

#include <string>

namespace lpvid {

/// Estimated operations from which a step's stages are announced.
inline constexpr double kAnnouncedWork = 4e9;

/// Restarts the check's clock and says whether its stages are announced
/// (start_total_work calls it for every check: talking under lpvid-verify's
/// limits, quiet when the check runs unlimited).
void start_check_progress(bool talking);

/// Announces `stage` of a step estimated at `step_work` operations.
void check_progress(double step_work, const std::string& stage);

}  // namespace lpvid
