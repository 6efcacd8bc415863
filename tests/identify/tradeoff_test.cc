// The δ–d_max trade-off curve (identify/tradeoff.h) and the gnuplot wrapper
// (plot/gnuplot.h).
//
// Monotonicity slack. Along the certified curve δ must not grow and d_max
// must not fall as λ grows, up to 1e-3 relative + 1e-6 absolute. The exact
// Pareto order holds for one convex problem; here each point is a different
// rounded model re-optimised by the certification, whose own errors are the
// SDP's relative gap (1e-7 of the objective), the δ² margin (≥ 1e-9
// relative), 12-digit rounding of the taps and 15-digit rounding of d_max²:
// all far below 1e-3. The grid is chosen so that consecutive δ differ by
// ~10× (Example 1 with weight W = 0.01 makes δ expensive: λ must be small
// for δ to buy a smaller d_max).
#include <gtest/gtest.h>

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli/certificate_names.h"
#include "data/csv_reader.h"
#include "data/data_reference.h"
#include "data/csv_writer.h"
#include "data/experiment_builder.h"
#include "examples/paper_example1.h"
#include "identify/basis_selection.h"
#include "plot/tradeoff_plot.h"
#include "identify/tradeoff.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "verify/certificate/certificate_check.h"

#include "support/scratch_dir.h"

