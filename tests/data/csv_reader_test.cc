#include "data/csv_reader.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "core/number_text.h"
#include "data/experiment_builder.h"

#include "support/input_error_text.h"

namespace lpvid {
namespace {

using gen::error_of;

using gen::contains;

TEST(CsvReaderTest, ReadsHeaderQuotesCrlfAndTrailingCommas) {
  const TextTable t = parse_csv("\"uEst\",\"uVal\", yEst ,\r\n1.5,2,3,\r\n-4, 5e-1 ,,\r\n\r\n", "t.csv");
  EXPECT_EQ(t.file, "t.csv");
  EXPECT_EQ(t.header, (std::vector<std::string>{"uEst", "uVal", "yEst"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0], (std::vector<std::string>{"1.5", "2", "3"}));
  EXPECT_EQ(t.rows[1], (std::vector<std::string>{"-4", "5e-1", ""}));
  EXPECT_EQ(t.line_numbers, (std::vector<long>{2, 3}));
}

TEST(CsvReaderTest, QuotedCellsMayHoldCommasAndQuotes) {
  const TextTable t = parse_csv("a,\"b,c\",\"say \"\"hi\"\"\"\n1,2,3\n", "q.csv");
  EXPECT_EQ(t.header, (std::vector<std::string>{"a", "b,c", "say \"hi\""}));
  EXPECT_EQ(t.rows[0], (std::vector<std::string>{"1", "2", "3"}));
}

TEST(CsvReaderTest, SkipsBlankLinesAndByteOrderMark) {
  const TextTable t = parse_csv("\xEF\xBB\xBF\n\nx,y\n\n1,2\n   \n3,4", "b.csv");
  EXPECT_EQ(t.header, (std::vector<std::string>{"x", "y"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.line_numbers, (std::vector<long>{5, 7}));
}

TEST(CsvReaderTest, RaggedRowIsAnErrorWithLine) {
  std::string e = error_of([] { parse_csv("a,b\n1,2\n1,2,3\n", "r.csv"); });
  EXPECT_TRUE(contains(e, "r.csv:3:")) << e;
  EXPECT_TRUE(contains(e, "expected 2 cells")) << e;
  EXPECT_TRUE(contains(e, "got 3")) << e;
  e = error_of([] { parse_csv("a,b,c\n1,2\n", "r.csv"); });
  EXPECT_TRUE(contains(e, "r.csv:2:")) << e;
  // One trailing empty cell is a trailing comma, two are not.
  EXPECT_NO_THROW(parse_csv("a,b\n1,2,\n", "r.csv"));
  e = error_of([] { parse_csv("a,b\n1,2,,\n", "r.csv"); });
  EXPECT_TRUE(contains(e, "got 4")) << e;
}

TEST(CsvReaderTest, DuplicateAndEmptyColumnNames) {
  std::string e = error_of([] { parse_csv("u,y,u\n1,2,3\n", "d.csv"); });
  EXPECT_TRUE(contains(e, "d.csv:1:")) << e;
  EXPECT_TRUE(contains(e, "duplicate column name 'u'")) << e;
  e = error_of([] { parse_csv("\"u\",\"u\"\n", "d.csv"); });
  EXPECT_TRUE(contains(e, "duplicate")) << e;
  e = error_of([] { parse_csv("u,,y\n", "d.csv"); });
  EXPECT_TRUE(contains(e, "column 2 has an empty name")) << e;
}

TEST(CsvReaderTest, QuoteErrors) {
  std::string e = error_of([] { parse_csv("a,\"b\n", "q.csv"); });
  EXPECT_TRUE(contains(e, "q.csv:1:") && contains(e, "unterminated quote")) << e;
  e = error_of([] { parse_csv("a,b\n\"1\"x,2\n", "q.csv"); });
  EXPECT_TRUE(contains(e, "q.csv:2:") && contains(e, "after closing quote")) << e;
  e = error_of([] { parse_csv("a,b\n1\"2,3\n", "q.csv"); });
  EXPECT_TRUE(contains(e, "quote inside an unquoted cell")) << e;
}

TEST(CsvReaderTest, EmptyFileHasNoHeader) {
  EXPECT_TRUE(contains(error_of([] { parse_csv("", "e.csv"); }), "no header"));
  EXPECT_TRUE(contains(error_of([] { parse_csv("\r\n  \n", "e.csv"); }), "no header"));
  // A header without rows is a table without rows (make_experiment rejects it).
  EXPECT_EQ(parse_csv("a,b\n", "h.csv").rows.size(), 0u);
}

TEST(CsvReaderTest, MissingFileNamesThePath) {
  const std::string e = error_of([] { read_csv("/nonexistent/dir/data.csv"); });
  EXPECT_TRUE(contains(e, "/nonexistent/dir/data.csv") && contains(e, "cannot open")) << e;
}

TEST(WhitespaceTableTest, ReadsTabsSpacesAndComments) {
  const TextTable t = parse_whitespace_table("% dryer\n  6.41\t 4.76\t\n\n3.41 4.7636589e+00\n", "w.dat", {"u", "y"});
  EXPECT_EQ(t.header, (std::vector<std::string>{"u", "y"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[1], (std::vector<std::string>{"3.41", "4.7636589e+00"}));
  EXPECT_EQ(t.line_numbers, (std::vector<long>{2, 4}));
  const std::string e = error_of([] { parse_whitespace_table("1 2\n1 2 3\n", "w.dat", {"u", "y"}); });
  EXPECT_TRUE(contains(e, "w.dat:2:") && contains(e, "got 3")) << e;
  EXPECT_TRUE(contains(error_of([] { parse_whitespace_table("1\n", "w.dat", {"u", "u"}); }), "duplicate"));
}

TEST(ReadTableTest, DispatchRule) {
  // Numbers on the first line + names: headerless (whitespace or CSV).
  TextTable w = parse_table("1 2\n3 4\n", "n.dat", std::vector<std::string>{"u", "y"});
  EXPECT_EQ(w.header, (std::vector<std::string>{"u", "y"}));
  EXPECT_EQ(w.rows.size(), 2u);
  TextTable c = parse_table("# comment\n1,2,\n3,4,\n", "n.csv", std::vector<std::string>{"u", "y"});
  EXPECT_EQ(c.rows.size(), 2u);
  EXPECT_EQ(c.rows[1], (std::vector<std::string>{"3", "4"}));
  // Numbers on the first line without names: an error, not a header "1","2".
  EXPECT_TRUE(contains(error_of([] { parse_table("1,2\n", "n.csv"); }), "looks like numbers"));
  // A header: CSV, names ignored.
  TextTable h = parse_table("u,y\n1,2\n", "h.csv", std::vector<std::string>{"a", "b"});
  EXPECT_EQ(h.header, (std::vector<std::string>{"u", "y"}));
}

// ---- the real data sets (read in place, never copied into the repository)

const std::string kData = LPVID_SOURCE_DIR "/../shared/data/";

/// Independent split of one line on commas (no quote handling needed here).
std::vector<std::string> simple_split(std::string line) {
  if (!line.empty() && line.back() == '\r') line.pop_back();
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  return out;
}

TEST(RealDataTest, CascadedTanksReadsInPlace) {
  const std::string path = kData + "cascaded-tanks/dataBenchmark.csv";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not present";
  const TextTable t = read_csv(path);
  EXPECT_EQ(t.header, (std::vector<std::string>{"uEst", "uVal", "yEst", "yVal", "Ts"}));
  ASSERT_EQ(t.rows.size(), 1024u);

  std::ifstream in(path);
  std::vector<std::vector<std::string>> lines;
  for (std::string line; std::getline(in, line);)
    if (line != "\r" && !line.empty()) lines.push_back(simple_split(line));
  ASSERT_EQ(lines.size(), 1025u);
  const auto& first = lines[1];
  const auto& last = lines[1024];
  for (size_t c = 0; c < 4; ++c) {
    EXPECT_EQ(t.rows.front()[c], first[c]);
    EXPECT_EQ(t.rows.back()[c], last[c]);
  }
  EXPECT_EQ(t.rows.front()[4], "4");
  EXPECT_EQ(t.rows.back()[4], "");

  const Experiment<Rational> est = make_experiment<Rational>(t, ColumnMap{{"uEst"}, {"yEst"}, {}});
  EXPECT_EQ(est.n(), 1024);
  EXPECT_EQ(est.u(0, 0), rational_from_text(first[0]));
  EXPECT_EQ(est.y(1023, 0), rational_from_text(last[2]));
  const Experiment<double> val = make_experiment<double>(t, ColumnMap{{"uVal"}, {"yVal"}, {}});
  EXPECT_EQ(val.y(1023, 0), double_from_text(last[3]));
  // Ts is empty after the first row: using it as a column is an error at line 3.
  const std::string e = error_of([&] { make_experiment<double>(t, ColumnMap{{"uEst"}, {"Ts"}, {}}); });
  EXPECT_TRUE(contains(e, "dataBenchmark.csv:3: column 'Ts'")) << e;
}

TEST(RealDataTest, DryerReadsInPlace) {
  const std::string path = kData + "dryer/dryer.dat";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not present";
  const TextTable t = read_whitespace_table(path, {"u", "y"});
  ASSERT_EQ(t.rows.size(), 1000u);
  const TextTable same = read_table(path, std::vector<std::string>{"u", "y"});
  EXPECT_EQ(same.rows, t.rows);
  const Experiment<Rational> e = make_experiment<Rational>(t, ColumnMap{{"u"}, {"y"}, {}});
  EXPECT_EQ(e.n(), 1000);
  EXPECT_EQ(e.u(0, 0), rational_from_text("6.41"));
  EXPECT_EQ(e.y(0, 0), rational_from_text("4.7660989"));
}

}  // namespace
}  // namespace lpvid
