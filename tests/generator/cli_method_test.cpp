// SPDX-License-Identifier: Apache-2.0
// `--method hertz|kp|analyn|mim1d|bem2d` end to end: `ctab solve --gap`, the table config key solver.method (into the
// table's `method` attribute), and `ctab solve --config` with it.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "cli_run.hpp"
#include "ctab/core/error.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "test_support.hpp"

namespace {

const std::string kSphere = ctab::test::source_path("examples/gaps/hertz_sphere_r40.csv");
const char* const kMethods[] = {"hertz", "kp", "analyn", "mim1d", "bem2d"};

std::string small_config(const std::string& method) {
  return "[solver]\nmode = \"wheel\"\nmethod = \"" + method +
         "\"\n[axes]\nlateral_displacement_m = { start = -2e-3, stop = 2e-3, step = 2e-3 }\nvertical_load_N = 78.5e3\n";
}

// `ctab solve` of the right wheel on the flange flank (dy 7.5 mm, built-in S1002 on UIC60 1:40, single wheel,
// 78.5 kN vertical load) with `extra` options: the right wheel's JSON.
nlohmann::json solve_flank(const std::vector<std::string>& extra) {
  std::vector<std::string> arguments = {"solve", "--mode", "wheel",           "--side", "right",
                                        "--dy",  "7.5e-3", "--vertical-load", "78.5e3", "--json"};
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  const ctab::test::CtabRun run = ctab::test::run_ctab(arguments);
  EXPECT_EQ(run.exit_code, 0) << run.output();
  return nlohmann::json::parse(run.out)["right"];
}

}  // namespace

TEST(CliMethod, SolveGapWithEveryRung) {
  for (const char* method : kMethods) {
    const ctab::test::CtabRun run =
        ctab::test::run_ctab({"solve", "--gap", kSphere, "--load", "963e3", "--method", method, "--json"});
    ASSERT_EQ(run.exit_code, 0) << method << ": " << run.output();
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["method"], method);
    EXPECT_EQ(json["status"], "converged") << method;
    EXPECT_NEAR(json["normal_load_N"].get<double>(), 963e3, 1e-3) << method;
    // Hertz area 125.6 mm^2; KP is +6.6 % on a circle by construction (method_ladder_test); bem2d counts whole
    // 0.2 mm elements, +0.84 % (CONTACT's own figure on that mesh, bem2d_reference_test).
    const std::string name = method;
    const double expected_area_m2 = name == "kp" ? 133.9e-6 : name == "bem2d" ? 126.65e-6 : 125.6e-6;
    EXPECT_NEAR(json["patches"][0]["area_m2"].get<double>(), expected_area_m2, 0.4e-6) << method;
  }
}

TEST(CliMethod, UnknownMethodIsAnInputError) {
  const ctab::test::CtabRun run = ctab::test::run_ctab({"solve", "--gap", kSphere, "--load", "1e3", "--method", "bem"});
  EXPECT_EQ(run.exit_code, 2) << run.output();
  EXPECT_NE(run.err.find("--method"), std::string::npos) << run.err;
  const std::string path = ctab::test::write_temp("bad_method.toml", small_config("stripes"));
  try {
    (void)ctab::gen::read_table_config(path);
    ADD_FAILURE() << "no error for method = \"stripes\"";
  } catch (const ctab::gen::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("expected one of hertz, kp, analyn, mim1d, bem2d, auto, got \"stripes\""),
              std::string::npos)
        << e.what();
    EXPECT_EQ(e.line(), 3u);
  }
}

