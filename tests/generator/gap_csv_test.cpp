// SPDX-License-Identifier: Apache-2.0
// Gap CSV input: good files parse; every malformed file gives an InputError naming file, line and field.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "ctab/core/error.hpp"
#include "ctab/io/gap_csv.hpp"
#include "test_support.hpp"

using namespace ctab::gen;

namespace {

std::string error_of(const std::string& text) {
  std::istringstream in(text);
  try {
    (void)parse_gap_csv(in, "gap.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

const std::string kHeader = "y_m,h_m,A_per_m,B_per_m\n";

}  // namespace

TEST(GapCsv, ParsesCommentsExtraColumnsAndOrder) {
  std::istringstream in("# comment\nB_per_m,note,y_m,h_m,A_per_m\n1,a,-1e-3,1e-6,2\n1,b,0,0,2\n1,c,1e-3,1e-6,2\n");
  const GapProfile gap = parse_gap_csv(in, "x.csv");
  ASSERT_EQ(gap.size(), 3u);
  EXPECT_DOUBLE_EQ(gap.y_m[0], -1e-3);
  EXPECT_DOUBLE_EQ(gap.A_per_m[2], 2.0);
}

TEST(GapCsv, RejectsMalformedInputWithFileLineAndField) {
  EXPECT_EQ(error_of(""), "gap.csv: empty gap file: expected a header y_m,h_m,A_per_m,B_per_m and rows");
  EXPECT_EQ(error_of("y,h,A,B\n"), "gap.csv:1: header must name the columns y_m,h_m,A_per_m,B_per_m; missing 'y_m'");
  EXPECT_EQ(error_of(kHeader + "0,0,1,1\n1e-3,abc,1,1\n"), "gap.csv:3: field 'h_m': expected a number, got 'abc'");
  EXPECT_EQ(error_of(kHeader + "0,0,1,1\n1e-3,nan,1,1\n"), "gap.csv:3: field 'h_m': value is not finite");
  EXPECT_EQ(error_of(kHeader + "0,0,1\n"), "gap.csv:2: expected 4 fields, got 3");
  EXPECT_EQ(error_of(kHeader + "0,0,1,1\n0,0,1,1\n"),
            "gap.csv:3: field 'y_m': strips must be strictly increasing in y");
  EXPECT_EQ(error_of(kHeader + "0,0,-1,1\n"), "gap.csv:2: field 'A_per_m': must be positive, got '-1'");
  EXPECT_EQ(error_of(kHeader + "0,0,1,1\n1e-3,-1,1,1\n"),
            "gap.csv:3: field 'h_m': a separation must not be negative (the bodies' gap before loading), got '-1'");
  EXPECT_EQ(error_of(kHeader + "-1e-3,1e-6,1,1\n0,-1e-10,1,1\n1e-3,1e-6,1,1\n"), "no error") << "rounding of 0";
  EXPECT_EQ(error_of(kHeader + "0,0,1,1\n1e-3,0,1,1\n"), "gap.csv:3: need at least 3 rows of gap data, got 2");
  EXPECT_EQ(error_of(kHeader), "gap.csv:1: need at least 3 rows of gap data, got 0");
}

TEST(GapCsv, SkipsAUtf8ByteOrderMark) {
  std::istringstream in("\xEF\xBB\xBF" + kHeader + "-1e-3,1e-6,2,1\n0,0,2,1\n1e-3,1e-6,2,1\n");
  const GapProfile gap = parse_gap_csv(in, "bom.csv");
  ASSERT_EQ(gap.size(), 3u);
  EXPECT_DOUBLE_EQ(gap.y_m[0], -1e-3);
}

TEST(GapCsv, EchoesAHugeFieldCutAt60Characters) {
  const std::string huge(2'000'000, 'x');  // a 2 MB field
  const std::string message = error_of(kHeader + "0,0,1,1\n1e-3," + huge + ",1,1\n");
  EXPECT_EQ(message, "gap.csv:3: field 'h_m': expected a number, got '" + std::string(60, 'x') + "\xE2\x80\xA6'");
}

TEST(GapCsv, MissingFile) {
  try {
    (void)read_gap_csv("/nonexistent/gap.csv");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/gap.csv: cannot open gap file");
  }
}

TEST(GapCsv, ExampleFilesRoundTrip) {
  const GapProfile gap = read_gap_csv(ctab::test::source_path("examples/gaps/nonhertz_r40_r500.csv"));
  std::ostringstream out;
  write_gap_csv(gap, out);
  std::istringstream in(out.str());
  const GapProfile again = parse_gap_csv(in, "round-trip");
  ASSERT_EQ(again.size(), gap.size());
  for (std::size_t i = 0; i < gap.size(); ++i) {
    EXPECT_EQ(again.y_m[i], gap.y_m[i]);
    EXPECT_EQ(again.h_m[i], gap.h_m[i]);
    EXPECT_EQ(again.B_per_m[i], gap.B_per_m[i]);
  }
}
