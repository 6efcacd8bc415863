// The figures of each record and of all records pooled (certify/record_figures.h) and their table (cli/records_report.h)
// on two records of two samples each, every number worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "certify/record_figures.h"
#include "cli/records_report.h"

namespace lpvid {
namespace {

TEST(RecordFigures, EachRecordAndThePooledLineByHand) {
  Mat<double> y(4, 1), r(4, 1), w(4, 1);
  y << 0, 2, 0, 4;  // record 1: mean 1, ||y - mean||^2 = 2; record 2: mean 2, 8; pooled: mean 1.5, 11
  r << 1, 1, 2, 0;  // ||r_1||^2 = 2, ||r_2||^2 = 4
  w << 1, 0, 0, 0;  // d = r - w = (0, 1 | 2, 0): ||d_1||^2 = 1, ||d_2||^2 = 4
  const RecordTable t = record_figures(y, r, {2, 2}, w);
  ASSERT_EQ(t.records.size(), 2u);
  EXPECT_EQ(t.records[0].samples, 2);
  EXPECT_DOUBLE_EQ(t.records[0].rms_residual, 1.0);
  EXPECT_NEAR(t.records[0].fit_percent, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(t.records[1].rms_residual, std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(t.records[1].fit_percent, 100.0 * (1.0 - 2.0 / std::sqrt(8.0)));
  EXPECT_DOUBLE_EQ(*t.records[0].rms_noise, std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(*t.records[1].rms_noise, std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(*t.records[0].dmax_share, 0.2);
  EXPECT_DOUBLE_EQ(*t.records[1].dmax_share, 0.8);
  EXPECT_EQ(t.pooled.samples, 4);
  EXPECT_DOUBLE_EQ(t.pooled.rms_residual, std::sqrt(1.5));
  EXPECT_DOUBLE_EQ(t.pooled.fit_percent, 100.0 * (1.0 - std::sqrt(6.0 / 11.0)));
  EXPECT_DOUBLE_EQ(*t.pooled.rms_noise, std::sqrt(5.0 / 4.0));
}

TEST(RecordFigures, WithoutACertificateThereIsNoNoiseColumn) {
  Mat<double> y(3, 1), r(3, 1);
  y << 1, 2, 3;
  r << 0, 0, 1;
  const RecordTable t = record_figures(y, r, {}, std::nullopt);  // one record
  ASSERT_EQ(t.records.size(), 1u);
  EXPECT_FALSE(t.records[0].rms_noise.has_value());
  EXPECT_FALSE(t.records[0].dmax_share.has_value());
  EXPECT_DOUBLE_EQ(t.records[0].rms_residual, std::sqrt(1.0 / 3.0));
  EXPECT_DOUBLE_EQ(t.pooled.fit_percent, 100.0 * (1.0 - 1.0 / std::sqrt(2.0)));
  const std::string text = cli::records_text({DataReference{"a.csv", "00", {}, 0, -1}}, t);
  EXPECT_NE(text.find("pooled"), std::string::npos) << text;
  EXPECT_EQ(text.find("rms(d)"), std::string::npos) << text;
}

}  // namespace
}  // namespace lpvid
