// SPDX-License-Identifier: Apache-2.0
// `ctab solve --config FILE --dy D [--load V]` reproduces a table entry: same set-up, roll, load kind and statuses
// as the generator (compared with gen::generate_table in process).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "ctab/sweep/table_generator.hpp"

namespace {

double total_force(const ctab::tables::Table& t, std::size_t i_dy, std::size_t i_second, std::size_t wheel) {
  double sum = 0.0;
  for (std::size_t slot = 0; slot < t.n_slots; ++slot) {
    const std::size_t k = t.patch_index(i_dy, i_second, wheel, slot);
    if (t.patch.present[k]) sum += t.patch.normal_force_N[k];
  }
  return sum;
}

}  // namespace

TEST(CliSolveConfig, ReproducesTableEntries) {
  const std::string text = "[axes]\nlateral_displacement_m = { start = -8e-3, stop = 8e-3, step = 4e-3 }\n"
                           "vertical_load_N = [60e3, 90e3]\n";
  const std::string path = ctab::test::write_temp("solve_config.toml", text);
  const ctab::gen::TableConfig config = ctab::gen::read_table_config(path);
  const ctab::tables::Table table = ctab::gen::generate_table(config, ctab::gen::GeneratorInfo{});
  for (const std::size_t i_dy : {std::size_t{0}, std::size_t{2}, std::size_t{4}}) {
    std::ostringstream dy;
    dy.precision(17);
    dy << table.lateral_displacement_m[i_dy];
    const ctab::test::CtabRun run =
        ctab::test::run_ctab({"solve", "--config", path, "--dy", dy.str(), "--load", "90e3", "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.output();
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["mode"], "wheelset");
    EXPECT_EQ(json["load_kind"], "vertical_load_N");
    EXPECT_EQ(json["config_source"], path);
    EXPECT_EQ(json["roll_rad"].get<double>(), table.roll_rad[i_dy * 2 + 1]) << "dy " << dy.str();
    // The right wheel is solved exactly as in the table; the table's left wheel is the mirrored right wheel at -dy,
    // equal to the direct solve up to the roll iteration's tolerance.
    EXPECT_EQ(json["right"]["normal_load_N"].get<double>(), total_force(table, i_dy, 1, 0)) << "dy " << dy.str();
    EXPECT_NEAR(json["left"]["normal_load_N"].get<double>(), total_force(table, i_dy, 1, 1), 1.0) << "dy " << dy.str();
    for (std::size_t wheel = 0; wheel < 2; ++wheel)
      EXPECT_EQ(table.status[table.wheel_index(i_dy, 1, wheel)], ctab::tables::CaseStatus::Converged)
          << "converged in the table";
  }
  // A config with a load axis needs --load; a single-value config does not.
  const ctab::test::CtabRun missing = ctab::test::run_ctab({"solve", "--config", path, "--dy", "0"});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("--load: " + path + " has a vertical_load_N axis of 2 values: give --load VALUE"),
            std::string::npos)
      << missing.err;
  const ctab::test::CtabRun excluded =
      ctab::test::run_ctab({"solve", "--config", path, "--dy", "0", "--mode", "wheel"});
  EXPECT_EQ(excluded.exit_code, 2);
  EXPECT_NE(excluded.err.find("--config excludes --mode"), std::string::npos) << excluded.err;
}

