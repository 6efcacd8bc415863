// psd_bench: timings of `lpvid-verify psd` on random PD matrices written as
// 5-significant-digit decimals (M = BᵀB/n + I, B uniform in [-1, 1], fixed seed).
//
//   psd_bench [--sizes 100,200,400,800,1000] [--exact-max 400]
//             [--bareiss-max 200] [--rational-max 100] [--threads 0] [--dir /tmp]
//             [--keep]   (keep the generated matrix files psd_bench_<n>.txt)
//
// Columns: n; parse = reading the text file exactly (same reader as the
// command); filter = decide_psd with the filter (what the command does);
// end-to-end = run_psd_command on the file (parse + decide + print);
// exact(1t), exact(Nt) = decide_psd_exact (multi-modular) with 1 and N threads
// (n ≤ exact-max); bareiss = decide_psd_bareiss, 1 thread (n ≤ bareiss-max);
// rational = decide_psd_rational_ldlt, the reference (n ≤ rational-max).
// "-" = not run. Every verdict must be PD; the program exits 1 otherwise.

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "verify/psd/exact_psd.h"
#include "verify/psd/psd_command.h"
#include "verify/psd/rational_matrix_io.h"

namespace {

using Clock = std::chrono::steady_clock;

template <typename F>
double timed(F&& f) {
  const auto t0 = Clock::now();
  f();
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Writes M = BᵀB/n + I rounded to 5 significant digits to `path`.
void write_random_pd(const std::string& path, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  std::vector<double> B(static_cast<size_t>(n) * n);
  for (double& b : B) b = uni(rng);
  std::vector<double> G(static_cast<size_t>(n) * n, 0.0);  // BᵀB
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < n; ++i) {
      const double bki = B[static_cast<size_t>(k) * n + i];
      for (int j = i; j < n; ++j) G[static_cast<size_t>(i) * n + j] += bki * B[static_cast<size_t>(k) * n + j];
    }
  std::vector<std::string> text(static_cast<size_t>(n) * n);
  char buf[40];
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j) {
      double m = G[static_cast<size_t>(i) * n + j] / n + (i == j ? 1.0 : 0.0);
      std::snprintf(buf, sizeof buf, "%.5g", m);
      text[static_cast<size_t>(i) * n + j] = text[static_cast<size_t>(j) * n + i] = buf;
    }
  std::ofstream out(path);
  out << "# psd_bench: M = B'B/n + I, n = " << n << ", seed " << seed << ", 5 significant digits\n";
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) out << (j ? " " : "") << text[static_cast<size_t>(i) * n + j];
    out << '\n';
  }
}

std::vector<int> parse_sizes(const std::string& s) {
  std::vector<int> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(std::atoi(item.c_str()));
  return out;
}

std::string cell(double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", seconds);
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes{100, 200, 400, 800, 1000};
  int exact_max = 400, bareiss_max = 200, rational_max = 100, threads = 0;
  std::string dir = "/tmp";
  bool keep = false;
  for (int a = 1; a < argc; ++a) {
    std::string arg = argv[a];
    auto next = [&]() -> std::string {
      if (a + 1 >= argc) {
        std::fprintf(stderr, "missing value for %s\n", arg.c_str());
        std::exit(2);
      }
      return argv[++a];
    };
    if (arg == "--sizes") sizes = parse_sizes(next());
    else if (arg == "--exact-max") exact_max = std::atoi(next().c_str());
    else if (arg == "--bareiss-max") bareiss_max = std::atoi(next().c_str());
    else if (arg == "--rational-max") rational_max = std::atoi(next().c_str());
    else if (arg == "--threads") threads = std::atoi(next().c_str());
    else if (arg == "--dir") dir = next();
    else if (arg == "--keep") keep = true;
    else {
      std::fprintf(stderr, "usage: psd_bench [--sizes a,b,..] [--exact-max N] [--bareiss-max N] [--rational-max N] [--threads N] [--dir D] [--keep]\n");
      return 2;
    }
  }
  const int nthreads = threads > 0 ? threads : static_cast<int>(std::max(1u, std::min(8u, std::thread::hardware_concurrency())));

  std::printf("%6s | %8s | %8s | %8s | %10s | %7s | %9s | %9s | %9s | %9s\n", "n", "write", "parse", "filter",
              "end-to-end", "verdict", "exact(1t)", ("exact(" + std::to_string(nthreads) + "t)").c_str(), "bareiss",
              "rational");
  std::printf("-------|----------|----------|----------|------------|---------|-----------|-----------|-----------|----------\n");
  bool all_pd = true;
  for (int n : sizes) {
    const std::string path = dir + "/psd_bench_" + std::to_string(n) + ".txt";
    const double t_write = timed([&] { write_random_pd(path, n, 20240611u + static_cast<unsigned>(n)); });
    lpvid::Mat<lpvid::Rational> M;
    const double t_parse = timed([&] { M = lpvid::read_rational_matrix_file(path); });
    lpvid::PsdResult fast;
    const double t_filter = timed([&] { fast = lpvid::decide_psd(M); });
    std::ostringstream sink_out, sink_err;
    int code = 0;
    const double t_e2e = timed([&] { code = lpvid::run_psd_command(path, sink_out, sink_err); });
    std::string verdict = lpvid::verdict_word(fast.verdict);
    if (fast.verdict != lpvid::PsdVerdict::kPositiveDefinite || code != 0) all_pd = false;
    if (!fast.decided_by_filter) verdict += "*";

    std::string e1 = "-", en = "-", bar = "-", rat = "-";
    if (n <= exact_max) {
      lpvid::PsdResult r1, rn;
      e1 = cell(timed([&] { r1 = lpvid::decide_psd_exact(M, 1); }));
      en = cell(timed([&] { rn = lpvid::decide_psd_exact(M, nthreads); }));
      if (r1.verdict != fast.verdict || rn.verdict != fast.verdict) all_pd = false;
    }
    if (n <= bareiss_max) {
      lpvid::PsdResult rb;
      bar = cell(timed([&] { rb = lpvid::decide_psd_bareiss(M, 1); }));
      if (rb.verdict != fast.verdict) all_pd = false;
    }
    if (n <= rational_max) {
      lpvid::PsdResult rr;
      rat = cell(timed([&] { rr = lpvid::decide_psd_rational_ldlt(M); }));
      if (rr.verdict != fast.verdict) all_pd = false;
    }
    std::printf("%6d | %8s | %8s | %8s | %10s | %7s | %9s | %9s | %9s | %9s\n", n, cell(t_write).c_str(),
                cell(t_parse).c_str(), cell(t_filter).c_str(), cell(t_e2e).c_str(), verdict.c_str(), e1.c_str(),
                en.c_str(), bar.c_str(), rat.c_str());
    std::fflush(stdout);
    if (!keep) std::remove(path.c_str());
  }
  std::printf("(times in seconds; verdict* = decided by the exact path, not the filter)\n");
  if (!all_pd) {
    std::printf("ERROR: some verdict was not PD or the paths disagreed\n");
    return 1;
  }
  return 0;
}
