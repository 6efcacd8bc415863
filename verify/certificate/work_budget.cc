#include "verify/certificate/work_budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include <nlohmann/json.hpp>

#include "data/csv_reader.h"
#include "verify/psd/check_progress.h"
#include "verify/psd/work_limits.h"
#include "verify/certificate/path_dual.h"
#include "verify/certificate/tap_gram_filter.h"

namespace lpvid {
namespace {

// Calibration (docs/exit_codes.md, "The total work of a check"): operations
// per unit of each estimate, measured against max_exact_work's operations.
constexpr double kWorkPerCube = 1.0;         ///< a dual point's floating rebuild, per m³
constexpr double kWorkPerRecord = 1.5e6;     ///< a record's fixed cost (its rows, its own x0, stacking)
constexpr double kWorkPerByte = 20;          ///< reading, hashing and parsing a data file
constexpr double kWorkPerLimbProduct = 450;  ///< one product of the exact simulation, per 64-bit limb (and its gcd)
constexpr double kWorkPerConvolutionLimb = 2;  ///< one product of a convolution of z (integers on a common denominator)

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

double rational_bits(const Rational& q) {
  return static_cast<double>(mpz_sizeinbase(mpq_numref(q.mpq()), 2) + mpz_sizeinbase(mpq_denref(q.mpq()), 2));
}

double matrix_bits(const Mat<Rational>& m) {
  double most = 0;
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) most = std::max(most, rational_bits(m(i, j)));
  return most;
}

/// The dual points a check rebuilds: their horizons (one per class leaf).
std::vector<long> dual_horizons(const Certificate& c) {
  std::vector<long> horizons;
  if (is_class_claim(c.claim)) {
    for (const ClassNode& node : c.region.nodes)
      if (node.split < 0) horizons.push_back(node.dual.horizon);
  } else if (is_dual_claim(c.claim) && !is_closed_form(c.form)) {
    horizons.push_back(c.dual.horizon);
  }
  return horizons;
}

/// Bits the exact state gains per sample: the model's state matrices A, B
/// (numerator plus denominator of their largest entry) and, scheduled, the
/// scheduling's numbers as often as the highest degree multiplies them.
double growth_bits(const Certificate& c, double scheduling_bits) {
  double model = 0;
  int degree = 0;
  for (const auto* m : {&c.model.A, &c.model.B})
    for (const auto& term : m->terms) {
      model = std::max(model, matrix_bits(term.value));
      degree = std::max(degree, term.basis.degree());
    }
  return std::max(1.0, model + degree * scheduling_bits);
}

/// Products of z's samples per sample beyond the simulation's own step:
/// every convolution with L taps (Δ taps, each dual point's adjoint, a Gram of z).
double convolution_taps(const Certificate& c, const std::vector<long>& rows) {
  double taps = 0;
  for (const long L : dual_horizons(c)) taps += static_cast<double>(L);
  if (!is_class_claim(c.claim) && !is_dual_claim(c.claim)) {
    if (c.form == CertificateForm::kDelta) {
      taps += static_cast<double>(c.taps.rows());
    } else {
      for (const long n : rows) taps += static_cast<double>(n);  // the Gram of z (form w, paper mode)
    }
  }
  return taps;
}

}  // namespace

void charge_declared_work(const Certificate& c) {
  start_total_work();
  const long max_records = verify_work_limits().max_records;
  const auto records = static_cast<long>(c.records.size());
  if (max_records > 0 && records > max_records)
    throw WorkLimitError("the certificate names " + std::to_string(records) + " records, above the limit " +
                         std::to_string(max_records) + "; raise it with --max-records");
  const double ny = c.model.ny, nz = c.model.nz();
  const bool dense = c.form == CertificateForm::kDualDelta;
  double rebuild = 0, sums = 0;
  const std::vector<long> horizons = dual_horizons(c);
  for (const long L : horizons) {
    const Eigen::Index order = L * (dense ? c.model.ny + c.model.nz() : c.model.ny);
    const double m = static_cast<double>(order);
    rebuild += kWorkPerCube * dual_step_work(order);
    sums += m * m * ny * nz;
  }
  if (!horizons.empty()) {
    const std::string points =
        std::to_string(horizons.size()) + (horizons.size() == 1 ? " dual point" : " dual points (class leaves)");
    charge_floating_work(rebuild, "the floating rebuild of " + points);
    charge_total_work(sums, "the exact sums of " + points);
  }
  if (c.form == CertificateForm::kDelta && !is_class_claim(c.claim) && !is_dual_claim(c.claim)) {
    const double m = static_cast<double>(c.horizon) * std::min(ny, nz);  // (C1): δ²I − T_Δ T_Δᵀ, floating filter
    if (structured_c1_applies(static_cast<long>(c.horizon), c.model.ny, c.model.nz()))
      charge_floating_work(structured_c1_work(static_cast<long>(c.horizon)), "the (C1) proof in doubles of order " + number(m));
    else
      charge_total_work(kWorkPerCube * m * m * m, "the (C1) check of order " + number(m));
  }
  if (records > 1) charge_total_work(kWorkPerRecord * static_cast<double>(records), std::to_string(records) + " records");
}

