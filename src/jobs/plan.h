#pragma once
/// A long record past one machine: its windows are independent Theorem 2.1
/// problems, so `lpvid jobs plan` writes one `lpvid invalidate` command per
/// window (a job list any batch engine runs: GNU parallel, xargs -P, a Slurm
/// job array, an MPI launcher) and `lpvid jobs merge` compares every
/// certificate with the plan (jobs/window_check.h), re-checks it
/// exactly and assembles the report.
///
/// A window [b, e) of the record is certified for the model with its state
/// at b: the model's own state, simulated from its x0 over the record
/// (rounded to 12 significant digits and declared in the window's model
/// file, as `lpvid diagnose` does for its bound windows). What a window's
/// bound claims: on exactly these rows, this model with this initial state
/// explains the data with ‖Δ‖ ≤ δ and noise RMS ≤ d_max (Theorem 2.1). The
/// windows' Δ are separate; nothing is claimed across window borders.
///
/// `plan --joint` adds one job: every window as a record of ONE claim (one
/// Δ for all windows, acting on each from rest, and one noise bound on the
/// RMS over all their samples: Theorem 2.1 over several records), each
/// window from the x0 declared for it (`lpvid invalidate --data F --rows
/// b:e --x0 … --data F …`). Merge judges it beside the windows
/// (jobs/joint_check.h).

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace lpvid::jobs {

inline constexpr const char* kJobsFormat = "lpvid-jobs/1";

/// One window of a plan (file names relative to the plan's folder).
struct JobWindow {
  int index = 0;
  long file_begin = 0, file_end = 0;  ///< rows of the data file, [begin, end)
  std::string model, certificate, report;
  std::string command;  ///< the job's shell command line
  /// The window's initial state as exact text (the x0 its model file
  /// declares): merge compares every certificate's x0 with it.
  std::vector<std::string> x0;
};

/// The joint job of `plan --joint` (file names relative to the plan's folder).
struct JointJob {
  std::string command, certificate, report;
};

/// The plan: what `merge` needs to judge the certificates it finds.
struct JobPlan {
  std::string data_path;     ///< absolute
  std::string data_sha256;
  std::vector<std::string> data_names;
  std::string model_path;    ///< absolute (the model the windows derive from)
  std::string model_sha256;  ///< of the model file's bytes when planned
  std::string toeplitz;      ///< "signal" or "paper", as the jobs run
  std::string objective;     ///< min_dmax, min_delta, weighted or feasibility
  std::string delta_text, dmax_text, lambda_text;  ///< as given
  long window = 0, min_last = 0;
  std::vector<JobWindow> windows;
  std::optional<JointJob> joint;  ///< plan --joint
};

nlohmann::ordered_json plan_json(const JobPlan& plan);
/// Reads `dir`/plan.json; throws InputError naming the file and field.
JobPlan read_plan(const std::string& dir);

/// `text` quoted for a POSIX shell ('…', with ' written as '\'').
std::string shell_quote(const std::string& text);

}  // namespace lpvid::jobs
