// SPDX-License-Identifier: Apache-2.0
// Profiles: the built-in S1002 and 60E1 against the Manchester point files, the readers, and malformed files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "ctab/profiles/builtin_profiles.hpp"
#include "ctab/core/error.hpp"
#include "ctab/io/profile_io.hpp"
#include "ctab/profiles/rail_cant.hpp"
#include "test_support.hpp"

using namespace ctab::gen;

namespace {

std::string profile_file(const std::string& name) { return ctab::test::shared_path("profiles/" + name); }

ProfileReadOptions as_given() {
  ProfileReadOptions o;
  o.inclination = 0.0;
  return o;
}

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

std::string error_of(const std::string& path, ProfileRole role) {
  try {
    (void)read_profile_points(path, role, as_given());
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string ten_points(double step_sign = 1.0) {
  std::string text;
  for (int i = 0; i < 12; ++i)
    text += std::to_string(step_sign * (-20.0 + 4.0 * i)) + " " + std::to_string(0.01 * (i - 6) * (i - 6)) + "\n";
  return text;
}

}  // namespace

TEST(Profiles, BuiltinS1002MatchesTheManchesterFile) {
  CTAB_REQUIRE_SHARED();
  const ProfilePoints points = read_profile_points(profile_file("MBench_S1002_v3.prw"), ProfileRole::Wheel, as_given());
  ASSERT_GE(points.y_m.size(), 390u);
  double worst = 0.0;
  for (std::size_t i = 0; i < points.y_m.size(); ++i)
    worst = std::max(worst, std::abs(s1002_mm(points.y_m[i] * 1e3).f - points.z_m[i] * 1e3));
  EXPECT_LT(worst, 1e-4);  // mm
  const ProfileTable table(*s1002_curve(), kProfileTableStep_m, "S1002");
  EXPECT_NEAR(table.at(-0.055).z, 28e-3, 1e-9);                // flange tip F = 28 mm at S = -55 mm
  EXPECT_NEAR(1.0 / table.at(0.0).curvature(), 0.320, 0.002);  // tread radius 320 mm at the tape circle
}

TEST(Profiles, Builtin60E1Inclined1To40MatchesTheManchesterFileTo005mm) {
  CTAB_REQUIRE_SHARED();
  const ProfileTable builtin(*uic60_inclined_curve(1.0 / 40.0), kProfileTableStep_m, "UIC60");
  const auto top = builtin.highest_point();
  EXPECT_NEAR(top.first, 0.0, 2e-5);
  EXPECT_NEAR(top.second, 0.0, 1e-9);
  const ProfilePoints points = read_profile_points(profile_file("MBench_UIC60_v3.prr"), ProfileRole::Rail, as_given());
  double worst = 0.0;
  for (std::size_t i = 0; i < points.y_m.size(); ++i) {
    if (!builtin.contains(points.y_m[i])) continue;
    const ProfilePoint p = builtin.at(points.y_m[i]);
    worst = std::max(worst, std::abs(p.z - points.z_m[i]) / std::sqrt(1.0 + p.dz * p.dz));  // normal distance
  }
  EXPECT_LT(worst, 0.05e-3);
  EXPECT_GT(worst, 0.02e-3);  // the file's R300/R80 tangent is at 10.5 mm, not 10.228: a real, known difference
}

TEST(Profiles, ReadersAgree) {
  CTAB_REQUIRE_SHARED();
  const ProfileTable prr = load_profile(profile_file("MBench_UIC60_v3.prr"), ProfileRole::Rail, as_given());
  const ProfileTable ban = load_profile(profile_file("MBench_UIC60_v3.ban"), ProfileRole::Rail, as_given());
  for (double y = -0.040; y < 0.028; y += 1e-3) EXPECT_NEAR(prr.at(y).z, ban.at(y).z, 1e-9) << y;
  const ProfileTable wheel = load_profile(profile_file("MBench_S1002_v3.prw"), ProfileRole::Wheel, as_given());
  const ProfileTable builtin = load_profile("S1002", ProfileRole::Wheel, as_given());
  for (double y = -0.060; y < 0.058; y += 1e-3) EXPECT_NEAR(wheel.at(y).z, builtin.at(y).z, 5e-6) << y;
  // A 2-column file in mm, mirrored and upside down, comes back canonical.
  std::string text = "y z\n";
  for (double s = 59.0; s >= -60.0; s -= 0.5) text += std::to_string(-s) + "," + std::to_string(-s1002_mm(s).f) + "\n";
  const ProfileTable plain = load_profile(write_temp("s1002_mirrored.csv", text), ProfileRole::Wheel, as_given());
  for (double y = -0.050; y < 0.050; y += 2e-3) EXPECT_NEAR(plain.at(y).z, builtin.at(y).z, 5e-6) << y;
}

TEST(Profiles, MalformedFilesNameFileLineAndProblem) {
  EXPECT_EQ(error_of("/nonexistent/x.prr", ProfileRole::Rail), "/nonexistent/x.prr: cannot open profile file");
  const std::string no_header = write_temp("no_header.prr", "point.begin\n0 0\npoint.end\n");
  EXPECT_EQ(error_of(no_header, ProfileRole::Rail), no_header + ": missing Simpack header.begin/spline.begin block");
  const std::string bad_number = write_temp("bad.txt", "0 0\n1 x\n");
  EXPECT_EQ(error_of(bad_number, ProfileRole::Rail), bad_number + ":2: expected numeric coordinates, got '1 x'");
  const std::string few = write_temp("few.txt", "0 0\n1 1\n2 4\n");
  EXPECT_EQ(error_of(few, ProfileRole::Rail), few + ": expected at least 10 profile points, got 3");
  const std::string nan = write_temp("nan.txt", "0 0\n1 nan\n");
  EXPECT_EQ(error_of(nan, ProfileRole::Rail), nan + ":2: non-finite coordinate");
  std::string loop = ten_points();
  loop += "10 0.5\n";  // steps back in y
  const std::string backwards = write_temp("loop.txt", loop);
  EXPECT_NE(error_of(backwards, ProfileRole::Rail).find("loop.txt:13: profile steps backwards in y"), std::string::npos)
      << error_of(backwards, ProfileRole::Rail);
  const std::string metres = write_temp("metres.txt", ten_points());
  ProfileReadOptions in_metres = as_given();
  in_metres.length_unit_m = 1.0;
  try {
    (void)read_profile_points(metres, ProfileRole::Rail, in_metres);
    FAIL() << "expected an implausible-length error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("check the length unit"), std::string::npos);
  }
  const std::string no_points = write_temp("no_points.whl", "Filename=x\nColumnDef=X,Y\n\n");
  EXPECT_EQ(error_of(no_points, ProfileRole::Wheel), no_points + ": expected at least 10 profile points, got 0");
}

// ---- Input checks of issue 7: rails inclined twice, MiniProf counts, Simpack scale, duplicates, BOM, echoes.

namespace {

//! Points of a built-in table every `step_mm`, as "y z" lines in mm.
std::string points_text(const ProfileTable& table, double step_mm = 0.1) {
  std::string text;
  char line[80];
  for (double y = table.y_min(); y <= table.y_max(); y += step_mm * 1e-3) {
    std::snprintf(line, sizeof line, "%.6f %.6f\n", y * 1e3, table.at(y).z * 1e3);
    text += line;
  }
  return text;
}

ProfileTable builtin_60e1(double inclination) {
  return ProfileTable(*uic60_inclined_curve(inclination), kProfileTableStep_m, "60E1");
}

std::optional<HeadCant> cant_of(const ProfileTable& table) {
  std::vector<double> y, z;
  for (double s = table.y_min(); s <= table.y_max(); s += 0.1e-3) {
    y.push_back(s);
    z.push_back(table.at(s).z);
  }
  return measure_head_cant(y, z);
}

std::string load_error(const std::string& path, ProfileRole role, double inclination) {
  ProfileReadOptions options;
  options.inclination = inclination;
  try {
    (void)load_profile(path, role, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

//! A Simpack file of the given points ("y z" lines in the file's unit) with units.len.f = `per_metre`.
std::string simpack_text(const std::string& points, double per_metre, const std::string& extra = "") {
  return "header.begin\n  version = 1\nheader.end\nspline.begin\n  units.len.f = " + std::to_string(per_metre) + "\n" +
         extra + "  point.begin\n" + points + "  point.end\nspline.end\n";
}

std::string s1002_points_mm() {
  std::string text;
  char line[80];
  for (double s = -69.6; s <= 60.0 + 1e-9; s += 0.2) {
    std::snprintf(line, sizeof line, "%.6f %.6f\n", s, s1002_mm(s).f);
    text += line;
  }
  return text;
}

//! A MiniProf rail file: header, then `rows` rows of a parabola (numbers written %.7E), the last `last_row`.
std::string miniprof_text(const std::string& declared, int rows, const std::string& last_row = "",
                          bool final_newline = true) {
  std::string text = "Filename=t.ban\nXYPoints=" + declared + "\nColumnDef=X,Y\n\n";
  char line[80];
  for (int i = 0; i < rows; ++i) {
    std::snprintf(line, sizeof line, "%.7E\t%.7E\n", -20.0 + 4.0 * i, 0.01 * (i - 6) * (i - 6));
    text += line;
  }
  text += last_row;
  if (!final_newline && !text.empty() && text.back() == '\n') text.pop_back();
  return text;
}

}  // namespace

TEST(HeadCant, Builtin60E1UprightAndInclined) {
  const auto upright = cant_of(builtin_60e1(0.0));
  ASSERT_TRUE(upright);
  EXPECT_NEAR(upright->cant, 0.0, 1e-4);
  EXPECT_NEAR(upright->depth_m, 14e-3, 1e-12);
  for (const double inclination : {1.0 / 40.0, 1.0 / 30.0, 1.0 / 20.0, -1.0 / 40.0}) {
    const auto cant = cant_of(builtin_60e1(inclination));
    ASSERT_TRUE(cant) << inclination;
    EXPECT_NEAR(cant->cant, inclination, 0.02 * std::abs(inclination)) << inclination;  // within 2 %
  }
}

TEST(HeadCant, ManchesterRailFileIsInclined1To40) {
  const ProfilePoints points = read_profile_points(profile_file("MBench_UIC60_v3.prr"), ProfileRole::Rail, as_given());
  const auto cant = measure_head_cant(points.y_m, points.z_m);
  ASSERT_TRUE(cant);
  EXPECT_NEAR(cant->cant, 1.0 / 40.0, 5e-4);
}

TEST(HeadCant, NotMeasuredOnACrownOnlyProfile) {
  const ProfileTable head = builtin_60e1(0.0);
  std::vector<double> y, z;
  for (double s = -15e-3; s <= 15e-3; s += 0.1e-3) {  // about 1 mm deep: no faces to find
    y.push_back(s);
    z.push_back(head.at(s).z);
  }
  EXPECT_FALSE(measure_head_cant(y, z));
}

TEST(InclinedTwice, AnInclinedRailFileIsNotInclinedAgain) {
  const std::string inclined = write_temp("inclined_1_40.txt", points_text(builtin_60e1(1.0 / 40.0)));
  for (const double inclination : {1.0 / 40.0, 1.0 / 20.0}) {
    const std::string message = load_error(inclined, ProfileRole::Rail, inclination);
    EXPECT_TRUE(contains(message, inclined + ": the rail head is already canted: measured cant 0.02")) << message;
    EXPECT_TRUE(contains(message, "pass --inclination 0 (inclination = \"0\" in a config)")) << message;
  }
  EXPECT_TRUE(contains(load_error(inclined, ProfileRole::Rail, 1.0 / 40.0), "inclining it by 1:40 would give 1:20."));
  EXPECT_EQ(load_error(inclined, ProfileRole::Rail, 0.0), "no error");
}

TEST(InclinedTwice, AnUprightRailFileIsInclinedLikeTheBuiltin) {
  const std::string upright = write_temp("upright_60e1.txt", points_text(builtin_60e1(0.0)));
  ProfileReadOptions options;  // the default inclination 1/40
  const ProfileTable from_file = load_profile(upright, ProfileRole::Rail, options);
  const ProfileTable builtin = load_profile("60E1", ProfileRole::Rail, options);
  for (double y = -0.025; y <= 0.025; y += 1e-3) EXPECT_NEAR(from_file.at(y).z, builtin.at(y).z, 2e-6) << y;
}

TEST(InclinedTwice, ManchesterRailFileWithTheDefaultInclinationIsAnError) {
  const std::string path = profile_file("MBench_UIC60_v3.prr");
  const std::string message = load_error(path, ProfileRole::Rail, 1.0 / 40.0);
  EXPECT_EQ(
      message.rfind(path + ": the rail head is already canted: measured cant 0.0247 (1:40.4; the limit is 0.0125)", 0),
      0u)
      << message;
  EXPECT_EQ(load_error(path, ProfileRole::Rail, 0.0), "no error");
}

TEST(MiniProf, DeclaredPointCountIsChecked) {
  EXPECT_EQ(error_of(write_temp("ok.ban", miniprof_text("12", 12)), ProfileRole::Rail), "no error");
  const std::string short_file = write_temp("short.ban", miniprof_text("12", 11));
  EXPECT_EQ(error_of(short_file, ProfileRole::Rail),
            short_file + ":15: expected 12 points (XYPoints on line 2), found 11");
  const std::string long_file = write_temp("long.ban", miniprof_text("10", 12));
  EXPECT_EQ(error_of(long_file, ProfileRole::Rail),
            long_file + ":16: expected 10 points (XYPoints on line 2), found 12");
  const std::string bad_count = write_temp("bad_count.ban", miniprof_text("12.5", 12));
  EXPECT_EQ(error_of(bad_count, ProfileRole::Rail),
            bad_count + ":2: XYPoints: expected a whole number of points, got '12.5'");
}

TEST(MiniProf, MarkedRowsCountButAreNotUsed) {
  std::string text = miniprof_text("14", 12);
  text += "\" 2.8000000E+01\t3.6000000E-01\n\" 3.2000000E+01\t4.9000000E-01\n";
  const std::string path = write_temp("marked.ban", text);
  EXPECT_EQ(read_profile_points(path, ProfileRole::Rail, as_given()).y_m.size(), 12u);
}

TEST(MiniProf, DeclaredColumnCountIsChecked) {
  const std::string path = write_temp("one_column.ban", miniprof_text("12", 11, "2.4000000E+01\n"));
  EXPECT_EQ(error_of(path, ProfileRole::Rail),
            path + ":16: expected 2 numbers per point (ColumnDef on line 3), found 1");
}

TEST(MiniProf, ALastNumberCutShortIsAnError) {
  const std::string cut = write_temp("cut.ban", miniprof_text("12", 11, "2.4000000E+01\t3.6", false));
  EXPECT_EQ(
      error_of(cut, ProfileRole::Rail),
      cut + ":16: the last point looks cut short: '3.6' is not written like '1.6000000E-01' on line 15 and the file "
            "ends without a newline (truncated file?)");
  // The same last row complete, without the final newline: fine.
  EXPECT_EQ(error_of(write_temp("whole.ban", miniprof_text("12", 11, "2.4000000E+01\t3.6000000E-01", false)),
                     ProfileRole::Rail),
            "no error");
}

TEST(SimpackScale, WheelUnitFactorOffBy2IsNamed) {
  EXPECT_EQ(error_of(write_temp("s1002.prw", simpack_text(s1002_points_mm(), 1000.0)), ProfileRole::Wheel), "no error");
  const std::string doubled = write_temp("s1002_x2.prw", simpack_text(s1002_points_mm(), 500.0));
  EXPECT_EQ(error_of(doubled, ProfileRole::Wheel),
            doubled + ": wheel profile width 259.2 mm is outside 100 to 160 mm: check units.len.f (scale)");
  const std::string halved = write_temp("s1002_half.prw", simpack_text(s1002_points_mm(), 2000.0));
  EXPECT_EQ(error_of(halved, ProfileRole::Wheel),
            halved + ": wheel profile width 64.8 mm is outside 100 to 160 mm: check units.len.f (scale)");
  const std::string shifted =
      write_temp("s1002_shifted.prw", simpack_text(s1002_points_mm(), 1000.0, "  shift.y = 75\n"));
  EXPECT_EQ(
      error_of(shifted, ProfileRole::Wheel),
      shifted +
          ": wheel profile spans y = 5.4 to 135.0 mm, without the tape circle y = 0: check shift.y and units.len.f");
  const std::string low = write_temp("s1002_low.prw", simpack_text(s1002_points_mm(), 1000.0, "  shift.y = 69.6\n"));
  EXPECT_TRUE(
      contains(error_of(low, ProfileRole::Wheel), "wheel flange height (flange tip above the tape circle y = 0) 14."))
      << error_of(low, ProfileRole::Wheel);
}

TEST(SimpackScale, RailUnitFactorOffBy2IsNamed) {
  const std::string points = points_text(builtin_60e1(0.0), 0.25);
  EXPECT_EQ(error_of(write_temp("60e1.prr", simpack_text(points, 1000.0)), ProfileRole::Rail), "no error");
  const std::string doubled = write_temp("60e1_x2.prr", simpack_text(points, 500.0));
  EXPECT_TRUE(contains(error_of(doubled, ProfileRole::Rail), doubled + ": rail profile width 14"))
      << error_of(doubled, ProfileRole::Rail);
  EXPECT_TRUE(contains(error_of(doubled, ProfileRole::Rail), " mm is outside 50 to 120 mm: check units.len.f (scale)"));
  const std::string halved = write_temp("60e1_half.prr", simpack_text(points, 2000.0));
  EXPECT_TRUE(contains(error_of(halved, ProfileRole::Rail), halved + ": rail profile width 3"))
      << error_of(halved, ProfileRole::Rail);
}

TEST(Profiles, DuplicatePointIsNamedNotCalledALoop) {
  std::string text;
  for (int i = 0; i < 12; ++i) {
    const std::string row = std::to_string(-20.0 + 4.0 * i) + " " + std::to_string(0.01 * (i - 6) * (i - 6)) + "\n";
    text += row;
    if (i == 5) text += row;  // line 7 repeats line 6
  }
  const std::string path = write_temp("duplicate.txt", text);
  EXPECT_EQ(error_of(path, ProfileRole::Rail),
            path + ":7: duplicate point at line 7 (y = 0, z = 0.01 as in the file; the same as line 6): remove it");
}

TEST(Profiles, ByteOrderMarkIsSkippedInColumnFiles) {
  const ProfilePoints with_header =
      read_profile_points(write_temp("bom_header.csv", "\xEF\xBB\xBFy,z\n" + ten_points()), ProfileRole::Rail,
                          as_given());
  EXPECT_EQ(with_header.y_m.size(), 12u);
  const ProfilePoints bare =
      read_profile_points(write_temp("bom.txt", "\xEF\xBB\xBF" + ten_points()), ProfileRole::Rail, as_given());
  ASSERT_EQ(bare.y_m.size(), 12u);
  EXPECT_DOUBLE_EQ(bare.y_m.front(), -20e-3);
}

TEST(Profiles, HugeFieldIsEchoedCutShort) {
  const std::string path = write_temp("huge.txt", "0 0\n1 " + std::string(2'000'000, 'x') + "\n");
  EXPECT_EQ(error_of(path, ProfileRole::Rail),
            path + ":2: expected numeric coordinates, got '1 " + std::string(58, 'x') + "\xE2\x80\xA6'");
}

TEST(Profiles, InclinationTextIsEchoedCutShort) {
  try {
    (void)parse_inclination(std::string(1000, '9'), "--inclination", 0, "");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--inclination: expected a ratio such as 1/40 or a number in [0, 0.2), got '" +
                                         std::string(60, '9') + "\xE2\x80\xA6'");
  }
}
