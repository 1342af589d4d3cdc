// SPDX-License-Identifier: Apache-2.0
// The ctab executable end to end: JSON output, and a one-line error with a non-zero exit code for bad input.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "cli_run.hpp"
#include "ctab/sweep/table_config.hpp"
#include "test_support.hpp"

namespace {

using ctab::test::CtabRun;
using ctab::test::write_temp;

// stdout and stderr together, as a user sees them.
struct Combined {
  int exit_code;
  std::string output;
};
Combined run_ctab(const std::string& arguments) {
  const CtabRun run = ctab::test::run_ctab(arguments);
  return {run.exit_code, run.output()};
}

const std::string kSphere = ctab::test::source_path("examples/gaps/hertz_sphere_r40.csv");

}  // namespace

TEST(Cli, HelpListsSubcommands) {
  const Combined run = run_ctab("--help");
  EXPECT_EQ(run.exit_code, 0);
  for (const char* name : {"solve", "paper-cases", "bench"})
    EXPECT_NE(run.output.find(name), std::string::npos) << name;
}

// main registers only the subcommand the command line names (by a table of names): each name must be its
// subcommand's, and the full help must list every one.
TEST(Cli, EverySubcommandByItsName) {
  const std::string help = run_ctab("--help").output;
  for (const char* name : {"generate", "inspect", "solve", "paper-cases", "geometry", "bench", "config", "export",
                           "query", "merge", "batch", "verify"}) {
    const Combined run = run_ctab(std::string(name) + " --help");
    EXPECT_EQ(run.exit_code, 0) << name << ": " << run.output;
    EXPECT_NE(run.output.find(std::string("ctab ") + name), std::string::npos) << name << ": " << run.output;
    EXPECT_NE(help.find(name), std::string::npos) << name;
  }
  const Combined misspelt = run_ctab("generat");  // not a command: the nearest one is named
  EXPECT_EQ(misspelt.exit_code, 2);
  EXPECT_NE(misspelt.output.find("did you mean 'generate'?"), std::string::npos) << misspelt.output;
}