namespace {

/// The streaming pass of refuse_declared_text: counts the keys "leaf" and
/// "dual" and takes the largest "horizon" and "outputs" (keys arrive
/// unescaped, so no spelling of them is missed).
struct DeclaredSizes : nlohmann::json_sax<nlohmann::json> {
  std::string last_key;
  double points = 0, horizon = 0, outputs = 1;
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t v) override { return take(static_cast<double>(v)); }
  bool number_unsigned(number_unsigned_t v) override { return take(static_cast<double>(v)); }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool key(string_t& k) override {
    last_key = k;
    if (k == "leaf" || k == "dual") points += 1;
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }
  bool take(double v) {
    if (last_key == "horizon") horizon = std::max(horizon, v);
    if (last_key == "outputs") outputs = std::max(outputs, v);
    return true;
  }
};

}  // namespace

void refuse_declared_text(std::string_view text, const std::string& file) {
  const double limit = verify_work_limits().max_floating_work;
  if (limit <= 0) return;
  DeclaredSizes sizes;
  if (!nlohmann::json::sax_parse(text, &sizes) || sizes.points == 0) return;  // the parser says what is wrong
  const double m = sizes.horizon * sizes.outputs;
  const double work = sizes.points * kWorkPerCube * m * m * m;
  if (work > limit)
    throw WorkLimitError(file + " declares " + number(sizes.points) + " dual points (class leaves) of order up to " +
                         number(m) + ": their floating rebuild alone is about " + number(work) +
                         " multiply-adds, above --max-floating-work " + number(limit) +
                         " (refused before the numbers are read); raise it with --max-floating-work");
}

void charge_data_file(std::uintmax_t bytes, const std::string& path) {
  charge_total_work(kWorkPerByte * static_cast<double>(bytes),
                    "reading data file '" + path + "' (" + std::to_string(bytes) + " bytes)");
}

double simulation_work(const Certificate& c, const std::vector<long>& rows, const DataBits& data) {
  const double g = growth_bits(c, data.scheduling);
  const double b0 = std::max(data.signals, data.scheduling) + 64;
  double bits = 0;  // Σ over records and samples of the state's bits
  for (const long r : rows) {
    const double n = static_cast<double>(r);
    bits += n * b0 + g * n * (n - 1) / 2;
  }
  const double nx = c.model.nx, nu = c.model.nu, ny = c.model.ny, nz = c.model.nz();
  const double parameters = is_class_claim(c.claim) ? static_cast<double>(c.region.parameters.size()) : 0;
  const double step = (nx + ny + nz) * (nx + nu + 1) * (1 + parameters);
  double gram = 0;  // form w: the n × n Schur complement of (C1), floating filter
  if (!is_class_claim(c.claim) && !is_dual_claim(c.claim) && c.form == CertificateForm::kW)
    for (const long r : rows) gram += kWorkPerCube * std::pow(static_cast<double>(r), 3);
  return (kWorkPerLimbProduct * step + kWorkPerConvolutionLimb * convolution_taps(c, rows) * ny * nz) * bits / 64 + gram;
}

void charge_simulation(const Certificate& c, const std::vector<long>& rows, const DataBits& data) {
  long total = 0;
  for (const long r : rows) total += r;
  const double work = simulation_work(c, rows, data);
  const std::string what = "the exact simulation of " + std::to_string(total) + " rows";
  charge_total_work(work, what + " (" + std::to_string(rows.size()) + (rows.size() == 1 ? " record" : " records") +
                              ", numbers of up to " + number(std::max(data.signals, data.scheduling)) +
                              " bits in the data, growing by about " + number(growth_bits(c, data.scheduling)) +
                              " bits per sample)");
  check_progress(work, what + " and the convolutions of its z (about " + number(work) + " operations)");
}

namespace {
/// Bits of the number a cell writes, at most: a decimal of d characters is
/// p/10^k with both parts below 10^d; "1e4000" adds its exponent's digits.
double cell_bits(const std::string& cell) {
  double digits = static_cast<double>(cell.size());
  const std::size_t e = cell.find_first_of("eE");
  if (e != std::string::npos) {
    const long exponent = std::strtol(cell.c_str() + e + 1, nullptr, 10);
    digits += static_cast<double>(exponent < 0 ? -exponent : exponent);
  }
  return 2 * 3.33 * digits;
}
}  // namespace

namespace {
/// The most bits of a cell in the named columns of `table` (absent names skipped).
double columns_bits(const TextTable& table, const std::vector<std::string>& names) {
  double most = 0;
  for (const std::string& name : names) {
    const std::optional<size_t> j = find_column(table, name);
    if (!j) continue;
    for (const auto& row : table.rows)
      if (*j < row.size()) most = std::max(most, cell_bits(row[*j]));
  }
  return most;
}
}  // namespace

DataBits table_bits(const TextTable& table, const ColumnMap& columns) {
  return {std::max(columns_bits(table, columns.u), columns_bits(table, columns.y)), columns_bits(table, columns.rho)};
}

DataBits experiment_bits(const Experiment<Rational>& exp) {
  return {std::max(matrix_bits(exp.u), matrix_bits(exp.y)), matrix_bits(exp.rho)};
}

}  // namespace lpvid
