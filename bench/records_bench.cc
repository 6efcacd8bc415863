// Several records under one Δ (docs/several_records.md): the cost of the
// certified interval of min d_max² at a fixed δ for K = 1, 2, 4, 8 records of
// n samples each (SISO and 2×2), against one record. The Toeplitz constraint
// lives on the horizon n whatever K is; only the data term grows with K, so
// the time should grow about like K (not like (K·n)³). Prints a table; not a test.
//
// SISO: the LTI model of fixtures/models/lti_siso.json; record k: u ~ N(0, 1)
// (seed 1000 + k), y = ŷ + 0.48·z(k − 20) + noise U(−0.002, 0.002): one Δ
// (a delay of 0.48) for every record.
// 2×2: the paper's Example 1 with its initial model, record k along the
// trajectory of seed k + 1 with noise variance 0.01.
// Usage: records_bench [n=200] [counts=1,2,4,8] [delta_siso=0.45] [delta_2x2=1] [systems=siso,2x2]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "certify/certificate_files.h"
#include "certify/certify.h"
#include "core/decimal_rounding.h"
#include "core/number_text.h"
#include "data/csv_writer.h"
#include "data/data_reference.h"
#include "data/experiment_builder.h"
#include "examples/paper_example1.h"
#include "examples/random_stream.h"
#include "model/model_file.h"
#include "model/simulate.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "verify/certificate/certificate_check.h"
#include "bench_measure.h"

using namespace lpvid;
using bench::int_list;
using bench::kilobytes;
using bench::peak_mb;
using bench::seconds_since;

namespace {

/// SISO record k: one Δ (0.48 at delay 20) for every record.
Experiment<Rational> siso_record(const LpvModel<Rational>& model, int n, int k) {
  Experiment<Rational> e;
  RandomStream rng(1000 + static_cast<uint64_t>(k));
  e.u = Mat<Rational>(n, 1);
  e.rho = Mat<Rational>(n, 0);
  e.y = Mat<Rational>::Zero(n, 1);
  for (int i = 0; i < n; ++i) e.u(i, 0) = round_to_digits(rng.normal(), 6);
  const Simulation<Rational> s = simulate(model, e);
  for (int i = 0; i < n; ++i) {
    const double w = i >= 20 ? 0.48 * nearest_double(s.z(i - 20, 0)) : 0.0;
    e.y(i, 0) = round_to_digits(nearest_double(s.output(i, 0)) + w + 0.002 * (2 * rng.uniform() - 1), 10);
  }
  return e;
}

Experiment<Rational> example1_record(int n, int k) {
  Example1Options o;
  o.n = n;
  o.noise_variance = 0.01;
  o.seed = static_cast<uint64_t>(k + 1);
  return example1_experiment(o);
}

struct Row {
  long samples = 0, horizon = 0;
  double certify = 0, verify_upper = 0, verify_lower = 0, gap = NAN, kb_upper = 0, kb_lower = 0, upper = NAN;
  std::string ok = "-";
};

Row run(const LpvModel<Rational>& model, const std::vector<Experiment<Rational>>& records, double delta,
        const std::filesystem::path& dir, const std::string& tag) {
  Row row;
  CertifyOptions co;
  co.objective.kind = BoundObjective::Kind::kMinDmax;
  co.objective.delta = delta;
  for (size_t k = 0; k < records.size(); ++k) {
    const std::string path = (dir / (tag + ".record" + std::to_string(k) + ".csv")).string();
    write_csv(path, experiment_columns(model.columns, records[k]));
    co.records.push_back(read_data_table(path).reference);
  }
  co.progress = [tag](const std::string& stage) { std::fprintf(stderr, "  [%s] %s\n", tag.c_str(), stage.c_str()); };
  const Experiment<Rational> exp = stack_records(records);
  row.samples = static_cast<long>(exp.n());
  auto solver = make_solver("csdp");
  auto t0 = std::chrono::steady_clock::now();
  const CertifiedBounds b = certify_fixed_model(model, exp, co, *solver);
  row.certify = seconds_since(t0);
  row.horizon = b.horizon;
  row.gap = relative_gap(b);
  if (b.verified()) row.upper = std::sqrt(nearest_double(b.dmax2));
  if (!b.verified()) std::fprintf(stderr, "  (%s: no upper end: %s)\n", tag.c_str(), b.reason.c_str());
  if (!b.lower.verified()) std::fprintf(stderr, "  (%s: no lower end: %s)\n", tag.c_str(), b.lower.reason.c_str());
  const CertificateFiles files = write_certificates(b, (dir / (tag + ".cert.json")).string());
  bool all = b.verified() && b.lower.verified();
  if (b.verified()) {
    t0 = std::chrono::steady_clock::now();
    all = check_certificate_file(files.certificate).holds && all;
    row.verify_upper = seconds_since(t0);
    row.kb_upper = kilobytes(files.certificate);
  }
  if (b.lower.verified()) {
    t0 = std::chrono::steady_clock::now();
    all = check_certificate_file(files.lower).holds && all;
    row.verify_lower = seconds_since(t0);
    row.kb_lower = kilobytes(files.lower);
  }
  row.ok = all ? "yes" : "NO";
  return row;
}

void print(const char* sys, int k, const Row& r) {
  std::printf("%-4s %2d %6ld %5ld | %9.2f %8.3f %8.3f %-3s | %10.2e %10.4g | %8.0f %8.0f | %7.0f\n", sys, k, r.samples,
              r.horizon, r.certify, r.verify_upper, r.verify_lower, r.ok.c_str(), r.gap, r.upper, r.kb_upper, r.kb_lower,
              peak_mb());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 200;
  const std::vector<int> counts = int_list(argc > 2 ? argv[2] : "1,2,4,8");
  const double delta_siso = argc > 3 ? std::atof(argv[3]) : 0.45;
  const double delta_2x2 = argc > 4 ? std::atof(argv[4]) : 1.0;
  const std::string systems = argc > 5 ? argv[5] : "siso,2x2";
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "lpvid_records_bench";
  std::filesystem::create_directories(dir);
  std::printf("Several records under one Delta: certified interval of min dmax^2 at fixed delta, n = %d per record\n", n);
  std::printf("sys   K  total     L |  certify   verify   verify ok  |    rel gap  dmax(up)  |  kB up  kB low  | peak MB\n");
  std::printf("                      |      [s]  up [s]  low [s]     |                      |                 |\n");
  const LpvModel<Rational> siso = read_model_file<Rational>(std::string(LPVID_SOURCE_DIR) + "/fixtures/models/lti_siso.json");
  const LpvModel<Rational> ex1 = example1_initial_model();
  for (const int K : counts) {
    if (systems.find("siso") != std::string::npos) {
      std::vector<Experiment<Rational>> recs;
      for (int k = 0; k < K; ++k) recs.push_back(siso_record(siso, n, k));
      std::fprintf(stderr, "SISO, K = %d records of %d samples\n", K, n);
      print("SISO", K, run(siso, recs, delta_siso, dir, "siso_K" + std::to_string(K)));
    }
    if (systems.find("2x2") != std::string::npos) {
      std::vector<Experiment<Rational>> recs;
      for (int k = 0; k < K; ++k) recs.push_back(example1_record(n, k));
      std::fprintf(stderr, "2x2, K = %d records of %d samples\n", K, n);
      print("2x2", K, run(ex1, recs, delta_2x2, dir, "2x2_K" + std::to_string(K)));
    }
  }
  std::filesystem::remove_all(dir);
  return 0;
}
