#pragma once
/// `lpvid jobs merge` as one library call: the plan of a folder, every
/// window's certificates judged against it (jobs/window_check.h), the joint
/// claim of `plan --joint` (jobs/joint_check.h), the exact summary over the
/// verified windows and one typed verdict. The command line only renders it.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/scalar.h"
#include "jobs/plan.h"
#include "jobs/window_check.h"

namespace lpvid::jobs {

/// What a merge says about the plan's claims, as a whole.
enum class MergeVerdict {
  kConsistent,    ///< every window (and the joint claim) verified by a certificate that passed
  kInvalidated,   ///< a passing certificate invalidates a window (or the joint claim)
  kNotVerified,   ///< none invalidated, but a window (or the joint claim) is missing or refused
  kDataChanged,   ///< the data file is not the one planned (sha256 differs): nothing judged
  kModelChanged,  ///< the model file is not the one planned (sha256 differs): nothing judged
};
/// "consistent", "invalidated", "not_verified", "data_changed", "model_changed".
const char* to_string(MergeVerdict v);

/// One window of the plan and what merge found for it.
struct MergedWindow {
  JobWindow w;
  WindowResult r;
};

/// How many claims have each status.
struct StatusCounts {
  size_t verified = 0, invalidated = 0, missing = 0, refused = 0;
  void add(WindowStatus s);
};

/// Over the verified windows, exact.
struct VerifiedSummary {
  long samples = 0;                             ///< rows of the verified windows
  Rational worst_upper, worst_dmax2, worst_delta2;
  Rational record_dmax2;                        ///< Σ n_k d_k² / Σ n_k: the noise RMS² over them is at most this
  bool any_lower = false;
  Rational best_lower;                          ///< the largest certified lower end of the objective
};

struct MergeResult {
  JobPlan plan;
  MergeVerdict verdict = MergeVerdict::kNotVerified;
  std::string changed;                 ///< kDataChanged, kModelChanged: which file, why
  std::vector<MergedWindow> windows;
  StatusCounts counts;                 ///< of the windows
  VerifiedSummary summary;             ///< when counts.verified > 0
  std::optional<WindowResult> joint;   ///< plan --joint
};

/// The verdict of judged windows and joint claim (none changed).
MergeVerdict merge_verdict(const std::vector<MergedWindow>& windows, const std::optional<WindowResult>& joint);

/// The summary over the verified ones of `windows`.
VerifiedSummary verified_summary(const std::vector<MergedWindow>& windows);

/// Reads `dir`/plan.json (throws InputError for a bad plan), checks that the
/// planned data and model files are unchanged (else the verdict says which,
/// and nothing is judged), then judges every window and the joint claim.
/// `progress(done, total)` is called after each window.
MergeResult merge_jobs(const std::string& dir, const std::function<void(size_t, size_t)>& progress = {});

}  // namespace lpvid::jobs
