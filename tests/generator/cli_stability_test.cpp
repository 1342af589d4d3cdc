// SPDX-License-Identifier: Apache-2.0
// `ctab bench stability` (issue 10, "Stability where methods fail"): the CSV of one quick scene (columns, every
// rung, finite results, exit 0) and an unknown --scene refused with exit 2 naming it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "ctab/validation/reference_csv.hpp"
#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kColumns = {"scene",
                                           "case",
                                           "method",
                                           "strip_width_m",
                                           "status",
                                           "finite",
                                           "area_error_rel",
                                           "max_pressure_error_rel",
                                           "force_error_rel",
                                           "error_rel",
                                           "reference",
                                           "reference_status",
                                           "reference_area_m2",
                                           "resolved_strips",
                                           "iterations",
                                           "time_s",
                                           "claimed",
                                           "error_bound_rel"};

}  // namespace

TEST(StabilityBench, QuickSceneWritesTheCsv) {
  const fs::path dir = fs::path(::testing::TempDir()) / ("ctab_stability_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const ctab::test::CtabRun run = ctab::test::run_ctab(
      std::vector<std::string>{"bench", "stability", "--quick", "--scene", "barely_touching", "--out", dir.string()});
  ASSERT_EQ(run.exit_code, 0) << run.output();
  EXPECT_NE(run.out.find("wrote"), std::string::npos) << run.output();
  const ctab::gen::CsvTable table = ctab::gen::read_csv((dir / "stability.csv").string());
  EXPECT_EQ(table.header, kColumns);
  ASSERT_EQ(table.rows.size(), 10u);  // two cases x five rungs
  std::set<std::string> methods;
  for (const auto& row : table.rows) {
    methods.insert(row.at(table.column("method")));
    EXPECT_EQ(row.at(table.column("finite")), "1");
    EXPECT_EQ(row.at(table.column("scene")), "barely_touching");
  }
  EXPECT_EQ(methods, (std::set<std::string>{"hertz", "kp", "analyn", "mim1d", "bem2d"}));
  fs::remove_all(dir);
}

TEST(StabilityBench, UnknownSceneIsAUsageError) {
  const ctab::test::CtabRun run = ctab::test::run_ctab(
      std::vector<std::string>{"bench", "stability", "--scene", "no_such_scene", "--out", ::testing::TempDir()});
  EXPECT_EQ(run.exit_code, 2) << run.output();
  EXPECT_NE(run.err.find("no_such_scene"), std::string::npos) << run.output();
}
