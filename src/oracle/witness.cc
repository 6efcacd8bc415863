#include "oracle/witness.h"

#include <filesystem>

#include "core/number_text.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/certificate_file.h"

namespace lpvid {
namespace {

/// The certificate the witness makes at the claimed values (the task's fixed
/// values for the others), claiming that the data are consistent.
Certificate witness_certificate(const OracleTask& task, const OracleAnswer& a, const LpvModel<Rational>& model,
                                const DataReference& data) {
  Certificate c;
  set_data_reference(c, data);
  c.model = model;
  c.mode = ToeplitzMode::kSignal;
  const Rational delta = task.delta.empty() ? *a.delta : rational_from_text(task.delta);
  const Rational dmax = task.dmax.empty() ? *a.dmax : rational_from_text(task.dmax);
  c.delta2 = delta * delta;
  c.dmax2 = dmax * dmax;
  if (a.witness->taps_form) {
    c.form = CertificateForm::kDelta;
    c.taps = a.witness->taps;
    c.horizon = a.witness->horizon;
  } else {
    c.form = CertificateForm::kW;
    c.w = a.witness->w;
  }
  c.info["tool"] = "lpvid oracle";
  c.info["meaning"] = "the outside implementation's witness, judged at its claimed values";
  return c;
}

}  // namespace

WitnessResult judge_witness(const OracleTask& task, const OracleAnswer& answer, const LpvModel<Rational>& model,
                            const DataReference& data, const Experiment<Rational>& exp, const std::string& folder,
                            WrittenFiles& written) {
  WitnessResult r;
  if (!answer.witness) return r;
  Certificate c = witness_certificate(task, answer, model, data);
  const CertificateVerdict holds = check_certificate(c, exp);
  if (holds.holds) {
    r.status = WitnessResult::kHolds;
    r.text = holds.details;
    return r;
  }
  c.claim = CertificateClaim::kNotAWitness;
  const CertificateVerdict fails = check_certificate(c, exp);
  if (!fails.holds) {
    r.status = WitnessResult::kMalformed;
    r.text = holds.reason;
    return r;
  }
  r.certificate = (std::filesystem::path(folder) / "witness.not_a_witness.json").string();
  write_certificate_at(c, r.certificate, &written);
  r.status = WitnessResult::kFails;
  r.text = holds.reason;
  return r;
}

}  // namespace lpvid