TEST(Cli, SolveJson) {
  const Combined run = run_ctab("solve --gap " + kSphere + " --load 963e3 --json");
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
  const Combined run = run_ctab("solve --gap " + kSphere + " --approach 1e-3 --method hertz --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NEAR(nlohmann::json::parse(run.output)["normal_load_N"].get<double>(), 963.74e3, 0.01e3);
}

TEST(Cli, GenerateAndInspect) {
  const std::string config =
      write_temp("small.toml", "[solver]\nmode = \"wheel\"\n[axes]\n"
                               "lateral_displacement_m = { start = -2e-3, stop = 2e-3, step = 1e-3 }\n"
                               "vertical_load_N = 78.5e3\n");
  const std::string table = ::testing::TempDir() + "small.h5";
  const Combined generated = run_ctab("generate " + config + " -o " + table + " --threads 2");
  ASSERT_EQ(generated.exit_code, 0) << generated.output;
  EXPECT_NE(generated.output.find("5 lateral shifts x 1 vertical_load_N x 2 wheels"), std::string::npos)
      << generated.output;
  const Combined inspected = run_ctab("inspect " + table);
  ASSERT_EQ(inspected.exit_code, 0) << inspected.output;
  for (const char* text :
       {"schema version 2 (valid)", "git_commit", "wheel_profile_sha256", "lateral_displacement_m 5 values",
        "status counts (case x wheel): converged 10", "mode                   wheel"})
    EXPECT_NE(inspected.output.find(text), std::string::npos) << text << "\n" << inspected.output;
  // Bad inputs: clear one-line errors, non-zero exit, and the old table stays.
  const Combined bad_config =
      run_ctab("generate " + write_temp("bad.toml", "[axes]\nlateral_displacement_m = 3\n") + " -o " + table);
  EXPECT_EQ(bad_config.exit_code, 2);
  EXPECT_NE(bad_config.output.find("bad.toml:2: 'axes.lateral_displacement_m': expected {start, stop, step}"),
            std::string::npos)
      << bad_config.output;
  EXPECT_EQ(run_ctab("inspect " + table).exit_code, 0);
  const Combined not_a_table = run_ctab("inspect " + config);
  EXPECT_EQ(not_a_table.exit_code, 2);
  EXPECT_NE(not_a_table.output.find("not an HDF5 contact table"), std::string::npos) << not_a_table.output;
  EXPECT_NE(run_ctab("inspect /nonexistent.h5").output.find("/nonexistent.h5: cannot open table file"),
            std::string::npos);
}

TEST(Cli, BadInputGivesOneLineErrorAndNonZeroExit) {
  struct Case {
    std::string arguments, expected;
  };
  const std::string bad_number =
      write_temp("bad_number.csv", "y_m,h_m,A_per_m,B_per_m\n0,0,1,1\n1e-3,x,1,1\n2e-3,0,1,1\n");
  const std::string empty = write_temp("empty.csv", "");
  const std::string decreasing =
      write_temp("decreasing.csv", "y_m,h_m,A_per_m,B_per_m\n0,0,1,1\n-1e-3,0,1,1\n2e-3,0,1,1\n");
  const Case cases[] = {
      {"solve --gap /nonexistent.csv --load 1", "/nonexistent.csv: cannot open gap file"},
      {"solve --gap " + bad_number + " --load 1", "bad_number.csv:3: field 'h_m': expected a number, got 'x'"},
      {"solve --gap " + empty + " --load 1", "empty gap file"},
      {"solve --gap " + decreasing + " --load 1", "decreasing.csv:3: field 'y_m': strips must be strictly increasing"},
      {"solve --gap " + kSphere + " --load 1 --E -5", "--E: expected a Young's modulus in (1e6, 1e13] Pa, got -5"},
      {"solve --gap " + kSphere + " --load 1 --youngs-modulus -5",
       "--youngs-modulus: expected a Young's modulus in (1e6, 1e13] Pa"},
      {"solve --gap " + kSphere + " --load 1 --nu 0.7", "--nu: expected a Poisson's ratio in (-1, 0.5], got 0.7"},
      {"solve --gap " + kSphere + " --load 1 --poisson-ratio 0.7",
       "--poisson-ratio: expected a Poisson's ratio in (-1, 0.5]"},
      {"solve --gap " + kSphere + " --load nan", "--load: expected a load in (0, 1e8] N, got nan"},
      {"solve --gap " + kSphere + " --load 1 --strip-width 0",
       "--strip-width: expected a number in [1e-05, 0.005] m, got 0"},
      {"solve --gap " + kSphere, "give exactly one of --approach METRES or --load NEWTONS"},
      {"solve --gap " + kSphere + " --load 1 --approach 1e-3",
       "give exactly one of --approach METRES or --load NEWTONS"},
      {"solve --gap " + kSphere + " --load 1 --method magic", "magic"},
  };
  for (const Case& c : cases) {
    const Combined run = run_ctab(c.arguments);
    EXPECT_EQ(run.exit_code, 2) << c.arguments;
    EXPECT_NE(run.output.find(c.expected), std::string::npos) << c.arguments << "\n" << run.output;
  }
}

// ---- one option model: the same defaults (the embedded default config) everywhere, shown in --help ----

TEST(CliOptions, HelpShowsTheSharedDefaults) {
  for (const char* command : {"solve --help", "geometry --help"}) {
    const Combined run = run_ctab(command);
    ASSERT_EQ(run.exit_code, 0) << command;
    for (const char* text : {"--mode TEXT:{wheelset,wheel}=wheelset", "--wheel TEXT=S1002", "--rail TEXT=UIC60",
                             "--inclination TEXT=1/40", "=1.435", "=1.36", "=0.46"})
      EXPECT_NE(run.output.find(text), std::string::npos) << command << ": " << text << "\n" << run.output;
  }
  const Combined solve = run_ctab("solve --help");
  for (const char* text : {"--youngs-modulus", "--poisson-ratio", "--strip-width",
                           "--method TEXT:{hertz,kp,analyn,mim1d,bem2d,auto}=mim1d", "--tolerance"})
    EXPECT_NE(solve.output.find(text), std::string::npos) << text;
  EXPECT_EQ(solve.output.find("--E "), std::string::npos) << "the alias --E is hidden";
  EXPECT_EQ(solve.output.find("--nu "), std::string::npos) << "the alias --nu is hidden";
}

TEST(CliOptions, SolveDefaultsToWheelsetModeWithBothWheels) {
  const Combined run = run_ctab("solve --dy 2e-3 --vertical-load 78.5e3 --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto json = nlohmann::json::parse(run.output);
  EXPECT_EQ(json["mode"], "wheelset");
  EXPECT_EQ(json["load_kind"], "vertical_load_N");
  EXPECT_LT(json["roll_rad"].get<double>(), 0.0) << "the wheelset rolls at dy = 2 mm";
  for (const char* wheel : {"right", "left"}) {
    ASSERT_TRUE(json.contains(wheel)) << wheel;
    EXPECT_EQ(json[wheel]["status"], "converged") << wheel;
    EXPECT_NEAR(json[wheel]["vertical_load_N"].get<double>(), 78.5e3, 1.0) << wheel;
  }
  const auto single =
      nlohmann::json::parse(run_ctab("solve --dy 2e-3 --vertical-load 78.5e3 --mode wheel --side right --json").output);
  EXPECT_EQ(single["mode"], "wheel");
  EXPECT_EQ(single["roll_rad"].get<double>(), 0.0);
  EXPECT_FALSE(single.contains("left"));
  EXPECT_NE(run_ctab("geometry --dy-min 0 --dy-max 0").output.find("mode wheelset"), std::string::npos);
}

TEST(CliOptions, LongMaterialNamesAndHiddenAliasesAgree) {
  const std::string common = "solve --gap " + kSphere + " --approach 1e-3 --json ";
  const auto long_names =
      nlohmann::json::parse(run_ctab(common + "--youngs-modulus 200e9 --poisson-ratio 0.25").output);
  const auto aliases = nlohmann::json::parse(run_ctab(common + "--E 200e9 --nu 0.25").output);
  const auto steel = nlohmann::json::parse(run_ctab(common).output);
  EXPECT_EQ(long_names["normal_load_N"], aliases["normal_load_N"]);
  EXPECT_NE(long_names["normal_load_N"], steel["normal_load_N"]);
  const Combined both = run_ctab(common + "--E 200e9 --youngs-modulus 200e9");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.output.find("--E: alias of --youngs-modulus; give only one"), std::string::npos) << both.output;
}

TEST(CliOptions, ConfigPrintDefaultIsTheEmbeddedDefault) {
  const CtabRun run = ctab::test::run_ctab("config --print-default");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, ctab::gen::kDefaultTableConfig);
  const std::string copy = write_temp("printed_default.toml", run.out);
  const Combined checked = run_ctab("config " + copy);
  EXPECT_EQ(checked.exit_code, 0) << checked.output;
  EXPECT_NE(checked.output.find("265 lateral shifts x 1 vertical_load_N, wheelset mode, mim1d"), std::string::npos)
      << checked.output;
}