TEST(CliSolveConfig, ConfigErrorsNameTheFileAndKey) {
  const std::string path =
      ctab::test::write_temp("solve_bad_profile.toml",
                             "[profiles]\nwheel = \"/no/such/wheel.prw\"\n"
                             "[axes]\nlateral_displacement_m = { start = 0, stop = 1e-3, step = 1e-3 }\n"
                             "vertical_load_N = 78.5e3\n");
  const ctab::test::CtabRun run = ctab::test::run_ctab({"solve", "--config", path, "--dy", "0"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(path + ":2: 'profiles.wheel': "), std::string::npos) << run.err;
  const std::string wide = ctab::test::write_temp("solve_wide_strips.toml",
                                                  "[solver]\nstrip_width_m = 0.5\n[axes]\n"
                                                  "lateral_displacement_m = { start = 0, stop = 1e-3, step = 1e-3 }\n"
                                                  "vertical_load_N = 78.5e3\n");
  const ctab::test::CtabRun strips = ctab::test::run_ctab({"solve", "--config", wide, "--dy", "0"});
  EXPECT_EQ(strips.exit_code, 2);
  EXPECT_NE(strips.err.find(wide + ":2: 'solver.strip_width_m': expected a strip width in [1e-05, 0.005] m"),
            std::string::npos)
      << strips.err;
}

// `generate` runs the same set-up as `solve --config`: it refuses the same strip widths, naming the key.
TEST(CliSolveConfig, GenerateRefusesTheStripWidthsSolveRefuses) {
  const std::string wide = ctab::test::write_temp("generate_wide_strips.toml",
                                                  "[solver]\nstrip_width_m = 5e-6\n[axes]\n"
                                                  "lateral_displacement_m = { start = 0, stop = 1e-3, step = 1e-3 }\n");
  const std::string out = ctab::test::write_temp("generate_wide_strips.h5", "");
  std::remove(out.c_str());
  const ctab::test::CtabRun run = ctab::test::run_ctab({"generate", wide, "-o", out, "--quiet"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(wide + ":2: 'solver.strip_width_m': expected a strip width in [1e-05, 0.005] m"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(std::ifstream(out).good()) << "no table written";
}

// The set-up errors of a case given by options name the option, not the config key.
TEST(CliSolveConfig, OptionErrorsNameTheOption) {
  for (const char* option : {"--wheel", "--rail"}) {
    const ctab::test::CtabRun run =
        ctab::test::run_ctab({"solve", "--dy", "0", "--vertical-load", "78.5e3", option, "/no/such/profile.txt"});
    EXPECT_EQ(run.exit_code, 2) << option;
    EXPECT_NE(run.err.find(std::string(option) + ": /no/such/profile.txt"), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find("profiles."), std::string::npos) << run.err;
  }
}

// --side solves one wheel with the sweep's per-case solver: the same numbers as that wheel of a two-wheel solve
// (and of gen::solve_table_case with a wheel selection), and the other wheel is absent.
TEST(CliSolveConfig, OneSideEqualsThatSideOfBothSides) {
  const std::vector<std::string> base = {"solve", "--dy", "4.5e-3", "--vertical-load", "78.5e3", "--json"};
  const auto both = nlohmann::json::parse(ctab::test::run_ctab(base).out);
  ctab::gen::TableConfig config = ctab::gen::parse_table_config(ctab::gen::kDefaultTableConfig, "default");
  const ctab::gen::SweepSetup setup = ctab::gen::make_sweep_setup(config);
  for (const std::size_t wheel : {std::size_t{0}, std::size_t{1}}) {
    const char* name = wheel == 0 ? "right" : "left";
    std::vector<std::string> args = base;
    args.insert(args.end(), {"--side", name});
    const ctab::test::CtabRun run = ctab::test::run_ctab(args);
    ASSERT_EQ(run.exit_code, 0) << run.output();
    const auto one = nlohmann::json::parse(run.out);
    EXPECT_FALSE(one.contains(wheel == 0 ? "left" : "right")) << name;
    EXPECT_EQ(one[name]["normal_load_N"].get<double>(), both[name]["normal_load_N"].get<double>()) << name;
    EXPECT_EQ(one[name]["approach_m"].get<double>(), both[name]["approach_m"].get<double>()) << name;
    EXPECT_EQ(one[name]["dy_m"].get<double>(), 4.5e-3) << "track frame, not the mirrored side frame";
    ctab::gen::WheelSelection selection{};
    selection[wheel] = true;
    const ctab::gen::CaseSolution solution = ctab::gen::solve_table_case(setup, 4.5e-3, 78.5e3, selection);
    EXPECT_FALSE(solution.solved[1 - wheel]);
    EXPECT_EQ(solution.wheels[1 - wheel].contact.patches.size(), 0u);
    EXPECT_EQ(solution.rolling_radius_difference_m, 0.0) << "needs both wheels";
    EXPECT_EQ(solution.wheels[wheel].contact.normal_force_N, one[name]["normal_load_N"].get<double>()) << name;
  }
}
