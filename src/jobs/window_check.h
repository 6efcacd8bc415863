#pragma once
/// `lpvid jobs merge` trusts no job: a window counts only with certificates
/// that claim exactly what the plan asks for that window and pass the exact
/// check on the plan's data. Compared, as typed values:
///
///  - the data (sha256) and the rows [begin, end) of the window;
///  - the Toeplitz mode the jobs run in;
///  - the model, INCLUDING the x0 the plan declared for the window (a job
///    that edits its model file's x0 certifies another claim);
///  - the claim kind, by an allow-list: "consistent" (any objective) or
///    "invalidated" (only when the plan fixes both δ and d_max); any other
///    kind in place of the window's certificate (a lower end, not_a_witness,
///    class_lower_bound, class_invalidated) is refused, even when it holds;
///  - the fixed values, exactly: δ² (objective min_dmax, feasibility), d_max²
///    (min_delta, feasibility); a certificate at other values (a larger δ
///    making a window consistent, a smaller d_max invalidating it) is refused;
///  - the lower end (<certificate>.lower.json, when present): a lower bound on
///    the plan's objective — d_max² at the planned δ² (min_dmax), δ² at the
///    planned d_max² (min_delta), λδ² + (1−λ)d_max² at the planned λ
///    (weighted) — and no lower end at all when the plan fixes both.
/// Anything else refuses the whole window, with the reason. A certificate
/// that cannot be read (a broken link, not a file, bad JSON) refuses its
/// window only; a window with no certificate file is "missing".

#include <optional>
#include <string>

#include "jobs/plan.h"
#include "core/scalar.h"
#include "data/data_reference.h"
#include "lmi/bound_objective.h"
#include "model/lpv_model.h"
#include "toeplitz/uncertainty_toeplitz.h"
#include "verify/certificate/certificate_file.h"

namespace lpvid::jobs {

/// What the plan fixes for every window's certificates, exact.
struct PlannedClaim {
  std::string data_sha256;
  ToeplitzMode mode = ToeplitzMode::kSignal;
  BoundObjective::Kind objective = BoundObjective::Kind::kWeighted;
  std::optional<Rational> delta2, dmax2;  ///< the fixed ones
  Rational lambda;                        ///< weighted
};
PlannedClaim planned_claim(const JobPlan& plan);

/// The plan's kind name for an objective ("min_dmax", …) and back (throws
/// InputError for an unknown name).
const char* objective_name(BoundObjective::Kind kind);
BoundObjective::Kind objective_kind_of(const std::string& name);

/// The model a window's certificates must carry: the plan's model with the
/// window's declared x0 (throws InputError when x0 has the wrong size).
LpvModel<Rational> window_model(const LpvModel<Rational>& planned, const JobWindow& w);

/// The exact texts of `x0`, separated by spaces.
std::string exact_x0_text(const Vec<Rational>& x0);

/// "" when `have` is the `planned` model apart from x0, else the reason.
std::string model_besides_x0_mismatch(const LpvModel<Rational>& planned, const LpvModel<Rational>& have);

/// Why the claim of `c` (its kind and fixed δ², d_max²) is not what the plan
/// asks of a certificate ("" when it is).
std::string certificate_claim_mismatch(const PlannedClaim& p, const Certificate& c);

/// What a job left at a path: nothing, or a file, or something that cannot
/// be read as one (a link loop, a folder): `problem` says why.
struct FileState {
  bool missing = false;
  std::string problem;
};
FileState file_state(const std::string& path);

/// Which file of a window is judged.
enum class WindowFile { kCertificate, kLowerEnd };

/// Why `c` is not the certificate the plan asks for in window `w` ("" when
/// it is). Compares values only; the exact check is judge_window's.
std::string plan_mismatch(const PlannedClaim& plan, const JobWindow& w, const LpvModel<Rational>& model,
                          const Certificate& c, WindowFile file);

enum class WindowStatus { kVerified, kInvalidated, kMissing, kRefused };
/// "verified", "invalidated", "missing", "refused".
const char* to_string(WindowStatus s);

/// What merge found for one window.
struct WindowResult {
  WindowStatus status = WindowStatus::kMissing;
  std::string reason;             ///< refused, missing: why; else a note
  Rational delta2, dmax2, upper;  ///< verified
  bool has_lower = false;
  Rational lower;                 ///< the certified lower end of the objective
  std::string x0;                 ///< the window's x0, exact texts separated by spaces
};

/// Reads, compares with the plan and checks exactly (on `data`, the plan's
/// data file read once by the caller, its sha256 the plan's) the certificate
/// of window `w` at `certificate_path` and its lower end beside it. Never
/// throws for a job's file: an unreadable one refuses the window.
WindowResult judge_window(const PlannedClaim& plan, const JobWindow& w, const LpvModel<Rational>& model,
                          const std::string& certificate_path, const DataTable& data);

}  // namespace lpvid::jobs
