#include "verify/psd/rational_matrix_io.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/input_error.h"
#include "core/number_text.h"
#include "support/gen_matrices.h"

namespace lpvid {
namespace {

Mat<Rational> read_text(const std::string& text) {
  std::istringstream in(text);
  return read_rational_matrix(in, "m.txt");
}

/// The InputError message for `text` (fails the test if it does not throw).
std::string error_of(const std::string& text) {
  try {
    read_text(text);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return "";
}

TEST(RationalMatrixIoTest, ReadsDecimalsAndFractionsExactly) {
  const Mat<Rational> M = read_text("# a comment\n\n0.1\t-1/3  2e-3\n-1/3 7 0 # trailing comment\r\n 2E-3 0 -4/6\n");
  ASSERT_EQ(M.rows(), 3);
  ASSERT_EQ(M.cols(), 3);
  EXPECT_EQ(M(0, 0), Rational(1, 10));
  EXPECT_EQ(M(0, 1), Rational(-1, 3));
  EXPECT_EQ(M(0, 2), Rational(1, 500));
  EXPECT_EQ(M(1, 1), Rational(7));
  EXPECT_EQ(M(2, 0), Rational(1, 500));
  EXPECT_EQ(M(2, 2), Rational(-2, 3));
  // 1e-30 is not lost in a double.
  EXPECT_NE(read_text("1.000000000000000000000000000001\n")(0, 0), Rational(1));
}

TEST(RationalMatrixIoTest, ErrorsNameFileLineColumnAndReason) {
  EXPECT_NE(error_of("1 2\n2\n").find("m.txt:2: ragged row: 1 entries"), std::string::npos);
  EXPECT_NE(error_of("1 2 3\n2 1 0\n").find("m.txt:2: matrix is not square: 2 rows of 3 entries"), std::string::npos);
  EXPECT_NE(error_of("1 0\n0 1x\n").find("m.txt:2:3: "), std::string::npos);
  EXPECT_NE(error_of("# c\n1 1/0\n1/0 1\n").find("m.txt:2:3: zero denominator"), std::string::npos);
  EXPECT_NE(error_of("1 nan\nnan 1\n").find("m.txt:1:3: 'nan': NaN and infinity are not allowed"), std::string::npos);
  EXPECT_NE(error_of("-Inf 0\n0 1\n").find("m.txt:1:1: '-Inf': NaN and infinity"), std::string::npos);
  EXPECT_NE(error_of("1,0\n0,1\n").find("m.txt:1:1:"), std::string::npos);
  EXPECT_NE(error_of("0x10 0\n0 1\n").find("m.txt:1:1:"), std::string::npos);
  EXPECT_NE(error_of("1e99999 0\n0 1\n").find("exponent out of range"), std::string::npos);
  EXPECT_NE(error_of("").find("m.txt: no matrix rows"), std::string::npos);
  EXPECT_NE(error_of("# only\n   \n\t\n").find("no matrix rows"), std::string::npos);
}

TEST(RationalMatrixIoTest, UnreadableFilesAreInputErrors) {
  EXPECT_THROW(read_rational_matrix_file("/nonexistent/dir/m.txt"), InputError);
  EXPECT_THROW(read_rational_matrix_file(std::filesystem::temp_directory_path().string()), InputError);
}

TEST(RationalMatrixIoTest, WriterOutputIsReadBackExactly) {
  Mat<Rational> M(2, 2);
  M << Rational(1, 3), Rational(-7), Rational(-7), rational_from_text("1e-30");
  std::ostringstream out;
  write_rational_matrix(out, M, "two lines\nof comment");
  EXPECT_EQ(out.str().substr(0, 24), "# two lines\n# of comment");
  EXPECT_EQ(read_text(out.str()), M);
  const std::string path = (std::filesystem::temp_directory_path() / "lpvid_rational_matrix_io_test.txt").string();
  write_rational_matrix_file(path, M);
  EXPECT_EQ(read_rational_matrix_file(path), M);
  std::remove(path.c_str());
}

RC_GTEST_PROP(RationalMatrixIoProperty, WriteThenReadIsIdentity, ()) {
  const int n = *gen::psd_dimension();
  const Mat<Rational> M = *gen::rational_matrix(n, n, gen::small_rational());
  std::ostringstream out;
  write_rational_matrix(out, M);
  RC_ASSERT(read_text(out.str()) == M);
}

RC_GTEST_PROP(RationalMatrixIoProperty, DecimalTextIsReadAsItsExactValue, (int mantissa, int exponent)) {
  const int e = exponent % 40;
  const std::string text = std::to_string(mantissa) + "e" + std::to_string(e);
  Rational expected(mantissa);
  for (int i = 0; i < (e < 0 ? -e : e); ++i) expected = e < 0 ? expected / Rational(10) : expected * Rational(10);
  RC_ASSERT(read_text(text + "\n")(0, 0) == expected);
}

}  // namespace
}  // namespace lpvid
