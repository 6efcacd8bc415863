#pragma once
/// `lpvid jobs merge` judges the joint job of `plan --joint` (every window
/// of the plan as a record of one claim) as it judges a window: the
/// certificate counts only when it claims exactly what the plan asks and
/// passes the exact check. Compared, as typed values:
///
///  - the records: as many as the plan's windows, in order, each with the
///    plan's data (sha256), the window's rows and, exactly, the x0 the plan
///    declared for the window (a certificate of one record, "data", is not
///    the joint claim);
///  - the Toeplitz mode, and the plan's model (its own x0 aside: each record
///    carries its own);
///  - the claim kind and the fixed values, as for a window
///    (certificate_claim_mismatch of jobs/window_check.h).
/// Anything else refuses the joint claim, with the reason.

#include <string>

#include "jobs/plan.h"
#include "jobs/window_check.h"

namespace lpvid::jobs {

/// Why `c` is not the plan's joint certificate ("" when it is). Values only;
/// the exact check is judge_joint's.
std::string joint_mismatch(const PlannedClaim& p, const JobPlan& plan, const LpvModel<Rational>& model,
                           const Certificate& c);

/// Reads the joint certificate at `certificate_path`, compares it with the
/// plan and checks it exactly (on `data`, the plan's data file read once by
/// the caller). Never throws for the job's file. `x0` of the result is left
/// empty (one per record).
WindowResult judge_joint(const PlannedClaim& p, const JobPlan& plan, const LpvModel<Rational>& model,
                         const std::string& certificate_path, const DataTable& data);

}  // namespace lpvid::jobs
