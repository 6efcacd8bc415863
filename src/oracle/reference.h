#pragma once
/// lpvid's own answer to an identify task, the reference its judge
/// (oracle/judge.h) holds an outside claim against: the identification of
/// Theorem 3.1 of "Robust identification and invalidation of LPV systems"
/// (iterated relaxation, θ fixed and certified: identify/fix_and_certify.h),
/// whose certified d_max² makes a claim above it "suboptimal", and its class
/// interval (identify/class_interval.h; in the convex case the class optimum
/// replaces lpvid's θ when it certifies lower), whose certified lower end
/// L_class refutes a claim below it for every θ of its region.

#include <string>

#include "certify/certificate_files.h"
#include "certify/certify.h"
#include "data/experiment.h"
#include "model/lpv_model.h"
#include "model/problem.h"
#include "oracle/judge.h"
#include "solvers/sdp_solver.h"

namespace lpvid {

struct IdentifiedReference {
  bool verified = false;    ///< lpvid's own identified model was certified
  Rational dmax2;           ///< ... with this d_max²
  std::string certificate;  ///< its certificate file
  ClassReference klass;     ///< the class lower end (or why there is none)
};

/// Identifies the task's model on the data at certify.objective (the task's
/// objective: min d_max at the fixed δ) and certifies the result and its
/// class lower end, the certificates written to `folder` as
/// lpvid.identify.cert.json and lpvid.class.json, their bytes added to
/// `written`.
/// With `class_bound` false no class interval is computed (no
/// lpvid.class.json; the class reference says why).
IdentifiedReference identify_reference(const Problem& problem, const CertifyOptions& certify, SdpSolver& solver,
                                       const std::string& folder, WrittenFiles& written, bool class_bound = true);

}  // namespace lpvid
