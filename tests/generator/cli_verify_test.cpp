// SPDX-License-Identifier: Apache-2.0
// `ctab verify`: a fine tread table passes, a coarse flange table fails and names the point that reproduces its worst
// error, every class of cell gets points, the output is the same for a seed at any thread count, and bad arguments
// are clear errors. Each run's seed is printed to the test log.
#include <gtest/gtest.h>

#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "test_support.hpp"

namespace {

using ctab::test::CtabRun;
using ctab::test::run_ctab;

// A single-wheel table over [start, stop] mm in `step_mm` steps at the given vertical loads (TOML list text).
std::string make_table(const std::string& name, double start_mm, double stop_mm, double step_mm,
                       const std::string& loads) {
  const std::string config =
      ctab::test::write_temp(name + ".toml", "[solver]\nmode = \"wheel\"\n[axes]\nlateral_displacement_m = { start = " +
                                                 std::to_string(start_mm * 1e-3) +
                                                 ", stop = " + std::to_string(stop_mm * 1e-3) +
                                                 ", step = " + std::to_string(step_mm * 1e-3) +
                                                 " }\nvertical_load_N = " + loads + "\n");
  const std::string table = ::testing::TempDir() + name + ".h5";
  const CtabRun run = run_ctab({"generate", config, "-o", table, "--quiet", "--threads", "2"});
  EXPECT_EQ(run.exit_code, 0) << run.output();
  return table;
}

CtabRun verify(const std::string& table, int seed, std::vector<std::string> extra = {}) {
  std::cout << "ctab verify " << table << " --seed " << seed << '\n';
  std::vector<std::string> args{"verify", table, "--seed", std::to_string(seed)};
  args.insert(args.end(), extra.begin(), extra.end());
  return run_ctab(args);
}

}  // namespace

TEST(CliVerify, FineTreadTablePassesForSeveralSeeds) {
  const std::string table = make_table("verify_fine", 1.0, 2.5, 0.025, "78.5e3");
  for (const int seed : {1, 2, 3}) {
    const CtabRun run = verify(table, seed, {"--samples", "24", "--json"});
    ASSERT_EQ(run.exit_code, 0) << "seed " << seed << ": " << run.output();
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_TRUE(json["pass"].get<bool>());
    EXPECT_EQ(json["samples"], 24);
    EXPECT_EQ(json["seed"], seed);
    EXPECT_EQ(json["tolerance"]["force"], 0.005);  // the defaults of a table that states none
    EXPECT_EQ(json["tolerance"]["contact_point"], 1e-5);
  }
}

TEST(CliVerify, CoarseFlangeTableFailsAndNamesTheWorstPoint) {
  const std::string table = make_table("verify_coarse", 2.0, 9.0, 1.0, "[70e3, 85e3]");
  std::string first_json;
  for (const int seed : {7, 8}) {
    const CtabRun run = verify(table, seed, {"--samples", "30", "--json"});
    ASSERT_EQ(run.exit_code, 4) << "seed " << seed << ": " << run.output();
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_FALSE(json["pass"].get<bool>());
    EXPECT_GT(json["exceeding"].get<int>(), 0);
    const auto& worst = json["worst"];
    std::cout << "seed " << seed << " worst: " << worst.dump() << '\n';
    EXPECT_TRUE(worst.contains("dy_m") && worst.contains("vertical_load_N") && worst.contains("point"));
    // every class that has cells gets points, the load axis included
    for (const auto& c : json["classes"]) {
      if (c["cells"].get<int>() > 0) {
        EXPECT_GT(c["points"].get<int>(), 0) << c.dump();
      }
      if (c["class"] == "load" || c["class"] == "jump" || c["class"] == "tread") {
        EXPECT_GT(c["cells"].get<int>(), 0) << c.dump();
      }
    }
    if (seed == 7) first_json = run.out;
  }
  // the text output names the seed and point of the worst error
  const CtabRun text = verify(table, 7, {"--samples", "30"});
  EXPECT_EQ(text.exit_code, 4);
  EXPECT_NE(text.out.find("worst against its tolerance"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("(seed 7, point"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("FAIL"), std::string::npos) << text.out;
  // the same seed draws the same points and gives the same figures at any thread count
  const CtabRun one_thread = verify(table, 7, {"--samples", "30", "--json", "--threads", "1"});
  EXPECT_EQ(one_thread.out, first_json);
}

TEST(CliVerify, BadArgumentsAreClearErrors) {
  struct Case {
    std::vector<std::string> args;
    std::string expected;
  };
  const std::string missing = ::testing::TempDir() + "verify_no_such_table.h5";
  const std::string not_a_table = ctab::test::write_temp("verify_not_a_table.h5", "plain text\n");
  for (const Case& c : std::vector<Case>{{{"verify"}, "file is required"},
                                         {{"verify", missing, "--samples", "0"}, "--samples"},
                                         {{"verify", missing, "--seed", "x"}, "--seed"},
                                         {{"verify", missing}, missing},
                                         {{"verify", not_a_table}, not_a_table}}) {
    const CtabRun run = run_ctab(c.args);
    EXPECT_EQ(run.exit_code, 2) << run.output();
    EXPECT_NE(run.output().find(c.expected), std::string::npos) << run.output();
  }
}
