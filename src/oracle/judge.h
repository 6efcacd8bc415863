#pragma once
/// The oracle's verdict on one outside answer (the judging rules of
/// `lpvid oracle`, docs/oracle.md). lpvid certifies the task
/// itself — an interval [L, U] of the optimum (U from a primal certificate, L
/// from a dual one), or "consistent"/"invalidated" at fixed bounds — and
/// checks a witness, when the answer has one, exactly at the claimed values.
///
///  - refuted: the claim is impossible, with a certificate lpvid-verify
///    accepts: a claimed optimum J < L (the lower-end certificate), or a
///    verdict contradicting lpvid's certified one (lpvid's certificate);
///  - bad_witness: the claim is not shown false, but the witness attached to
///    it fails the exact check at the claimed values (a "not_a_witness"
///    certificate): the answer's proof is wrong, not necessarily its number;
///  - suboptimal: J > U·(1 + tolerance) + floor (lpvid's primal certificate
///    shows a better value); identify: also J above lpvid's own identified
///    and certified d_max² by more than that;
///  - confirmed: L ≤ J ≤ U·(1 + tolerance) + floor with both ends certified;
///    or a witness that holds exactly at the claimed values (J is attained;
///    it may even be below lpvid's own U); or J ≥ U (attained by lpvid's
///    certificate); or a verdict equal to lpvid's certified one;
///  - undecided: lpvid could not certify enough to decide (never counted as
///    an outside error);
///  - error: no usable answer (the command failed, timed out, or wrote a
///    malformed answer or witness);
///  - tampered: a file of the case lpvid holds in memory (an input of
///    either copy, one of lpvid's certificates) changed, or a process of the
///    command was still running after it ended; nothing it answered is
///    judged (set by the case runner, oracle/case_runner.h).
/// J is the task's objective at the claim: d_max² (min_dmax, identify), δ²
/// (min_delta), λδ² + (1−λ)d_max² (weighted). The tolerance comes from the
/// oracle's command line, never from a file the command under test can edit.
/// identify: the claim (θ, d_max) is judged first against lpvid's class
/// interval [L_class, U] (identify/class_bound.h, docs/class_lower_bound.md):
/// L_class is certified for every θ of a region — the whole correction class
/// when no correction moves z (additive structure: Theorem 3.1 is convex),
/// else a box around lpvid's own identified θ (multiplicative: a BMI) — so a
/// claimed d_max² below L_class with a θ of that region is refuted by the
/// class certificate whatever the θ. A claimed θ outside the box is not
/// refutable by it (said in the reason). Then the claim is judged as the
/// fixed model with θ folded in: [L, U] is that model's certified interval,
/// and a refutation there proves that THIS θ cannot explain the data with the
/// claimed d_max at δ.

#include <optional>
#include <string>

#include "core/scalar.h"
#include "certify/certificate_files.h"
#include "certify/certify.h"
#include "oracle/answer.h"
#include "oracle/task.h"
#include "oracle/witness.h"

namespace lpvid {

enum class OracleVerdict { kConfirmed, kRefuted, kBadWitness, kSuboptimal, kUndecided, kError, kTampered };

/// "confirmed", "refuted", "bad_witness", "suboptimal", "undecided", "error", "tampered".
const char* to_string(OracleVerdict v);

/// How much worse than lpvid's certified upper end U an optimum may be and
/// still be confirmed: J ≤ U·(1 + relative) + absolute. The absolute floor
/// keeps a correct answer to a zero optimum (a solver's 1e-11 against
/// lpvid's 1e-26) from being called suboptimal; it is in the objective's own
/// units (d_max², δ² or the weighted sum).
struct JudgeTolerance {
  double relative = 0.01;
  double absolute = 1e-9;
};

/// identify: lpvid's certified class lower end on d_max² at the task's δ,
/// over every θ of the region its certificate states.
struct ClassReference {
  bool verified = false;
  Rational lower;                ///< L_class
  std::string certificate;       ///< its file ("class_lower_bound", checked again before a refutation)
  bool whole_class = false;      ///< no parameter boxed: the region is every θ of the basis
  /// The region in the class's parameter layout (θ_out first, as the answer's
  /// theta; then θ_unc, φ, x0): the box's centre and half-widths, and the free
  /// parameters (any real).
  Vec<Rational> center, radius;
  std::vector<long> free;
  std::string reason;            ///< why there is none
};

/// Whether the answer's θ (output correction; the class's other parameters
/// taken as 0, the free ones as anything) lies in the class region; else why not.
bool theta_in_class_region(const Vec<Rational>& theta, const ClassReference& klass, std::string& why_not);

/// What lpvid certified for the task (from CertifiedBounds).
struct ReferenceResult {
  CertifyOutcome outcome = CertifyOutcome::kNotVerified;
  bool upper_verified = false;
  Rational upper;                 ///< the objective at lpvid's primal certificate
  std::string upper_certificate;  ///< also the "consistent" certificate of a decide task
  bool lower_verified = false;
  Rational lower;
  std::string lower_certificate;
  std::string invalidation_certificate;  ///< decide: the "invalidated" certificate
  ClassReference klass;                  ///< identify: the class lower end
  bool identified_verified = false;      ///< identify: lpvid's own identified model was certified
  Rational identified;                   ///< ... with this d_max²
  std::string identified_certificate;
  std::string reason;                    ///< why lpvid certified less than both ends
};

/// The reference of a task from lpvid's certified bounds and the files its
/// certificates were written to.
ReferenceResult reference_of(const CertifiedBounds& b, const BoundObjective& objective, const CertificateFiles& files);

struct Judgement {
  OracleVerdict verdict = OracleVerdict::kUndecided;
  std::string reason;
  std::string evidence;        ///< the certificate file behind refuted/suboptimal/confirmed, if any
  std::optional<Rational> claimed;  ///< J (bound tasks)
};

Judgement judge(const OracleTask& task, const OracleAnswer& answer, const ReferenceResult& ref,
                const WitnessResult& witness, const JudgeTolerance& tolerance = {});

}  // namespace lpvid
