#include "verify/certificate/certificate_check.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <map>
#include <ostream>
#include <sstream>

#include "core/decimal_rounding.h"
#include "core/exit_codes.h"
#include "core/file_io.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "core/sha256.h"
#include "core/stop_request.h"
#include "data/csv_reader.h"
#include "data/experiment_builder.h"
#include "model/simulate.h"
#include "toeplitz/fir.h"
#include "toeplitz/record_segments.h"
#include "toeplitz/uncertainty_toeplitz.h"
#include "toeplitz/toeplitz_gram.h"
#include "verify/certificate/c1_check.h"
#include "verify/certificate/class_check.h"
#include "verify/certificate/closed_form_check.h"
#include "verify/certificate/column_gram.h"
#include "verify/certificate/data_file_cache.h"
#include "verify/certificate/dual_check.h"
#include "verify/certificate/verdict_text.h"
#include "verify/certificate/work_budget.h"
#include "verify/psd/work_limits.h"

namespace lpvid {
namespace {

/// T_zᵀT_z of the paper mode, T_z = T_G12·T_u (uncertainty_toeplitz.h).
Mat<Rational> paper_gram(const LpvModel<Rational>& model, const Experiment<Rational>& exp) {
  return column_gram(T_z_paper(model, exp));
}

}  // namespace

namespace {
/// The exact check of a primal point (steps 4–6).
struct PrimalCheck {
  enum Result { kHolds, kConditionFails, kMalformed } result = kMalformed;
  std::string reason;  ///< the failing condition or the malformation
  std::string text;    ///< what was checked (details)
};
PrimalCheck check_primal_point(const Certificate& c, const Experiment<Rational>& exp, const Simulation<Rational>& sim,
                               std::ostringstream& details);
CertificateVerdict with_claim(CertificateVerdict v, const Certificate& c);
}  // namespace

namespace {
/// Where a recorded data file is: relative to the certificate's folder, or,
/// moved together with its data, the file of the same name beside the certificate.
std::string recorded_data_path(const std::string& file, const std::string& certificate_dir) {
  namespace fs = std::filesystem;
  fs::path recorded(file);
  if (recorded.is_relative()) recorded = fs::path(certificate_dir) / recorded;
  std::error_code ec;
  if (fs::exists(recorded, ec)) return recorded.string();
  const fs::path beside = fs::path(certificate_dir) / fs::path(file).filename();
  return fs::exists(beside, ec) ? beside.string() : recorded.string();
}
}  // namespace

std::string certificate_data_path(const Certificate& c, const std::string& certificate_dir, const std::string& data_file) {
  if (!data_file.empty() || c.records.empty()) return data_file;
  return recorded_data_path(c.records.front().data.file, certificate_dir);
}

namespace {
/// Steps 1–2 (the file layer): the data file's bytes against the
/// certificate's sha256, then the exact rows it names, parsed from the same
/// bytes that were hashed (a second read could see another file: swapping
/// it between the reads passed a false claim).
struct CertificateData {
  std::string invalid;  ///< why the data does not fit the certificate (empty: it does)
  std::string path;
  Experiment<Rational> exp;
};
/// Step 2 on a table parsed from bytes whose sha256 matched: the recorded
/// window's exact rows (only their cells are read as numbers).
CertificateData window_rows(const DataReference& ref, const TextTable& table, const ColumnMap& columns, const std::string& what,
                            CertificateData out) {
  const auto rows = static_cast<long>(table.rows.size());
  if (ref.row_end < 0 || rows == 0) {  // the whole file (an empty one: make_experiment says "no data rows")
    out.exp = make_experiment<Rational>(table, columns);
    return out;
  }
  if (ref.row_end > rows) {
    out.invalid = what + ".rows ends at " + std::to_string(ref.row_end) + " but the data has " + std::to_string(rows) + " rows";
    return out;
  }
  out.exp = make_experiment<Rational>(select_table_rows(table, ref.row_begin, ref.row_end), columns);
  return out;
}

/// One reference's table before its rows are read as numbers: parsed from
/// bytes whose sha256 matched (`invalid` says why not).
struct ReferenceTable {
  std::string invalid;
  std::string path;
  const TextTable* table = nullptr;
};
using TableSource = std::function<ReferenceTable(const DataReference&)>;

/// A data file through `cache` (read, hashed and parsed once per check).
ReferenceTable file_table(const DataReference& ref, const std::string& path, DataFileCache& cache) {
  ReferenceTable out;
  out.path = path;
  const std::string& hash = cache.file(path).sha256;
  if (hash != ref.sha256) {
    out.invalid = "data file '" + path + "' has changed: sha256 " + hash + " differs from the certificate's " + ref.sha256;
    return out;
  }
  out.table = &cache.table(path, ref.names);
  return out;
}

/// The rows the reference's window takes from its table (the whole table
/// when it names none; a window beyond the table is refused later).
long window_length(const DataReference& ref, const TextTable& table) {
  const auto rows = static_cast<long>(table.rows.size());
  if (ref.row_end < 0 || rows == 0) return rows;
  return std::max(0L, std::min(ref.row_end, rows) - ref.row_begin);
}

/// Steps 1–2 for each reference (`what` names it in messages): every table
/// first, then the exact simulation of their windows charged against the
/// total work (verify/certificate/work_budget.h), then their exact rows;
/// several records are stacked (data/experiment.h: records, record_x0).
CertificateData references_data(const Certificate& c, const std::vector<DataReference>& refs, const TableSource& source) {
  CertificateData out;
  std::vector<ReferenceTable> tables;
  std::vector<long> lengths;
  std::vector<std::string> paths;
  DataBits bits;
  std::map<const TextTable*, DataBits> table_bits_of;  // each table scanned once
  for (const DataReference& ref : refs) {
    ReferenceTable t = source(ref);
    if (!t.invalid.empty()) {
      out.invalid = t.invalid;
      return out;
    }
    if (!table_bits_of.contains(t.table)) table_bits_of[t.table] = table_bits(*t.table, c.model.columns);
    bits.signals = std::max(bits.signals, table_bits_of[t.table].signals);
    bits.scheduling = std::max(bits.scheduling, table_bits_of[t.table].scheduling);
    lengths.push_back(window_length(ref, *t.table));
    if (std::find(paths.begin(), paths.end(), t.path) == paths.end()) {  // each file named once
      out.path += (paths.empty() ? "" : ", ") + t.path;
      paths.push_back(t.path);
    }
    tables.push_back(std::move(t));
  }
  charge_simulation(c, lengths, bits);
  const bool several = c.records.size() > 1;
  std::vector<Experiment<Rational>> parts;
  for (size_t k = 0; k < refs.size(); ++k) {
    const std::string what = several ? "records[" + std::to_string(k) + "]" : "data";
    CertificateData one = window_rows(refs[k], *tables[k].table, c.model.columns, what, CertificateData{});
    if (!one.invalid.empty()) return one;
    if (!several) {
      if (c.records.front().x0.size() != 0) {
        out.invalid = "data: one record starts from the model's x0 (an own x0 is for several records)";
        return out;
      }
      one.path = out.path;
      return one;
    }
    const CertificateRecord& r = c.records[k];
    if (r.x0.size() != 0 && r.x0.size() != c.model.nx) {
      out.invalid = what + ".x0 has " + std::to_string(r.x0.size()) + " entries, the model has " + std::to_string(c.model.nx) + " states";
      return out;
    }
    parts.push_back(std::move(one.exp));
  }
  out.exp = stack_records(parts);
  for (const CertificateRecord& r : c.records) out.exp.record_x0.push_back(r.x0);
  return out;
}

/// The references a certificate names, one per record.
std::vector<DataReference> data_references(const Certificate& c) {
  std::vector<DataReference> refs;
  for (const CertificateRecord& r : c.records) refs.push_back(r.data);
  return refs;
}

CertificateData certificate_data(const Certificate& c, const std::string& certificate_dir, const std::string& data_file) {
  if (c.records.empty()) {
    CertificateData out;
    out.invalid = "the certificate names no data";
    return out;
  }
  if (c.records.size() > 1 && !data_file.empty()) {
    CertificateData out;
    out.invalid = "--data names one file, but the certificate names " + std::to_string(c.records.size()) + " records";
    return out;
  }
  DataFileCache cache;
  return references_data(c, data_references(c), [&](const DataReference& ref) {
    const std::string path = c.records.size() == 1 ? certificate_data_path(c, certificate_dir, data_file)
                                               : recorded_data_path(ref.file, certificate_dir);
    return file_table(ref, path, cache);
  });
}

/// Steps 3–6 on the exact rows of the certificate's window; `details` starts
/// with what the caller knows about the data's origin.
CertificateVerdict check_claim(const Certificate& c, Experiment<Rational> exp, std::ostringstream& details) {
  if (several_records(exp.records)) {
    details << exp.records.size() << " records under one Delta (rows";
    for (const Eigen::Index l : exp.records) details << " " << l;
    details << "); ";
    // The one-record Gram forms are not defined across records here.
    if (c.mode != ToeplitzMode::kSignal) return invalid_verdict("several records need toeplitz mode \"signal\"");
    if (c.form == CertificateForm::kW) return invalid_verdict("several records need form \"delta\" (one Delta for every record)");
  }
  if (is_class_claim(c.claim)) {
    details << "n = " << exp.n() << ", ny = " << c.model.ny << ", nz = " << c.model.nz();
    try {
      return check_class_claim(c, exp, details.str());
    } catch (const std::invalid_argument& e) {
      return invalid_verdict(std::string("the class's model and data: ") + e.what(), details.str());
    }
  }
  // "@x<i>", "@sqrt(x<i>-c)", … scheduling: functions of the certified model's own exact state on these rows
  try {
    exp = with_state_scheduling(c.model, exp);
  } catch (const std::invalid_argument& e) {
    return invalid_verdict(std::string("state scheduling: ") + e.what());
  }
  if (c.model.offset.values.empty() && !c.model.offset.basis.empty())
    return invalid_verdict("the model still has an unknown offset (offset.values missing)");
  if (c.delta2 < 0 || c.dmax2 < 0) return invalid_verdict("delta2 and dmax2 must be >= 0");
  // a state offset E(ρ) is part of the exact simulation below; T_G12·T_u cannot hold it
  if (c.mode == ToeplitzMode::kPaper && has_state_offset(c.model))
    return invalid_verdict("toeplitz mode \"paper\" does not support state_offset (T_z = T_G12 T_u drops E(rho))");

  // 3. Exact simulation.
  const Simulation<Rational> sim = simulate(c.model, exp);
  const Eigen::Index n = exp.n(), ny = c.model.ny, nz = c.model.nz();
  details << "n = " << n << ", ny = " << ny << ", nz = " << nz << ", toeplitz mode " << to_string(c.mode);

  if (is_dual_claim(c.claim) && is_closed_form(c.form)) return check_closed_form_claim(c, exp, sim, details.str());
  if (is_dual_claim(c.claim)) return check_dual_claim(c, exp, sim, details.str());
  const PrimalCheck p = check_primal_point(c, exp, sim, details);
  if (c.claim == CertificateClaim::kNotAWitness) {
    if (p.result == PrimalCheck::kConditionFails) return CertificateVerdict::holding(p.text);
    return invalid_verdict(p.result == PrimalCheck::kHolds ? "the point satisfies (C1) and (C2): it is a witness"
                                                           : p.text,
                           p.result == PrimalCheck::kHolds ? p.text : details.str());
  }
  if (p.result != PrimalCheck::kHolds) return invalid_verdict(p.reason, details.str());
  return CertificateVerdict::holding(p.text);
}
}  // namespace

namespace {
/// The stated size against the work limits, before the data are read
/// (a stated horizon that is not the data's is refused later anyway).
void require_work_limits(const Certificate& c) {
  if (c.form == CertificateForm::kDualDeltaPath) require_dual_order(c.dual.horizon * static_cast<long>(c.model.ny));
}
}  // namespace

CertificateVerdict check_certificate(const Certificate& c, const Experiment<Rational>& exp) {
  require_work_limits(c);
  charge_declared_work(c);
  const RecordLengths lengths = record_lengths_of(exp.records, exp.n());
  charge_simulation(c, std::vector<long>(lengths.begin(), lengths.end()), experiment_bits(exp));
  std::ostringstream details;
  details << "data in memory (" << exp.n() << " rows); ";
  return with_claim(check_claim(c, exp, details), c);
}

CertificateVerdict check_round_trip(const Certificate& c, const Experiment<Rational>& exp, const std::string& name) {
  return check_certificate(parse_certificate(certificate_json(c), name), exp);
}

CertificateVerdict check_certificate(const Certificate& c, const std::string& certificate_dir, const std::string& data_file) {
  require_work_limits(c);
  charge_declared_work(c);
  const CertificateData data = certificate_data(c, certificate_dir, data_file);
  if (!data.invalid.empty()) return invalid_verdict(data.invalid);
  std::ostringstream details;
  details << "data " << data.path << " (sha256 matches); ";
  return with_claim(check_claim(c, data.exp, details), c);
}

CertificateVerdict check_certificate(const Certificate& c, const DataTable& data) {
  require_work_limits(c);
  charge_declared_work(c);
  DataFileCache cache;  // references naming other column names read the file again, once
  const CertificateData read = references_data(c, data_references(c), [&](const DataReference& ref) {
    ReferenceTable out;
    out.path = data.reference.file;
    if (data.reference.sha256 != ref.sha256) {
      out.invalid = "data file '" + out.path + "' has changed: sha256 " + data.reference.sha256 +
                    " differs from the certificate's " + ref.sha256;
      return out;
    }
    if (ref.names != data.reference.names) return file_table(ref, out.path, cache);
    out.table = &data.table;
    return out;
  });
  if (!read.invalid.empty()) return invalid_verdict(read.invalid);
  std::ostringstream details;
  details << "data " << read.path << " (sha256 matches); ";
  return with_claim(check_claim(c, read.exp, details), c);
}

namespace {
/// Steps 4–6 for the primal point of a "consistent" or "not_a_witness" file.
/// kMalformed: the point does not fit the data (sizes): no verdict on
/// Theorem 2.1 either way. kConditionFails: a condition of Theorem 2.1 fails
/// exactly for this point (`reason` says which, with the numbers).
PrimalCheck check_primal_point(const Certificate& c, const Experiment<Rational>& exp, const Simulation<Rational>& sim,
                               std::ostringstream& details) {
  const Eigen::Index n = exp.n(), ny = c.model.ny, nz = c.model.nz();
  const auto fails = [&details](const std::string& why) {
    return PrimalCheck{PrimalCheck::kConditionFails, why, details.str() + "; " + why};
  };
  const auto malformed = [](const std::string& why) { return PrimalCheck{PrimalCheck::kMalformed, why, why}; };
  // 4. w.
  Mat<Rational> w;
  if (c.form == CertificateForm::kDelta) {
    if (c.mode != ToeplitzMode::kSignal) return malformed("form \"delta\" is only valid with toeplitz_mode \"signal\"");
    const Eigen::Index L = c.horizon, K = c.taps.rows();
    const RecordLengths lengths = record_lengths_of(exp.records, n);
    const std::vector<Eigen::Index> start = record_starts(lengths);
    Eigen::Index longest = 0;
    for (const Eigen::Index l : lengths) longest = std::max(longest, l);
    if (L > longest) return malformed("delta_horizon " + std::to_string(L) + " exceeds the " + std::to_string(longest) + " samples");
    // Δ acts on each record from rest: each record's z must vanish before its last L samples.
    for (size_t r = 0; r < lengths.size(); ++r)
      for (Eigen::Index k = 0; k < lengths[r] - L; ++k)
        for (Eigen::Index j = 0; j < nz; ++j)
          if (sim.z(start[r] + k, j) != 0)
            return fails("z_" + std::to_string(k) + (lengths.size() > 1 ? " of record " + std::to_string(r + 1) : "") +
                         " is not zero but precedes the delta horizon of " + std::to_string(L) +
                         " samples (the horizon must cover every sample from the first non-zero z)");
    w = apply_fir_records(c.taps, sim.z, ny, L, exp.records);
    details << ", form delta with " << K << " taps on a horizon of " << L << " samples";
  } else {
    if (c.w.rows() != n) return malformed("w has " + std::to_string(c.w.rows()) + " rows for " + std::to_string(n) + " samples");
    w = c.w;
    details << ", form w";
  }

  // 5. (C2), exactly.
  const Rational dd = residual_energy(exp.y - sim.output - w);
  const Rational bound = Rational(static_cast<long>(n * ny)) * c.dmax2;
  if (dd > bound)
    return fails("(C2) fails: ||d||^2 = " + approx_text(dd) + " > n*ny*dmax2 = " + approx_text(bound) +
                 " (exact comparison of rationals)");
  details << "; (C2) holds: ||d||^2 = " << approx_text(dd) << " <= n*ny*dmax2 = " << approx_text(bound);

  // 6. (C1), exactly (verify/certificate/c1_check.h). A failure is an exact NOT_PSD decision.
  const C1Outcome c1 = c.form == CertificateForm::kDelta
                           ? check_c1_delta_form(c.taps, c.horizon, ny, nz, c.delta2)
                           : check_c1_w_form(
                                 [&]() -> Mat<Rational> {
                                   return c.mode == ToeplitzMode::kSignal ? toeplitz_gram(sim.z, sim.z) : paper_gram(c.model, exp);
                                 },
                                 w, c.delta2);
  if (!c1.holds()) return fails(c1.text);
  details << "; " << c1.text;
  return {PrimalCheck::kHolds, "", details.str()};
}
}  // namespace

CertificateVerdict check_certificate_file(const std::string& path, const std::string& data_file) {
  const Certificate c = read_certificate(path);
  const std::string dir = std::filesystem::path(path).parent_path().string();
  return check_certificate(c, dir.empty() ? "." : dir, data_file);
}

namespace {
/// Sets claim_text on a verdict that holds.
CertificateVerdict with_claim(CertificateVerdict v, const Certificate& c) {
  if (!v.holds) return v;
  std::ostringstream o;
  o << to_string(c.claim);
  if (c.claim == CertificateClaim::kLowerBound || c.claim == CertificateClaim::kClassLowerBound)
    o << " " << lower_text(c.lower_bound, 10);
  v.claim_text = o.str();
  std::ostringstream e;
  e << "claim: toeplitz mode " << (c.mode == ToeplitzMode::kSignal ? "signal" : "paper") << "; ";
  // exact; a number of thousands of digits (an exact ||r||^2/(n*ny) of a long record) is shown by its value
  const auto exact = [](const Rational& q) {
    std::string text = exact_decimal_or_fraction(q);
    return text.size() <= 80 ? text : "~" + approx_text(q, 17) + " (exact in the file: " + std::to_string(text.size()) + " characters)";
  };
  switch (c.claim) {
    case CertificateClaim::kConsistent:
      e << "consistent at delta^2 = " << exact(c.delta2) << ", dmax^2 = " << exact(c.dmax2)
        << " (noise RMS: ||d||^2 <= n*ny*dmax^2)";
      break;
    case CertificateClaim::kNotAWitness:
      e << "the given " << (c.form == CertificateForm::kDelta ? "Delta taps" : "w") << " do not satisfy Theorem 2.1 at delta^2 = "
        << exact(c.delta2) << ", dmax^2 = " << exact(c.dmax2) << " (noise RMS: ||d||^2 <= n*ny*dmax^2)";
      break;
    case CertificateClaim::kInvalidated:
      e << "no causal LTI Delta with ||Delta||_inf^2 <= " << exact(c.delta2) << " and no noise with RMS^2 <= "
        << exact(c.dmax2) << " explain the data";
      break;
    case CertificateClaim::kClassInvalidated:
      e << "no correction theta of the class region (see the details), no causal LTI Delta with ||Delta||_inf^2 <= "
        << exact(c.delta2) << " and no noise with RMS^2 <= " << exact(c.dmax2) << " explain the data";
      break;
    case CertificateClaim::kClassLowerBound:
      e << "for every correction theta of the class region (see the details): ";
      [[fallthrough]];
    case CertificateClaim::kLowerBound:
      switch (c.objective) {
        case DualClaim::kMinDelta2: e << "delta^2 >= " << lower_text(c.lower_bound, 10) << " at dmax^2 = " << exact(c.dmax2); break;
        case DualClaim::kMinDmax2: e << "dmax^2 >= " << lower_text(c.lower_bound, 10) << " at delta^2 = " << exact(c.delta2); break;
        case DualClaim::kWeighted:
          e << "lambda*delta^2 + (1-lambda)*dmax^2 >= " << lower_text(c.lower_bound, 10) << " with lambda = " << exact(c.lambda);
          break;
        case DualClaim::kInvalidated: e << "margin " << lower_text(c.lower_bound, 10); break;
      }
      e << " (printed value rounded down)";
      break;
  }
  v.claim_echo = e.str();
  return v;
}
}  // namespace

namespace {
/// ", estimated work W operations (--max-total-work L)" when the total is
/// counted, and ", F floating multiply-adds (--max-floating-work M)" when
/// floating work was charged.
std::string total_work_text() {
  const VerifyWorkLimits& limits = verify_work_limits();
  std::ostringstream o;
  o << std::setprecision(3);
  if (limits.max_total_work > 0)
    o << ", estimated work " << total_work_charged() << " operations (--max-total-work " << limits.max_total_work << ")";
  if (limits.max_floating_work > 0 && floating_work_charged() > 0)
    o << ", " << floating_work_charged() << " floating multiply-adds (--max-floating-work " << limits.max_floating_work
      << ")";
  return o.str();
}
}  // namespace

int run_certificate_command(const std::string& path, std::ostream& out, std::ostream& err, const std::string& data_file) {
  try {
    const auto start = std::chrono::steady_clock::now();
    const CertificateVerdict v = check_certificate_file(path, data_file);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (v.holds) {
      out << v.claim_text << "\n" << v.claim_echo << "\n" << v.details << "\nchecked in exact rational arithmetic in " << secs
          << " s" << total_work_text() << "\n";
      return kExitOk;
    }
    out << "invalid: " << v.reason << "\n";
    if (!v.details.empty()) out << v.details << "\n";
    return kExitInvalidated;  // the claim does not hold
  } catch (const Interrupted&) {
    err << "lpvid-verify: interrupted\n";  // a requested stop (core/stop_request.h): nothing checked
    return kExitInterrupted;
  } catch (const InputError& e) {
    err << "lpvid-verify: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const IoError& e) {
    err << "lpvid-verify: " << e.what() << "\n";
    return kExitIo;
  } catch (const WorkLimitError& e) {
    err << "lpvid-verify: not checked: " << path << ": " << e.what() << "\n";
    return kExitWorkLimit;
  } catch (const std::bad_alloc&) {
    err << "lpvid-verify: out of memory while checking '" << path << "'\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    err << "lpvid-verify: cannot check '" << path << "': " << e.what() << "\n";
    return kExitBadInput;
  }
}

}  // namespace lpvid
