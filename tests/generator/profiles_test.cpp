// Profiles: the built-in S1002 and 60E1 against the Manchester point files, the readers, and malformed files.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "ctab/profiles/builtin_profiles.hpp"
#include "ctab/contact/error.hpp"
#include "ctab/io/profile_io.hpp"
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
  for (int i = 0; i < 12; ++i) text += std::to_string(step_sign * (-20.0 + 4.0 * i)) + " " + std::to_string(0.01 * (i - 6) * (i - 6)) + "\n";
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
  EXPECT_NEAR(table.at(-0.055).z, 28e-3, 1e-9);  // flange tip F = 28 mm at S = -55 mm
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
