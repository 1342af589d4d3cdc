// The ctab executable end to end: JSON output, and a one-line error with a non-zero exit code for bad input.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <fstream>
#include <string>
#include <sys/wait.h>

#include "test_support.hpp"

namespace {

struct CtabRun {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

CtabRun run_ctab(const std::string& arguments) {
  const std::string command = std::string(CTAB_EXECUTABLE) + " " + arguments + " 2>&1";
  CtabRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe)) run.output += buffer.data();
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

const std::string kSphere = ctab::test::source_path("examples/gaps/hertz_sphere_r40.csv");

}  // namespace

TEST(Cli, HelpListsSubcommands) {
  const CtabRun run = run_ctab("--help");
  EXPECT_EQ(run.exit_code, 0);
  for (const char* name : {"solve", "paper-cases", "bench"}) EXPECT_NE(run.output.find(name), std::string::npos) << name;
}

TEST(Cli, SolveJson) {
  const CtabRun run = run_ctab("solve --gap " + kSphere + " --load 963e3 --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto json = nlohmann::json::parse(run.output);
  EXPECT_EQ(json["status"], "converged");
  EXPECT_EQ(json["method"], "mim1d");
  EXPECT_NEAR(json["normal_load_N"].get<double>(), 963e3, 1.0);
  EXPECT_NEAR(json["approach_m"].get<double>(), 0.999487e-3, 0.001e-3);
  for (const char* key : {"iterations", "solve_time_s", "patches"}) EXPECT_TRUE(json.contains(key)) << key;
  const auto& patch = json["patches"][0];
  EXPECT_NEAR(patch["area_m2"].get<double>(), 125.6e-6, 0.4e-6);
  for (const char* key : {"normal_force_N", "max_pressure_Pa", "strips"}) EXPECT_TRUE(patch.contains(key)) << key;
  const auto& strip = patch["strips"][0];
  for (const char* key : {"y_m", "half_length_m", "p0_Pa"}) EXPECT_TRUE(strip.contains(key)) << key;
}

TEST(Cli, HertzMethod) {
  const CtabRun run = run_ctab("solve --gap " + kSphere + " --approach 1e-3 --method hertz --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NEAR(nlohmann::json::parse(run.output)["normal_load_N"].get<double>(), 963.74e3, 0.01e3);
}

TEST(Cli, GenerateAndInspect) {
  const std::string config = write_temp("small.toml", "[solver]\nmode = \"wheel\"\n[axes]\n"
                                        "lateral_displacement_m = { start = -2e-3, stop = 2e-3, step = 1e-3 }\n");
  const std::string table = ::testing::TempDir() + "small.h5";
  const CtabRun generated = run_ctab("generate " + config + " -o " + table + " --threads 2");
  ASSERT_EQ(generated.exit_code, 0) << generated.output;
  EXPECT_NE(generated.output.find("5 lateral shifts x 1 vertical_load_N x 2 wheels"), std::string::npos) << generated.output;
  const CtabRun inspected = run_ctab("inspect " + table);
  ASSERT_EQ(inspected.exit_code, 0) << inspected.output;
  for (const char* text : {"schema version 2 (valid)", "git_commit", "wheel_profile_sha256", "lateral_displacement_m 5 values",
                           "status counts (case x wheel): converged 10", "mode                   wheel"})
    EXPECT_NE(inspected.output.find(text), std::string::npos) << text << "\n" << inspected.output;
  // Bad inputs: clear one-line errors, non-zero exit, and the old table stays.
  const CtabRun bad_config = run_ctab("generate " + write_temp("bad.toml", "[axes]\nlateral_displacement_m = 3\n") + " -o " + table);
  EXPECT_NE(bad_config.exit_code, 0);
  EXPECT_NE(bad_config.output.find("bad.toml:2: 'axes.lateral_displacement_m': expected {start, stop, step}"), std::string::npos)
      << bad_config.output;
  EXPECT_EQ(run_ctab("inspect " + table).exit_code, 0);
  const CtabRun not_a_table = run_ctab("inspect " + config);
  EXPECT_EQ(not_a_table.exit_code, 2);
  EXPECT_NE(not_a_table.output.find("not an HDF5 contact table"), std::string::npos) << not_a_table.output;
  EXPECT_NE(run_ctab("inspect /nonexistent.h5").output.find("/nonexistent.h5: cannot open table file"), std::string::npos);
}

TEST(Cli, BadInputGivesOneLineErrorAndNonZeroExit) {
  struct Case {
    std::string arguments, expected;
  };
  const std::string bad_number = write_temp("bad_number.csv", "y_m,h_m,A_per_m,B_per_m\n0,0,1,1\n1e-3,x,1,1\n2e-3,0,1,1\n");
  const std::string empty = write_temp("empty.csv", "");
  const std::string decreasing = write_temp("decreasing.csv", "y_m,h_m,A_per_m,B_per_m\n0,0,1,1\n-1e-3,0,1,1\n2e-3,0,1,1\n");
  const Case cases[] = {
      {"solve --gap /nonexistent.csv --load 1", "/nonexistent.csv: cannot open gap file"},
      {"solve --gap " + bad_number + " --load 1", "bad_number.csv:3: field 'h_m': expected a number, got 'x'"},
      {"solve --gap " + empty + " --load 1", "empty gap file"},
      {"solve --gap " + decreasing + " --load 1", "decreasing.csv:3: field 'y_m': strips must be strictly increasing"},
      {"solve --gap " + kSphere + " --load 1 --E -5", "--E: expected a positive Young's modulus in Pa"},
      {"solve --gap " + kSphere + " --load 1 --nu 0.7", "--nu: expected a Poisson's ratio in (-1, 0.5)"},
      {"solve --gap " + kSphere + " --load nan", "--load: expected a finite, non-negative force in N"},
      {"solve --gap " + kSphere + " --load 1 --strip-width 0", "--strip-width: expected a positive width in metres"},
      {"solve --gap " + kSphere, "give exactly one of --approach METRES or --load NEWTONS"},
      {"solve --gap " + kSphere + " --load 1 --approach 1e-3", "give exactly one of --approach METRES or --load NEWTONS"},
      {"solve --gap " + kSphere + " --load 1 --method magic", "magic"},
  };
  for (const Case& c : cases) {
    const CtabRun run = run_ctab(c.arguments);
    EXPECT_NE(run.exit_code, 0) << c.arguments;
    EXPECT_NE(run.output.find(c.expected), std::string::npos) << c.arguments << "\n" << run.output;
  }
}
