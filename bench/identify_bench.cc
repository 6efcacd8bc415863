// Identification benchmark: time to identify (Theorem 3.1) and to
// certify the identified model (exact check of the written certificate), for
// SISO and 2×2 LPV systems at n = 50, 100, 200, 400, per method and backend.
// Prints a table; not a test.
//   relaxation   one solve of the paper's linearised BMI (w form); certified by
//                re-solving Theorem 2.1 in the Δ form (KYP, `taps` taps)
//   alternating  Δ/θ block-coordinate descent (identify/alternating_identify.h);
//                certified with its own Δ (no solve; re-solve only if that fails)
// Usage: identify_bench [max_n=400] [relax_max_n=100] [backends=csdp] [taps=16] [methods=relaxation,alternating]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "core/decimal_rounding.h"
#include "core/number_text.h"
#include "data/csv_writer.h"
#include "examples/random_stream.h"
#include "certify/certificate_files.h"
#include "certify/certify.h"
#include "data/data_reference.h"
#include "identify/identify.h"
#include "model/simulate.h"
#include "two_state_model.h"
#include "solvers/solver_factory.h"

using namespace lpvid;

namespace {

Rational dec(double x) { return round_to_digits(x, 6); }

/// A stable 2-state LPV system with ny = nu = m, scheduling rho1, its data
/// (exact decimals, noise RMS 0.05) and an initial model lacking a rho1 term
/// in C; correction basis {1, rho1}.
void make_case(int m, int n, LpvModel<Rational>* initial, Experiment<Rational>* exp) {
  RandomStream rng(7 + static_cast<uint64_t>(m) * 1000 + static_cast<uint64_t>(n));
  LpvModel<Rational> t = bench::two_state_model(m);
  Mat<Rational> C1 = Mat<Rational>::Zero(m, 2);
  for (int i = 0; i < m; ++i) C1(i, 0) = dec(0.3);
  *initial = t;
  initial->correction.basis = {Monomial{{0}}, Monomial{{1}}};
  initial->correction.A.assign(2, Mat<Rational>::Zero(2, 2));
  initial->correction.B.assign(2, Mat<Rational>::Zero(2, m));
  t.C.add(Monomial{{1}}, C1);
  exp->u = Mat<Rational>(n, m);
  exp->rho = Mat<Rational>(n, 1);
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < m; ++i) exp->u(k, i) = dec(rng.normal());
    exp->rho(k, 0) = dec(rng.uniform());
  }
  exp->y = Mat<Rational>::Zero(n, m);
  const Simulation<Rational> s = simulate(t, *exp);
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < m; ++i) exp->y(k, i) = round_to_digits(nearest_double(s.yhat(k, i)) + 0.05 * rng.normal(), 10);
}

std::vector<std::string> split(const char* text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string b; std::getline(ss, b, ',');) out.push_back(b);
  return out;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  const int max_n = argc > 1 ? std::atoi(argv[1]) : 400;
  const int relax_max_n = argc > 2 ? std::atoi(argv[2]) : 100;
  const std::vector<std::string> backends = split(argc > 3 ? argv[3] : "csdp");
  const long taps = argc > 4 ? std::atol(argv[4]) : 16;
  const std::vector<std::string> methods = split(argc > 5 ? argv[5] : "relaxation,alternating");
  const auto dir = std::filesystem::temp_directory_path() / "lpvid_identify_bench";
  std::filesystem::create_directories(dir);
  std::printf("Theorem 3.1 identification + certification (Delta form, %ld taps, exact check); relaxation up to n = %d\n",
              taps, relax_max_n);
  std::printf("%-4s %4s %-11s %-5s | %8s %5s %-18s | %8s %8s %-8s | %10s %10s\n", "sys", "n", "method", "solver",
              "solve s", "steps", "status", "cert s", "verify s", "verified", "delta", "dmax");
  for (int m : {1, 2})
    for (int n : {50, 100, 200, 400}) {
      if (n > max_n) continue;
      LpvModel<Rational> mq;
      Experiment<Rational> eq;
      make_case(m, n, &mq, &eq);
      const std::string data = (dir / ("case" + std::to_string(m) + "_" + std::to_string(n) + ".csv")).string();
      std::vector<TextColumn> cols;
      for (int i = 0; i < m; ++i) cols.push_back({mq.columns.u[static_cast<size_t>(i)], column_text(eq.u, i)});
      for (int i = 0; i < m; ++i) cols.push_back({mq.columns.y[static_cast<size_t>(i)], column_text(eq.y, i)});
      cols.push_back({"rho1", column_text(eq.rho, 0)});
      write_csv(data, cols);
      const LpvModel<double> md = convert_model<double>(mq);
      const Experiment<double> ed = nearest_double(eq);
      for (const std::string& method : methods)
        for (const std::string& b : backends) {
          const bool alternating = method == "alternating";
          if (!alternating && n > relax_max_n) continue;
          auto solver = make_solver(b);
          IdentifyOptions io;
          io.method = alternating ? IdentifyMethod::kAlternating : IdentifyMethod::kRelaxation;
          io.taps = taps;
          const auto t0 = std::chrono::steady_clock::now();
          const IdentifyResult res = identify(md, ed, io, *solver);
          const double ident = seconds_since(t0);
          if (!has_solution(res.status)) {  // p = 0 then: certifying it would show the initial model's bounds
            std::printf("%-4s %4d %-11s %-5s | %8.2f %5zu %-18s | %8s %8s %-8s | %10s %10s\n", m == 1 ? "SISO" : "2x2",
                        n, method.c_str(), b.c_str(), ident, res.iterates.size(), to_string(res.status), "-", "-", "-",
                        "-", "-");
            continue;
          }
          Vec<Rational> p(res.p.size());
          for (Eigen::Index i = 0; i < p.size(); ++i) p(i) = round_to_digits(res.p(i), 12);
          CertifyOptions co;
          co.max_taps = taps;
          co.delta_norm = DeltaNorm::kKyp;
          co.records = {read_data_table(data).reference};
          const LpvModel<Rational> fixed = apply_parameters(mq, res.layout, p);
          const auto t1 = std::chrono::steady_clock::now();
          CertifiedBounds cb;
          if (alternating && res.taps.size() > 0) cb = certify_with_taps(fixed, eq, res.taps, co, solver->name());
          if (!cb.verified()) cb = certify_fixed_model(fixed, eq, co, *solver);
          const double cert = seconds_since(t1);
          std::printf("%-4s %4d %-11s %-5s | %8.2f %5zu %-18s | %8.2f %8.3f %-8s | %10.4g %10.4g\n",
                      m == 1 ? "SISO" : "2x2", n, method.c_str(), b.c_str(), ident, res.iterates.size(),
                      to_string(res.status), cert, cb.verify_seconds, cb.verified() ? "true" : "false",
                      cb.verified() ? cb.delta : NAN, cb.verified() ? cb.dmax : NAN);
          std::fflush(stdout);
        }
    }
  return 0;
}