namespace lpvid {
namespace {

namespace fs = std::filesystem;

TEST(Tradeoff, DefaultGrid) {
  const std::vector<double> g = default_lambda_grid();
  ASSERT_EQ(g.size(), 11u);
  EXPECT_DOUBLE_EQ(g.front(), 0.02);
  EXPECT_DOUBLE_EQ(g[5], 0.5);
  EXPECT_DOUBLE_EQ(g.back(), 0.98);
  for (size_t i = 1; i < g.size(); ++i) EXPECT_NEAR(g[i] - g[i - 1], 0.096, 1e-12);
}

TEST(Tradeoff, Example1CurveIsMonotoneAndCertified) {
  gen::ScratchDir dir("select");
  Example1Options eo;
  eo.n = 30;
  const Experiment<Rational> e = example1_experiment(eo);
  const std::string csv = dir.file("data.csv");
  write_csv(csv, {{"u1", column_text(e.u, 0)},
                  {"u2", column_text(e.u, 1)},
                  {"y1", column_text(e.y, 0)},
                  {"y2", column_text(e.y, 1)},
                  {"rho1", column_text(e.rho, 0)},
                  {"rho2", column_text(e.rho, 1)}});
  // The affine basis: the model class lacks rho2^2, so there is a real trade-off.
  const std::vector<Monomial> basis = {Monomial{{0, 0}}, Monomial{{1, 0}}, Monomial{{0, 1}}};
  const LpvModel<Rational> mq = with_correction_basis(example1_initial_model(), basis);
  const LpvModel<double> md = convert_model<double>(mq);
  const TextTable t = read_table(csv);
  const Experiment<Rational> xq = make_experiment<Rational>(t, mq.columns);
  const Experiment<double> xd = make_experiment<double>(t, md.columns);

  TradeoffOptions o;
  o.lambdas = {1e-5, 1e-4, 1e-3, 1e-2, 0.1, 0.5};
  o.certify.records = {read_data_table(csv).reference};
  int called = 0;
  o.on_point = [&](const TradeoffPoint&) { ++called; };
  auto solver = make_solver("csdp");
  std::vector<TradeoffPoint> pts = tradeoff_curve(Problem{mq, md, xq, xd}, o, *solver);
  cli::write_tradeoff_certificates(pts, dir.file("tr"));  // as lpvid tradeoff names them
  ASSERT_EQ(pts.size(), o.lambdas.size());
  EXPECT_EQ(called, static_cast<int>(pts.size()));
  for (const TradeoffPoint& p : pts) {
    std::cout << "  lambda " << p.lambda << "  delta " << p.bounds.delta << "  dmax " << p.bounds.dmax
              << "  (relaxation " << p.delta_solver << ", " << p.dmax_solver << ")\n";
    ASSERT_TRUE(p.bounds.verified()) << p.bounds.reason;
    EXPECT_TRUE(check_certificate_file(p.certificate).holds);
  }
  EXPECT_EQ(tradeoff_monotonicity_violation(pts, 1e-3, 1e-6), "");
  // The curve really trades: the ends differ by far more than the slack.
  EXPECT_GT(pts.front().bounds.delta, 100 * pts.back().bounds.delta);
  EXPECT_LT(pts.front().bounds.dmax, 0.9 * pts.back().bounds.dmax);

  const std::string text = tradeoff_csv(pts);
  std::istringstream lines(text);
  std::string header, line;
  std::getline(lines, header);
  EXPECT_EQ(header, "lambda,verified,delta,dmax,delta2_exact,dmax2_exact,delta_solver,dmax_solver,status,certificate");
  int rows = 0;
  while (std::getline(lines, line)) {
    ++rows;
    EXPECT_EQ(line.find(",true,"), line.find(','));  // every point verified
  }
  EXPECT_EQ(rows, static_cast<int>(pts.size()));

  const PlotSpec spec = tradeoff_plot(pts, "test");
  ASSERT_EQ(spec.series.size(), 1u);
  EXPECT_EQ(spec.series[0].x.size(), pts.size());
  EXPECT_TRUE(spec.logy);  // δ spans 4 decades here
}

TEST(Tradeoff, MonotonicityCheckFindsViolations) {
  auto point = [](double l, double d, double m) {
    TradeoffPoint p;
    p.lambda = l;
    p.bounds.outcome = CertifyOutcome::kVerified;
    p.bounds.delta = d;
    p.bounds.dmax = m;
    return p;
  };
  EXPECT_EQ(tradeoff_monotonicity_violation({point(0.1, 2, 1), point(0.5, 1, 2)}, 0, 0), "");
  EXPECT_NE(tradeoff_monotonicity_violation({point(0.1, 1, 1), point(0.5, 2, 2)}, 1e-3, 0), "");
  EXPECT_NE(tradeoff_monotonicity_violation({point(0.1, 2, 2), point(0.5, 1, 1)}, 1e-3, 0), "");
  EXPECT_EQ(tradeoff_monotonicity_violation({point(0.1, 1, 1), point(0.5, 1.0005, 0.9995)}, 1e-3, 0), "");
  // Order is by λ, not by position.
  EXPECT_EQ(tradeoff_monotonicity_violation({point(0.5, 1, 2), point(0.1, 2, 1)}, 0, 0), "");
}

TEST(Gnuplot, WritesAPngOrSaysWhyNot) {
  if (gnuplot_png_terminal().empty()) GTEST_SKIP() << "gnuplot with a PNG terminal is not installed";
  gen::ScratchDir dir("select");
  PlotSpec spec;
  spec.title = "it's a test";  // a quote in a gnuplot string
  spec.xlabel = "x";
  spec.ylabel = "y";
  PlotSeries s;
  s.title = "points";
  s.x = {1, 2, 3};
  s.y = {3, 1, 2};
  s.labels = {"a", "b\"q", "c"};
  spec.series.push_back(s);
  const std::string png = dir.file("p l o t.png");  // spaces in the path
  const PlotOutcome out = plot_png(spec, png);
  ASSERT_TRUE(out.ok) << out.message;
  std::ifstream f(png, std::ios::binary);
  char sig[8] = {};
  f.read(sig, 8);
  EXPECT_EQ(std::string(sig + 1, 3), "PNG");
}

TEST(Gnuplot, MissingProgramIsAClearMessage) {
  const char* old = std::getenv("LPVID_GNUPLOT");
  const std::string saved = old ? old : "";
  setenv("LPVID_GNUPLOT", "/nonexistent/gnuplot-for-lpvid-test", 1);
  PlotSpec spec;
  PlotSeries s;
  s.x = {1};
  s.y = {1};
  spec.series.push_back(s);
  gen::ScratchDir dir("select");
  const PlotOutcome out = plot_png(spec, dir.file("x.png"));
  if (old) setenv("LPVID_GNUPLOT", saved.c_str(), 1);
  else unsetenv("LPVID_GNUPLOT");
  EXPECT_FALSE(out.ok);
  EXPECT_NE(out.message.find("gnuplot"), std::string::npos) << out.message;
  EXPECT_FALSE(fs::exists(dir.file("x.png")));
}

TEST(Gnuplot, ScriptQuotesAndTerminal) {
  PlotSpec spec;
  spec.title = "a'b";
  PlotSeries s;
  s.x = {1};
  s.y = {2};
  spec.series.push_back(s);
  const std::string cairo = gnuplot_script(spec, "pngcairo", "/tmp/o.png", "/tmp/d.txt");
  EXPECT_NE(cairo.find("set terminal pngcairo"), std::string::npos);
  EXPECT_NE(cairo.find("set title 'a''b'"), std::string::npos);
  EXPECT_NE(cairo.find("'/tmp/d.txt' index 0 using 1:2"), std::string::npos);
  EXPECT_NE(gnuplot_script(spec, "png", "/tmp/o.png", "/tmp/d.txt").find("set terminal png size"), std::string::npos);
}

}  // namespace
}  // namespace lpvid
