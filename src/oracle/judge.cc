#include "oracle/judge.h"

#include <algorithm>
#include <optional>

#include "core/number_text.h"

namespace lpvid {

const char* to_string(OracleVerdict v) {
  switch (v) {
    case OracleVerdict::kConfirmed: return "confirmed";
    case OracleVerdict::kRefuted: return "refuted";
    case OracleVerdict::kBadWitness: return "bad_witness";
    case OracleVerdict::kSuboptimal: return "suboptimal";
    case OracleVerdict::kUndecided: return "undecided";
    case OracleVerdict::kError: return "error";
    case OracleVerdict::kTampered: return "tampered";
  }
  return "?";
}

ReferenceResult reference_of(const CertifiedBounds& b, const BoundObjective& objective, const CertificateFiles& files) {
  const std::string& certificate = files.certificate;
  ReferenceResult r;
  r.outcome = outcome_of(b, objective);  // b may be empty (no claim to certify): decided here, not stored
  r.upper_verified = b.verified();
  if (b.verified()) {
    r.upper = b.upper;
    r.upper_certificate = certificate;
  }
  if (b.lower.verified() && objective.kind != BoundObjective::Kind::kFeasibility) {
    r.lower_verified = true;
    r.lower = b.lower.value;
    r.lower_certificate = files.lower;
  }
  if (r.outcome == CertifyOutcome::kInvalidated) r.invalidation_certificate = certificate;
  if (!b.verified()) r.reason = b.reason;
  if (!b.lower.verified() && !b.lower.reason.empty()) r.reason += (r.reason.empty() ? "" : "; ") + b.lower.reason;
  return r;
}

namespace {

std::string approx(const Rational& q) { return double_to_text(CGAL::to_double(q)); }

Judgement verdict(OracleVerdict v, std::string reason, std::string evidence = "") {
  Judgement j;
  j.verdict = v;
  j.reason = std::move(reason);
  j.evidence = std::move(evidence);
  return j;
}

Judgement bad_witness(const WitnessResult& wit, const std::string& claim) {
  return verdict(OracleVerdict::kBadWitness,
                 claim + " is not shown false, but the witness fails the exact check at the claimed values: " + wit.text,
                 wit.certificate);
}

Judgement judge_bound(const OracleTask& task, const OracleAnswer& a, const ReferenceResult& ref, const WitnessResult& wit,
                      const JudgeTolerance& tol) {
  const Rational zero(0);
  const Rational J = objective_at(objective_of(task), a.delta ? *a.delta * *a.delta : zero, a.dmax ? *a.dmax * *a.dmax : zero);
  const std::string name = task.kind == TaskKind::kMinDelta ? "delta^2" : task.kind == TaskKind::kWeighted ? "objective" : "dmax^2";
  const std::string claim = "claimed " + name + " = " + approx(J);
  const auto with_claim = [&J](Judgement j) {
    j.claimed = J;
    return j;
  };
  if (ref.lower_verified && J < ref.lower)
    return with_claim(verdict(OracleVerdict::kRefuted,
                              claim + " is below lpvid's certified lower end " + approx(ref.lower) + " (its lower-end certificate)",
                              ref.lower_certificate));
  if (wit.status == WitnessResult::kFails) return with_claim(bad_witness(wit, claim));
  const Rational slack = Rational(1) + rational_from_text(double_to_text(tol.relative));
  const Rational floor = rational_from_text(double_to_text(tol.absolute));
  const std::string by_more = " by more than the tolerance " + double_to_text(tol.relative) + " (relative) + " +
                              double_to_text(tol.absolute) + " (absolute)";
  if (ref.upper_verified && J > ref.upper * slack + floor)
    return with_claim(verdict(OracleVerdict::kSuboptimal, claim + " is above lpvid's certified upper end " + approx(ref.upper) + by_more,
                              ref.upper_certificate));
  if (ref.identified_verified && J > ref.identified * slack + floor)
    return with_claim(verdict(OracleVerdict::kSuboptimal,
                              claim + " is above the d_max^2 = " + approx(ref.identified) +
                                  " of lpvid's own identified and certified model" + by_more,
                              ref.identified_certificate));
  const bool witnessed = wit.status == WitnessResult::kHolds;
  const std::string interval = "[" + (ref.lower_verified ? approx(ref.lower) : std::string("?")) + ", " +
                               (ref.upper_verified ? approx(ref.upper) : std::string("?")) + "]";
  if (ref.upper_verified && ref.lower_verified)
    return with_claim(verdict(OracleVerdict::kConfirmed,
                              claim + " lies in lpvid's certified interval " + interval + (witnessed ? "; the witness holds exactly" : ""),
                              ref.upper_certificate));
  if (witnessed)
    return with_claim(verdict(OracleVerdict::kConfirmed, claim + " is attained: the witness holds exactly; lpvid's interval " + interval));
  if (ref.upper_verified && J >= ref.upper)
    return with_claim(verdict(OracleVerdict::kConfirmed, claim + " is attained: lpvid's certificate holds at " + approx(ref.upper),
                              ref.upper_certificate));
  return with_claim(verdict(OracleVerdict::kUndecided, claim + ": lpvid's interval " + interval +
                                                            " cannot decide it (" + (ref.reason.empty() ? "no certified lower end" : ref.reason) + ")"));
}

/// identify: a claim below L_class with a θ of the class region is refuted by
/// the class certificate; `note` says why a claim below it is not.
std::optional<Judgement> refute_by_class(const OracleTask& task, const OracleAnswer& a, const ReferenceResult& ref,
                                         std::string& note) {
  const ClassReference& k = ref.klass;
  if (task.kind != TaskKind::kIdentify || !k.verified || !a.dmax) return std::nullopt;
  const Rational J = *a.dmax * *a.dmax;
  if (!(J < k.lower)) return std::nullopt;
  std::string why_not;
  if (!theta_in_class_region(a.theta, k, why_not)) {
    note = "claimed dmax^2 = " + approx(J) + " is below lpvid's class lower end " + approx(k.lower) +
           ", but not refutable by the class certificate: " + why_not;
    return std::nullopt;
  }
  Judgement j = verdict(OracleVerdict::kRefuted,
                        "claimed dmax^2 = " + approx(J) + " is below lpvid's certified class lower end " + approx(k.lower) +
                            ": no theta of " +
                            (k.whole_class ? std::string("the correction basis") : "the certified box, which contains the claimed theta,") +
                            " reaches it (class certificate)",
                        k.certificate);
  j.claimed = J;
  return j;
}

Judgement judge_decision(const OracleAnswer& a, const ReferenceResult& ref, const WitnessResult& wit) {
  const bool says_consistent = a.verdict == "consistent";
  if (ref.outcome == CertifyOutcome::kVerified && !says_consistent)
    return verdict(OracleVerdict::kRefuted, "claimed invalidated, but lpvid certifies consistent", ref.upper_certificate);
  if (ref.outcome == CertifyOutcome::kInvalidated && says_consistent)
    return verdict(OracleVerdict::kRefuted, "claimed consistent, but lpvid certifies invalidated", ref.invalidation_certificate);
  if (wit.status == WitnessResult::kFails) return bad_witness(wit, std::string("claimed ") + a.verdict);
  if (ref.outcome == CertifyOutcome::kVerified)
    return verdict(OracleVerdict::kConfirmed, "consistent, as lpvid certifies", ref.upper_certificate);
  if (ref.outcome == CertifyOutcome::kInvalidated)
    return verdict(OracleVerdict::kConfirmed, "invalidated, as lpvid certifies", ref.invalidation_certificate);
  if (wit.status == WitnessResult::kHolds) return verdict(OracleVerdict::kConfirmed, "consistent: the witness holds exactly");
  return verdict(OracleVerdict::kUndecided, std::string("claimed ") + a.verdict + "; lpvid could not certify either way (" +
                                                to_string(ref.outcome) + (ref.reason.empty() ? "" : ": " + ref.reason) + ")");
}

}  // namespace

Judgement judge(const OracleTask& task, const OracleAnswer& answer, const ReferenceResult& ref, const WitnessResult& witness,
                const JudgeTolerance& tolerance) {
  if (answer.failed) return verdict(OracleVerdict::kError, "the implementation reported failure" + (answer.message.empty() ? "" : ": " + answer.message));
  if (witness.status == WitnessResult::kMalformed) return verdict(OracleVerdict::kError, "malformed witness: " + witness.text);
  if (task.kind == TaskKind::kDecide) return judge_decision(answer, ref, witness);
  std::string note;
  if (std::optional<Judgement> j = refute_by_class(task, answer, ref, note)) return *j;
  Judgement j = judge_bound(task, answer, ref, witness, tolerance);
  if (!note.empty()) j.reason += "; " + note;
  return j;
}

bool theta_in_class_region(const Vec<Rational>& theta, const ClassReference& k, std::string& why_not) {
  const Eigen::Index P = k.center.size();
  if (theta.size() > P || k.radius.size() != P) {
    why_not = "theta has " + std::to_string(theta.size()) + " entries, the class " + std::to_string(P);
    return false;
  }
  for (Eigen::Index i = 0; i < P; ++i) {
    if (std::find(k.free.begin(), k.free.end(), static_cast<long>(i)) != k.free.end()) continue;
    const Rational value = i < theta.size() ? theta(i) : Rational(0);
    const Rational gap = value > k.center(i) ? value - k.center(i) : k.center(i) - value;
    if (gap > k.radius(i)) {
      why_not = "theta outside the certified box (parameter " + std::to_string(i + 1) + " is " + approx(gap) +
                " from the centre, half-width " + approx(k.radius(i)) + ")";
      return false;
    }
  }
  return true;
}

}  // namespace lpvid
