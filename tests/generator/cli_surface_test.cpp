// SPDX-License-Identifier: Apache-2.0
// `--surface planar|conformal` and `[solver] surface` (issue 8) end to end: `ctab solve` on the flange root (built-in
// S1002 on 60E1 1:40, single wheel, dy 6.5 mm), where the strips' own normals turn the force; the JSON names the
// surface; the config key reaches `ctab solve --config` and the table's `surface` attribute; a bad name is an input
// error naming the option or key and line.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "ctab/core/error.hpp"
#include "ctab/sweep/table_config.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "test_support.hpp"

namespace {

nlohmann::json solve_root(const std::vector<std::string>& extra) {
  std::vector<std::string> arguments = {"solve", "--mode", "wheel",           "--side", "right",
                                        "--dy",  "6.5e-3", "--vertical-load", "78.5e3", "--json"};
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  const ctab::test::CtabRun run = ctab::test::run_ctab(arguments);
  EXPECT_EQ(run.exit_code, 0) << run.output();
  return nlohmann::json::parse(run.out);
}

std::string config_text(const std::string& surface) {
  return "[solver]\nmode = \"wheel\"\nsurface = \"" + surface +
         "\"\n[axes]\nlateral_displacement_m = { start = 6.5e-3, stop = 6.5e-3, step = 1e-3 }\n"
         "vertical_load_N = 78.5e3\n";
}

}  // namespace

TEST(CliSurface, ConformalTurnsTheFlangeRootForce) {
  // the conformal surface is the default
  const auto planar = solve_root({"--surface", "planar"}), conformal = solve_root({});
  EXPECT_EQ(planar["surface"], "planar");
  EXPECT_EQ(conformal["surface"], "conformal");
  const auto &p = planar["right"], &c = conformal["right"];
  ASSERT_EQ(c["status"], "converged");
  ASSERT_FALSE(c["patches"].empty());
  EXPECT_NEAR(c["vertical_load_N"].get<double>(), 78.5e3, 78.5e3 * 1e-9);
  const auto& patch = c["patches"][0];
  const double direction = std::atan2(-patch["force_lateral_N"].get<double>(), patch["force_vertical_N"].get<double>());
  EXPECT_NEAR(patch["contact_angle_rad"].get<double>(), direction, 1e-12);
  // The planar patch pushes along its plane; the conformal one along its strips' normals, not the same direction.
  const auto& planar_patch = p["patches"][0];
  const double planar_direction =
      std::atan2(-planar_patch["force_lateral_N"].get<double>(), planar_patch["force_vertical_N"].get<double>());
  EXPECT_NEAR(planar_direction, planar_patch["plane_angle_rad"].get<double>(), 1e-9);
  // contact_angle_rad is the force direction on both surfaces.
  EXPECT_NEAR(planar_patch["contact_angle_rad"].get<double>(), planar_direction, 1e-12);
  EXPECT_GT(std::abs(direction - planar_direction), 1e-3);
}

TEST(CliSurface, ConfigKeyReachesSolveAndTable) {
  const std::string path = ctab::test::write_temp("surface_conformal.toml", config_text("conformal"));
  const ctab::test::CtabRun from_config =
      ctab::test::run_ctab({"solve", "--config", path, "--dy", "6.5e-3", "--side", "right", "--json"});
  ASSERT_EQ(from_config.exit_code, 0) << from_config.output();
  const auto json = nlohmann::json::parse(from_config.out);
  EXPECT_EQ(json["surface"], "conformal");
  const auto direct = solve_root({"--surface", "conformal"});
  EXPECT_DOUBLE_EQ(json["right"]["patches"][0]["force_lateral_N"].get<double>(),
                   direct["right"]["patches"][0]["force_lateral_N"].get<double>());

  const ctab::gen::TableConfig config = ctab::gen::read_table_config(path);
  EXPECT_EQ(config.surface, ctab::gen::ContactSurface::Conformal);
  const ctab::tables::Table table = ctab::gen::generate_table(config, ctab::gen::GeneratorInfo{});
  EXPECT_EQ(table.text_attributes.at("surface"), "conformal");
  const ctab::gen::TableConfig planar = ctab::gen::parse_table_config(config_text("planar"), "planar.toml");
  EXPECT_EQ(planar.surface, ctab::gen::ContactSurface::Planar);
}

TEST(CliSurface, TextOutputNamesTheConformalSurface) {
  const ctab::test::CtabRun run = ctab::test::run_ctab(
      {"solve", "--mode", "wheel", "--dy", "0", "--vertical-load", "78.5e3", "--surface", "conformal"});
  ASSERT_EQ(run.exit_code, 0) << run.output();
  EXPECT_NE(run.out.find("mim1d (conformal surface)"), std::string::npos) << run.out;
}

TEST(CliSurface, BadNameIsAnInputError) {
  const ctab::test::CtabRun bad = ctab::test::run_ctab(
      {"solve", "--mode", "wheel", "--dy", "0", "--vertical-load", "78.5e3", "--surface", "round"});
  EXPECT_EQ(bad.exit_code, 2) << bad.output();
  EXPECT_NE(bad.err.find("--surface"), std::string::npos) << bad.err;
  try {
    (void)ctab::gen::parse_table_config(config_text("round"), "bad_surface.toml");
    ADD_FAILURE() << "no error for surface = \"round\"";
  } catch (const ctab::gen::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("expected \"planar\" or \"conformal\", got \"round\""), std::string::npos)
        << e.what();
    EXPECT_EQ(e.line(), 3u);
  }
}
