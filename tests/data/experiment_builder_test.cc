#include "data/experiment_builder.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "data/csv_reader.h"

#include "support/input_error_text.h"

namespace lpvid {
namespace {

using gen::error_of;

using gen::contains;

const char* kCsv = "t,u1,u2,y,rho,note\n0,0.1,1/3,2,-1,a\n1,0.2,2,3e-1,0.5,\n2,1,1,1,1,x\n";

TEST(ExperimentBuilderTest, SelectsColumnsByNameExactly) {
  const TextTable t = parse_csv(kCsv, "e.csv");
  const Experiment<Rational> e = make_experiment<Rational>(t, ColumnMap{{"u1", "u2"}, {"y"}, {"rho"}});
  EXPECT_EQ(e.source, "e.csv");
  EXPECT_EQ(e.n(), 3);
  EXPECT_EQ(e.nu(), 2);
  EXPECT_EQ(e.ny(), 1);
  EXPECT_EQ(e.n_rho(), 1);
  EXPECT_EQ(e.u(0, 0), Rational(1) / Rational(10));  // 0.1 is 1/10 exactly
  EXPECT_EQ(e.u(0, 1), Rational(1) / Rational(3));
  EXPECT_EQ(e.y(1, 0), Rational(3) / Rational(10));
  EXPECT_EQ(e.rho(1, 0), Rational(1) / Rational(2));
  const Experiment<double> d = make_experiment<double>(t, ColumnMap{{"u1", "u2"}, {"y"}, {"rho"}});
  EXPECT_EQ(d.u(0, 0), 0.1);
  EXPECT_EQ(d.u(0, 1), 1.0 / 3.0);
  // No scheduling columns: n × 0.
  EXPECT_EQ(make_experiment<double>(t, ColumnMap{{"u1"}, {"y"}, {}}).rho.rows(), 3);
}

TEST(ExperimentBuilderTest, UnknownColumnListsAvailable) {
  const TextTable t = parse_csv(kCsv, "e.csv");
  const std::string e = error_of([&] { make_experiment<double>(t, ColumnMap{{"u1"}, {"yEst"}, {}}); });
  EXPECT_TRUE(contains(e, "e.csv: column 'yEst' not found")) << e;
  EXPECT_TRUE(contains(e, "available: 't', 'u1', 'u2', 'y', 'rho', 'note'")) << e;
}

TEST(ExperimentBuilderTest, BadNumbersNameFileLineColumnAndText) {
  const TextTable t = parse_csv("u,yEst\n1,2\n3,abc\n", "b.csv");
  std::string e = error_of([&] { make_experiment<Rational>(t, ColumnMap{{"u"}, {"yEst"}, {}}); });
  EXPECT_EQ(e, "b.csv:3: column 'yEst': 'abc' is not a number");
  for (const char* bad : {"nan", "NaN", "inf", "-inf", "1e", "0x10", "1/0"}) {
    const TextTable tb = parse_csv(std::string("u,y\n1,") + bad + "\n", "b.csv");
    for (int path = 0; path < 2; ++path) {
      e = error_of([&] {
        if (path == 0) make_experiment<Rational>(tb, ColumnMap{{"u"}, {"y"}, {}});
        else make_experiment<double>(tb, ColumnMap{{"u"}, {"y"}, {}});
      });
      EXPECT_TRUE(contains(e, "b.csv:2: column 'y':")) << bad << ": " << e;
    }
  }
  // Overflows a double but is an exact rational.
  const TextTable big = parse_csv("u,y\n1,1e400\n", "big.csv");
  EXPECT_NO_THROW(make_experiment<Rational>(big, ColumnMap{{"u"}, {"y"}, {}}));
  e = error_of([&] { make_experiment<double>(big, ColumnMap{{"u"}, {"y"}, {}}); });
  EXPECT_TRUE(contains(e, "big.csv:2: column 'y':") && contains(e, "overflows")) << e;
}

TEST(ExperimentBuilderTest, EmptyCellInUsedColumnOnly) {
  const TextTable t = parse_csv(kCsv, "e.csv");
  // "note" is empty on line 3, fine while unused.
  EXPECT_NO_THROW(make_experiment<double>(t, ColumnMap{{"u1"}, {"y"}, {}}));
  const std::string e = error_of([&] { make_experiment<double>(t, ColumnMap{{"u1"}, {"note"}, {}}); });
  EXPECT_TRUE(contains(e, "e.csv:2: column 'note': 'a' is not a number")) << e;
  const TextTable t2 = parse_csv("u,y\n1,\n", "e2.csv");
  EXPECT_EQ(error_of([&] { make_experiment<double>(t2, ColumnMap{{"u"}, {"y"}, {}}); }),
            "e2.csv:2: column 'y': empty cell is not a number");
}

TEST(ExperimentBuilderTest, EmptyTableIsAnError) {
  const TextTable t = parse_csv("u,y\n", "h.csv");
  EXPECT_EQ(error_of([&] { make_experiment<double>(t, ColumnMap{{"u"}, {"y"}, {}}); }), "h.csv: no data rows");
}

TEST(ExperimentBuilderTest, SelectRows) {
  const TextTable t = parse_csv(kCsv, "e.csv");
  const Experiment<Rational> e = make_experiment<Rational>(t, ColumnMap{{"u1"}, {"y"}, {"rho"}});
  const Experiment<Rational> s = select_rows(e, 1, 3);
  EXPECT_EQ(s.n(), 2);
  EXPECT_EQ(s.u(0, 0), e.u(1, 0));
  EXPECT_EQ(s.rho(1, 0), e.rho(2, 0));
  EXPECT_EQ(select_rows(e, 2, 2).n(), 0);
  EXPECT_TRUE(contains(error_of([&] { select_rows(e, 2, 4); }), "out of range"));
  EXPECT_TRUE(contains(error_of([&] { select_rows(e, 2, 1); }), "out of range"));
  EXPECT_TRUE(contains(error_of([&] { select_rows(e, -1, 1); }), "out of range"));
}

}  // namespace
}  // namespace lpvid