// ---- exit codes: 0 success, 2 usage or input, 3 I/O, 4 failed cases ----

TEST(CliExitCodes, EachCode) {
  struct Case {
    std::string arguments;
    int exit_code;
    std::string expected;  // on stdout or stderr
  };
  const std::string failing =
      write_temp("failing.toml", "[solver]\nmode = \"wheel\"\n[axes]\n"
                                 "lateral_displacement_m = { start = -0.08, stop = -0.079, step = 1e-3 }\n"
                                 "vertical_load_N = 78.5e3\n");
  const Case cases[] = {
      {"--help", 0, "Subcommands"},
      {"--version", 0, "ctab "},
      {"solve --help", 0, "--dy"},
      {"", 2, "ctab: error: A subcommand is required"},
      {"generat", 2, "ctab: error: unknown command 'generat'; did you mean 'generate'?"},
      {"xyz", 2, "ctab: error: unknown command 'xyz'; the commands are: generate inspect"},
      {"solve --bogus", 2, "ctab: error: The following argument was not expected: --bogus"},
      {"solve --dy", 2, "ctab: error: "},
      {"solve --dy 2e-3 --normal-load 1 --mode magic", 2, "--mode: magic not in {wheelset,wheel}"},
      {"solve --dy abc --normal-load 1", 2, "ctab: error: "},
      {"geometry --dy-step 0", 2, "--dy-step: expected a finite number > 0"},
      {"solve --gap /nonexistent.csv --load 1", 2, "/nonexistent.csv: cannot open gap file"},
      {"generate /nonexistent.toml", 2, "/nonexistent.toml"},
      {"generate " + failing + " -o " + ::testing::TempDir() + "no_such_dir/t.h5", 3, "does not exist"},
      {"solve --dy -0.08 --normal-load 78.5e3 --mode wheel --side right", 4, "ctab solve: right wheel at dy = -0.08 m"},
      {"generate " + failing + " --quiet -o " + ::testing::TempDir() + "failing.h5", 4, "of 4 wheel cases failed"},
  };
  for (const Case& c : cases) {
    const Combined run = run_ctab(c.arguments);
    EXPECT_EQ(run.exit_code, c.exit_code) << c.arguments << "\n" << run.output;
    EXPECT_NE(run.output.find(c.expected), std::string::npos) << c.arguments << "\n" << run.output;
  }
}