// A rung's own reason for a failed case reaches the user: bem2d with an element size whose grid would exceed its
// limit says so (before: only "invalid-input", and the wheel-rail message named the rung "ANALYN").
TEST(CliMethod, FailedCaseSaysWhy) {
  const ctab::test::CtabRun run =
      ctab::test::run_ctab({"solve", "--dy", "2e-3", "--normal-load", "78.5e3", "--side", "right", "--method", "bem2d",
                            "--strip-width", "1e-5", "--json"});
  EXPECT_EQ(run.exit_code, 4) << run.output();
  EXPECT_NE(run.err.find("invalid-input; bem2d: grid of"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("(max 1024 per side): element size too small"), std::string::npos) << run.err;
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_EQ(json["right"]["status"], "invalid-input");
  EXPECT_NE(json["right"]["detail"].get<std::string>().find("element size too small"), std::string::npos);
}

// A table with each of the new rungs: the attribute names the method, every case is solved, and
// `ctab solve --config` reproduces an entry with the same method.
TEST(CliMethod, TableConfigMethodReachesTheTableAndSolveConfig) {
  for (const char* method : {"kp", "analyn"}) {
    const std::string path = ctab::test::write_temp(std::string("method_") + method + ".toml", small_config(method));
    const ctab::gen::TableConfig config = ctab::gen::read_table_config(path);
    const ctab::tables::Table table = ctab::gen::generate_table(config, ctab::gen::GeneratorInfo{});
    EXPECT_EQ(table.text_attributes.at("method"), method);
    double right_force_at_0 = 0.0;
    for (std::size_t i = 0; i < table.lateral_displacement_m.size(); ++i) {
      const std::size_t k = table.wheel_index(i, 0, 0);
      EXPECT_EQ(table.status[k], ctab::tables::CaseStatus::Converged) << method << " dy #" << i;
      if (i == 1)
        for (std::size_t slot = 0; slot < table.n_slots; ++slot) {
          const std::size_t p = table.patch_index(i, 0, 0, slot);
          if (table.patch.present[p]) right_force_at_0 += table.patch.normal_force_N[p];
        }
    }
    const ctab::test::CtabRun run = ctab::test::run_ctab({"solve", "--config", path, "--dy", "0", "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.output();
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["method"], method);
    EXPECT_GT(right_force_at_0, 70e3) << method;
  }
}

// `--reference-point` and `[solver] reference_point` (issue 8): on the flange flank (dy 7.5 mm, built-in S1002 on
// UIC60 1:40, single wheel) the deepest rigid point sits where the rail slope is -70 deg; CONTACT's rule puts the
// contact plane at the centre of the interpenetration region, which moves the rail point by about 0.07 mm. Both
// balance the vertical load; the config key reaches `ctab solve --config`; a bad name is an input error (exit 2).
TEST(CliMethod, ReferencePointMovesTheFlankContactPlane) {
  const auto deepest = solve_flank({}), centre = solve_flank({"--reference-point", "interpenetration-centre"});
  ASSERT_EQ(deepest["patches"].size(), 1u);
  ASSERT_EQ(centre["patches"].size(), 1u);
  for (const auto* wheel : {&deepest, &centre}) {
    EXPECT_EQ((*wheel)["status"], "converged");
    EXPECT_NEAR((*wheel)["vertical_load_N"].get<double>(), 78.5e3, 1.0);
  }
  const double rail_shift_m =
      centre["patches"][0]["y_rail_m"].get<double>() - deepest["patches"][0]["y_rail_m"].get<double>();
  EXPECT_GT(std::abs(rail_shift_m), 0.03e-3) << "the centre rule must move the contact plane on the flank";
  EXPECT_LT(std::abs(rail_shift_m), 0.5e-3);

  const std::string path =
      ctab::test::write_temp("reference_point.toml",
                             "[solver]\nmode = \"wheel\"\nreference_point = \"interpenetration-centre\"\n"
                             "[axes]\nlateral_displacement_m = { start = 7.5e-3, stop = 7.5e-3, step = 1e-3 }\n"
                             "vertical_load_N = 78.5e3\n");
  const ctab::test::CtabRun from_config =
      ctab::test::run_ctab({"solve", "--config", path, "--dy", "7.5e-3", "--side", "right", "--json"});
  ASSERT_EQ(from_config.exit_code, 0) << from_config.output();
  EXPECT_DOUBLE_EQ(nlohmann::json::parse(from_config.out)["right"]["patches"][0]["y_rail_m"].get<double>(),
                   centre["patches"][0]["y_rail_m"].get<double>());

  const ctab::test::CtabRun bad = ctab::test::run_ctab(
      {"solve", "--mode", "wheel", "--dy", "0", "--vertical-load", "78.5e3", "--reference-point", "middle"});
  EXPECT_EQ(bad.exit_code, 2) << bad.output();
  EXPECT_NE(bad.err.find("--reference-point"), std::string::npos) << bad.err;
  const std::string bad_path =
      ctab::test::write_temp("bad_reference_point.toml",
                             "[solver]\nreference_point = \"middle\"\n" +
                                 std::string("[axes]\nlateral_displacement_m = { start = 0, stop = "
                                             "1e-3, step = 1e-3 }\nvertical_load_N = 78.5e3\n"));
  try {
    (void)ctab::gen::read_table_config(bad_path);
    ADD_FAILURE() << "no error for reference_point = \"middle\"";
  } catch (const ctab::gen::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("expected \"deepest\" or \"interpenetration-centre\", got \"middle\""),
              std::string::npos)
        << e.what();
    EXPECT_EQ(e.line(), 2u);
  }
}

// `--reference-angle` and `[solver] reference_angle`: at the flank (dy 7.5 mm, as above) the deepest point's plane
// inclined at CONTACT's reference angle keeps the deepest rail point and takes the centre rule's angle (within
// 0.02 deg; the tangent there is 0.6 deg steeper); the config key reaches `ctab solve --config` and the table's
// provenance; tangent with CONTACT's reference point, or a bad name, is an input error (exit 2) naming the line.
TEST(CliMethod, ReferenceAngleInclinesTheDeepestPointsPlane) {
  const auto solve = [](const std::vector<std::string>& extra) { return solve_flank(extra)["patches"][0]; };
  const auto tangent = solve({"--reference-angle", "tangent"}),
             centre = solve({"--reference-point", "interpenetration-centre"});
  const auto mean = solve({"--reference-angle", "interpenetration-mean"});
  EXPECT_EQ(solve({}), mean);  // the default
  constexpr double kDeg = 3.14159265358979323846 / 180.0;
  EXPECT_EQ(mean["y_rail_m"].get<double>(), tangent["y_rail_m"].get<double>());
  EXPECT_NEAR(mean["plane_angle_rad"].get<double>(), centre["plane_angle_rad"].get<double>(), 0.02 * kDeg);
  EXPECT_GT(std::abs(mean["plane_angle_rad"].get<double>() - tangent["plane_angle_rad"].get<double>()), 0.3 * kDeg);
  EXPECT_EQ(solve({"--reference-point", "interpenetration-centre", "--reference-angle", "interpenetration-mean"}),
            centre);

  const std::string axes = "[axes]\nlateral_displacement_m = { start = 7.5e-3, stop = 7.5e-3, step = 1e-3 }\n"
                           "vertical_load_N = 78.5e3\n";
  const std::string path =
      ctab::test::write_temp("reference_angle.toml",
                             "[solver]\nmode = \"wheel\"\nreference_angle = \"interpenetration-mean\"\n" + axes);
  const ctab::test::CtabRun from_config =
      ctab::test::run_ctab({"solve", "--config", path, "--dy", "7.5e-3", "--side", "right", "--json"});
  ASSERT_EQ(from_config.exit_code, 0) << from_config.output();
  EXPECT_EQ(nlohmann::json::parse(from_config.out)["right"]["patches"][0], mean);
  const ctab::gen::TableConfig config = ctab::gen::read_table_config(path);
  const ctab::tables::Table table = ctab::gen::generate_table(config, ctab::gen::GeneratorInfo{});
  EXPECT_EQ(table.text_attributes.at("reference_point"), "deepest");
  EXPECT_EQ(table.text_attributes.at("reference_angle"), "interpenetration-mean");
  const ctab::tables::Table centre_table =
      ctab::gen::generate_table(ctab::gen::parse_table_config("[solver]\nmode = \"wheel\"\nreference_point = "
                                                              "\"interpenetration-centre\"\n" +
                                                                  axes,
                                                              "centre.toml"),
                                ctab::gen::GeneratorInfo{});
  EXPECT_EQ(centre_table.text_attributes.at("reference_point"), "interpenetration-centre");
  EXPECT_EQ(centre_table.text_attributes.at("reference_angle"), "interpenetration-mean");

  // CONTACT's point with the tangent is refused in either order of the two options.
  for (const bool point_first : {true, false}) {
    std::vector<std::string> args{"solve", "--mode", "wheel", "--dy", "0", "--vertical-load", "78.5e3"};
    const std::vector<std::string> point{"--reference-point", "interpenetration-centre"},
        angle{"--reference-angle", "tangent"};
    for (const auto* option : point_first ? std::vector{&point, &angle} : std::vector{&angle, &point})
      args.insert(args.end(), option->begin(), option->end());
    const ctab::test::CtabRun conflict = ctab::test::run_ctab(args);
    EXPECT_EQ(conflict.exit_code, 2) << conflict.output();
    EXPECT_NE(conflict.err.find("--reference-angle"), std::string::npos) << conflict.err;
  }
  for (const auto& [text, expected] :
       {std::pair<std::string, std::string>{"reference_point = \"interpenetration-centre\"\nreference_angle = "
                                            "\"tangent\"\n",
                                            "\"tangent\" needs reference_point = \"deepest\""},
        std::pair<std::string, std::string>{"reference_angle = \"steep\"\n",
                                            "expected \"tangent\" or \"interpenetration-mean\", got \"steep\""}}) {
    const std::string bad_path = ctab::test::write_temp("bad_reference_angle.toml", "[solver]\n" + text + axes);
    try {
      (void)ctab::gen::read_table_config(bad_path);
      ADD_FAILURE() << "no error for " << text;
    } catch (const ctab::gen::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
      EXPECT_EQ(e.line(), text.find("reference_angle") == 0 ? 2u : 3u) << text;
    }
  }
}
