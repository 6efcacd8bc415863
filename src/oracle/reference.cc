#include "oracle/reference.h"

#include <filesystem>

#include "identify/class_interval.h"
#include "identify/fix_and_certify.h"

namespace lpvid {
namespace {

/// The class lower end of an identification's class interval, its
/// certificate written to `folder` (its bytes added to `written`).
ClassReference class_reference(const ClassInterval& ci, const std::filesystem::path& folder, WrittenFiles& written) {
  ClassReference k;
  const ClassBoundResult& b = ci.bound;
  if (!b.certified()) {
    k.reason = b.reason;
    return k;
  }
  k.verified = true;
  k.lower = b.lower;
  k.certificate = (folder / "lpvid.class.json").string();
  write_certificate_at(*b.certificate, k.certificate, &written);
  k.whole_class = b.whole_class;
  k.center = b.certificate->region.center;
  k.radius = b.certificate->region.radius;
  k.free = b.certificate->region.free;
  return k;
}

}  // namespace

IdentifiedReference identify_reference(const Problem& problem, const CertifyOptions& certify, SdpSolver& solver,
                                       const std::string& folder, WrittenFiles& written, bool class_bound) {
  IdentifiedReference ref;
  IdentifyOptions opt;
  opt.objective = certify.objective;
  opt.iterate = true;
  CertifyOptions co = certify;
  co.lower_end = false;
  IdentifiedModel id = identify_and_certify(problem, opt, co, solver);
  if (!id.bounds.verified()) {
    ref.klass.reason = "lpvid's own identification was not certified";
    return ref;
  }
  const std::filesystem::path dir(folder);
  if (class_bound) {
    ClassBoundOptions cbo;
    cbo.unknowns = opt.unknowns;
    ClassInterval ci = class_interval(id, problem, co, cbo, solver);
    adopt_class_optimum(id, ci);
    ref.klass = class_reference(ci, dir, written);
  } else {
    ref.klass.reason = "not computed (--no-class-bound)";
  }
  ref.verified = true;
  ref.dmax2 = id.bounds.dmax2;
  ref.certificate = write_certificates(id.bounds, (dir / "lpvid.identify.cert.json").string(), &written).certificate;
  return ref;
}

}  // namespace lpvid
