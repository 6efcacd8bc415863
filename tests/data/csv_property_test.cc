/// Properties of the table readers: random well-formed CSV round-trips, and
/// corrupted input either reads or throws InputError (never crashes, never
/// another exception; run under ASan/UBSan).

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/input_error.h"
#include "core/number_text.h"
#include "data/csv_reader.h"
#include "data/experiment_builder.h"
#include "support/generators.h"

namespace lpvid {
namespace {

using gen::files::CsvText;

RC_GTEST_PROP(CsvProperty, WellFormedCsvRoundTrips, ()) {
  const CsvText c = *gen::files::csv_text();
  const TextTable t = parse_csv(c.text, "gen.csv");
  RC_ASSERT(t.header == c.header);
  RC_ASSERT(t.rows == c.rows);
  RC_ASSERT(t.line_numbers == c.line_numbers);
}

RC_GTEST_PROP(CsvProperty, NumericCsvReadsExactlyInBothScalars, ()) {
  const CsvText c = *gen::files::numeric_csv_text();
  const TextTable t = parse_table(c.text, "gen.csv");
  RC_ASSERT(t.rows == c.rows);
  ColumnMap cols;
  cols.y = c.header;
  const Experiment<Rational> q = make_experiment<Rational>(t, cols);
  const Experiment<double> d = make_experiment<double>(t, cols);
  for (size_t r = 0; r < c.rows.size(); ++r)
    for (size_t k = 0; k < c.header.size(); ++k) {
      RC_ASSERT(q.y(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(k)) == rational_from_text(c.rows[r][k]));
      RC_ASSERT(d.y(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(k)) == double_from_text(c.rows[r][k]));
    }
}

/// Reads a corrupted table every way the tools do; only InputError may escape.
void read_every_way(const std::string& text) {
  try {
    const TextTable t = parse_csv(text, "bad.csv");
    ColumnMap cols;
    cols.u = t.header;
    make_experiment<Rational>(t, cols);
    make_experiment<double>(t, cols);
  } catch (const InputError&) {
  }
  try {
    parse_table(text, "bad.csv", std::vector<std::string>{"c0", "c1"});
  } catch (const InputError&) {
  }
  try {
    const TextTable t = parse_whitespace_table(text, "bad.dat", {"c0", "c1", "c2"});
    make_experiment<Rational>(t, ColumnMap{{"c0"}, {"c1"}, {"c2"}});
    make_experiment<double>(t, ColumnMap{{"c0"}, {"c1"}, {"c2"}});
  } catch (const InputError&) {
  }
}

RC_GTEST_PROP(CsvProperty, CorruptedCsvReadsOrThrowsInputError, ()) {
  const CsvText c = *gen::files::numeric_csv_text();
  const std::string bad = *gen::files::corrupted(c.text);
  read_every_way(bad);  // any other exception fails the property
}

RC_GTEST_PROP(CsvProperty, ArbitraryBytesReadOrThrowInputError, (const std::string& text)) { read_every_way(text); }

}  // namespace
}  // namespace lpvid