// ---- inputs that used to fail silently (exit 4, nothing on stderr), hang or crash ----

TEST(CliInput, EveryBadInputSaysWhatWentWrong) {
  struct Case {
    std::string arguments;
    int exit_code;
    std::string expected_on_stderr;
  };
  const std::string wheelrail = "solve --dy 2e-3 --normal-load 78.5e3 ";
  const Case cases[] = {
      {"solve --dy 2e-3 --approach -1e-3", 2, "--approach: expected an approach in (0, 0.01] m, got -1e-3"},
      {wheelrail + "--strip-width 1", 2, "--strip-width: expected a number in [1e-05, 0.005] m, got 1"},
      {wheelrail + "--strip-width 1e-6", 2, "--strip-width: expected a number in [1e-05, 0.005] m, got 1e-6"},
      {"solve --dy 1 --normal-load 78.5e3", 2, "wheel is off its rail at dy = 1000 mm"},
      {"solve --dy -0.08 --normal-load 78.5e3 --mode wheelset", 4,
       "right wheel at dy = -0.08 m, normal_load_N = 78500 (command line): max-iterations; the wheelset roll iteration "
       "did not converge"},
      {"solve --dy -0.08 --normal-load 78.5e3 --mode wheelset", 4, "; first contact at the end of the wheel profile"},
      {"geometry --dy-step 1e-21", 2, "--dy-step: gives more than 10^6 shifts"},
      {"geometry --dy-step nan", 2, "--dy-step: expected a finite number > 0"},
      {"geometry --dy-min 1e-3 --dy-max -1e-3", 2, "--dy-max: must not be below --dy-min"},
      {"geometry --conicity-amplitude 1", 2, "--conicity-amplitude: expected a finite number > 0 up to 0.02 m"},
      {"generate --threads 100000", 2, "--threads: Value 100000 not in range 0 to 1024"},
      {"bench solver --seconds -1", 2, "--seconds: expected a finite number > 0 up to 3600 s, got -1"},
      {"bench solver --seconds 0", 2, "--seconds: expected a finite number > 0"},
      {"bench wheelrail --seconds nan", 2, "--seconds: expected a finite number > 0"},
      {"bench generate --repetitions 0", 2, "--repetitions"},
      {"config", 2, "give --print-default or a config FILE.toml"},
  };
  for (const Case& c : cases) {
    const CtabRun run = ctab::test::run_ctab(c.arguments);
    EXPECT_EQ(run.exit_code, c.exit_code) << c.arguments << "\n" << run.output();
    EXPECT_NE(run.err.find(c.expected_on_stderr), std::string::npos) << c.arguments << "\n" << run.err;
  }
}

TEST(CliInput, OversizedOmpNumThreadsIsClampedWithAWarning) {
  const std::string config =
      write_temp("threads.toml", "[solver]\nmode = \"wheel\"\n[axes]\n"
                                 "lateral_displacement_m = { start = -1e-3, stop = 1e-3, step = 1e-3 }\n"
                                 "vertical_load_N = 78.5e3\n");
  ctab::test::CtabSpawnOptions options;
  options.environment = {"OMP_NUM_THREADS=100000"};
  const CtabRun run = ctab::test::run_ctab({"generate", config, "-o", ::testing::TempDir() + "threads.h5"}, options);
  EXPECT_EQ(run.exit_code, 0) << run.output();
  EXPECT_NE(run.err.find("ctab: warning: OMP_NUM_THREADS asks for 100000 threads; using 1024"), std::string::npos)
      << run.err;
}
