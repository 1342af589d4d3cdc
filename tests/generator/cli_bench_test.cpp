// SPDX-License-Identifier: Apache-2.0
// `ctab bench ... --json` (ctab's own figures only, issue 7), the timing statistics behind it, and
// scripts/speed_vs_contact.py, which compares those figures with CONTACT's reference CPU times.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench_stats.hpp"
#include "cli_run.hpp"

namespace {

using ctab::test::run_ctab;
using ctab::test::write_temp;

// Every row has the timing fields in order: min <= median <= worst, min <= mean <= worst, at least 5 samples.
void expect_timing(const nlohmann::json& row) {
  const double min = row.at("min_s"), median = row.at("median_s"), mean = row.at("mean_s"), worst = row.at("worst_s");
  EXPECT_GT(min, 0.0) << row;
  EXPECT_LE(min, median) << row;
  EXPECT_LE(median, worst) << row;
  EXPECT_LE(min, mean) << row;
  EXPECT_LE(mean, worst) << row;
  EXPECT_GE(row.at("samples").get<int>(), 5) << row;
}

struct ScriptRun {
  int exit_code = -1;
  std::string out, err;
};

// Runs scripts/speed_vs_contact.py with /usr/bin/python3 (the Debian interpreter the project uses).
// Its output goes to files named after the test and the process: ctest runs this binary's tests as parallel
// processes, and a shared name let one test read another's stderr (seen once in CI: an empty error message).
ScriptRun run_script(const std::string& arguments) {
  static int calls = 0;
  const std::string capture = ::testing::TempDir() + "speed_vs_contact_" +
                              ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
                              std::to_string(::getpid()) + "_" + std::to_string(++calls);
  const std::string command = "/usr/bin/python3 " CTAB_SOURCE_DIR "/scripts/speed_vs_contact.py " + arguments + " >" +
                              capture + ".out 2>" + capture + ".err";
  const int status = std::system(command.c_str());
  ScriptRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = ctab::test::read_text(capture + ".out");
  run.err = ctab::test::read_text(capture + ".err");
  return run;
}

}  // namespace

TEST(BenchStats, SummarizesTimes) {
  const ctab::cli::Timing odd = ctab::cli::summarize_times({3.0, 1.0, 2.0, 10.0, 4.0});
  EXPECT_EQ(odd.samples, 5u);
  EXPECT_DOUBLE_EQ(odd.mean_s, 4.0);
  EXPECT_DOUBLE_EQ(odd.min_s, 1.0);
  EXPECT_DOUBLE_EQ(odd.median_s, 3.0);
  EXPECT_DOUBLE_EQ(odd.worst_s, 10.0);
  EXPECT_DOUBLE_EQ(ctab::cli::summarize_times({4.0, 1.0, 2.0, 3.0}).median_s, 2.5) << "even count: middle two";
  EXPECT_EQ(ctab::cli::summarize_times({}).samples, 0u);
  int calls = 0;
  const ctab::cli::Timing timed = ctab::cli::time_repeatedly(0.0, [&] { ++calls; });
  EXPECT_EQ(calls, 5) << "at least kMinBenchSamples runs";
  EXPECT_EQ(timed.samples, 5u);
}

TEST(CliBench, SolverJsonHasCtabFiguresOnly) {
  const ctab::test::CtabRun run = run_ctab("bench solver --seconds 0.01 --json");
  ASSERT_EQ(run.exit_code, 0) << run.output();
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_EQ(json["benchmark"], "solver");
  EXPECT_EQ(json["normal_load_N"], 963e3);
  ASSERT_EQ(json["rows"].size(), 3u);
  const std::vector<double> widths = {0.2e-3, 0.08e-3, 0.04e-3};
  const std::vector<int> strips = {64, 158, 316};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& row = json["rows"][i];
    EXPECT_EQ(row["strip_width_m"].get<double>(), widths[i]);
    EXPECT_EQ(row["strips"].get<int>(), strips[i]);
    EXPECT_GT(row["iterations"].get<int>(), 0);
    expect_timing(row);
  }
}

TEST(CliBench, WheelRailJsonHasOneRowPerShift) {
  const ctab::test::CtabRun run = run_ctab("bench wheelrail --seconds 0.01 --json");
  ASSERT_EQ(run.exit_code, 0) << run.output();
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_EQ(json["benchmark"], "wheelrail");
  EXPECT_EQ(json["normal_load_N"], 78.5e3);
  ASSERT_EQ(json["rows"].size(), 5u);
  const std::vector<double> shifts = {-1e-3, 0.0, 1e-3, 2e-3, 5e-3};
  for (std::size_t i = 0; i < 5; ++i) {
    const auto& row = json["rows"][i];
    EXPECT_EQ(row["dy_m"].get<double>(), shifts[i]);
    EXPECT_GE(row["patches"].get<int>(), 1);
    EXPECT_GT(row["iterations"].get<int>(), 0);
    expect_timing(row);
  }
}

// Issue 7: the binary prints no reference times of other programs.
TEST(CliBench, TextOutputNamesNoOtherProgram) {
  for (const char* bench : {"solver", "wheelrail"}) {
    const ctab::test::CtabRun run = run_ctab(std::string("bench ") + bench + " --seconds 0.01");
    ASSERT_EQ(run.exit_code, 0) << run.output();
    for (const char* header : {"iters", "samples", "mean ms", "min ms", "median ms", "worst ms"})
      EXPECT_NE(run.out.find(header), std::string::npos) << bench << ": " << header << "\n" << run.out;
    for (const char* other : {"CONTACT", "paper", "Matlab", "speed-up"})
      EXPECT_EQ(run.out.find(other), std::string::npos) << bench << ": " << other << "\n" << run.out;
  }
}

TEST(CliBench, GenerateJson) {
  const ctab::test::CtabRun run = run_ctab("bench generate --repetitions 1 --json");
  ASSERT_EQ(run.exit_code, 0) << run.output();
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_EQ(json["benchmark"], "generate");
  EXPECT_EQ(json["lateral_shifts"], 265);
  ASSERT_EQ(json["rows"].size(), 2u);
  EXPECT_EQ(json["rows"][1]["threads"], 2);
  EXPECT_GT(json["rows"][0]["best_s"].get<double>(), 0.0);
  EXPECT_GT(json["parallel_efficiency"].get<double>(), 0.0);
  EXPECT_GT(json["file_bytes"].get<double>(), 1000.0);
}

// The script's arithmetic on fixed inputs: speed-up = CONTACT / median of the runs' means; min over all runs.
TEST(SpeedVsContactScript, ComputesTheSpeedUpTable) {
  const std::string reference = ::testing::TempDir() + "speed_reference";
  std::filesystem::create_directories(reference + "/wheelrail");
  write_temp("speed_reference/hertz_sphere.csv",
             "case,dx_mm,cpu_s_median5\nhertz_F_dx0p2,0.2,0.030\nhertz_F_dx0p08,0.08,0.200\n"
             "hertz_P_dx0p2,0.2,9.0\n");
  write_temp("speed_reference/wheelrail/summary.csv",
             "dy_mm,ipatch,cpu_s_case\n-1.0,1,0.150\n5.0,1,0.100\n5.0,2,0.100\n");
  auto solver = [](double mean_s, double min_s) {
    return nlohmann::json{
        {"benchmark", "solver"},
        {"normal_load_N", 963e3},
        {"rows",
         {{{"strip_width_m", 0.2e-3}, {"strips", 64}, {"iterations", 4}, {"mean_s", mean_s}, {"min_s", min_s}},
          {{"strip_width_m", 0.04e-3}, {"strips", 316}, {"iterations", 4}, {"mean_s", 0.01}, {"min_s", 0.009}}}}}
        .dump();
  };
  const std::string s1 = write_temp("speed_s1.json", solver(0.3e-3, 0.2e-3));
  const std::string s2 = write_temp("speed_s2.json", solver(0.1e-3, 0.09e-3));
  const std::string s3 = write_temp("speed_s3.json", solver(0.2e-3, 0.15e-3));
  const std::string w1 = write_temp(
      "speed_w1.json",
      nlohmann::json{{"benchmark", "wheelrail"},
                     {"normal_load_N", 78.5e3},
                     {"rows",
                      {{{"dy_m", -1e-3}, {"patches", 1}, {"iterations", 9}, {"mean_s", 1e-3}, {"min_s", 0.9e-3}},
                       {{"dy_m", 5e-3}, {"patches", 2}, {"iterations", 9}, {"mean_s", 0.5e-3}, {"min_s", 0.4e-3}}}}}
          .dump());
  const ScriptRun run =
      run_script("--reference " + reference + " --solver-json " + s1 + " " + s2 + " " + s3 + " --wheelrail-json " + w1);
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  // 0.2 mm: median mean 0.2 ms, min 0.09 ms, paper 2.0 ms, CONTACT 30 ms: 150x. 0.04 mm: no CONTACT row.
  EXPECT_NE(run.out.find("| 0.2 mm | 64 | 4 | 0.200 ms (0.0900) | 2.00 ms | 30.0 ms | 150× |"), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("| 0.04 mm | 316 | 4 | 10.0 ms (9.00) | 92.0 ms | — | — |"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("| −1 mm | 1 | 9 | 1.00 ms (0.900) | 150 ms | 150× |"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("| 5 mm | 2 | 9 | 0.500 ms (0.400) | 100 ms | 200× |"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("(3 run(s)"), std::string::npos) << run.out;
}

TEST(SpeedVsContactScript, RefusesOtherInput) {
  const std::string wrong = write_temp("speed_wrong.json", R"({"benchmark": "wheelrail", "rows": []})");
  const ScriptRun kind = run_script("--solver-json " + wrong + " --wheelrail-json " + wrong);
  EXPECT_EQ(kind.exit_code, 2);
  EXPECT_NE(kind.err.find(wrong + ": expected the output of `ctab bench solver --json`"), std::string::npos)
      << kind.err;
  const std::string broken = write_temp("speed_broken.json", "{\n oops");
  const ScriptRun text = run_script("--solver-json " + broken + " --wheelrail-json " + wrong);
  EXPECT_EQ(text.exit_code, 2);
  EXPECT_NE(text.err.find(broken + ": line 2: not JSON"), std::string::npos) << text.err;
  const ScriptRun missing = run_script("--reference /no/such/dir --ctab " CTAB_EXECUTABLE " --seconds 0.01");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("/no/such/dir/hertz_sphere.csv: cannot read"), std::string::npos) << missing.err;
}

// With the real reference data (../shared/reference/contact) and the built ctab: the columns the README names.
TEST(SpeedVsContactScript, ReadsTheContactReference) {
  const std::filesystem::path reference =
      std::filesystem::path(CTAB_SOURCE_DIR) / ".." / "shared" / "reference" / "contact";
  if (!std::filesystem::exists(reference / "hertz_sphere.csv")) GTEST_SKIP() << "no reference data at " << reference;
  const ScriptRun run = run_script("--ctab " CTAB_EXECUTABLE " --seconds 0.01 --reference " + reference.string());
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  for (const char* cell : {"| 2.00 ms | 33.0 ms |", "| 29.0 ms | 205 ms |", "| 92.0 ms | 993 ms |", "| 146 ms |",
                           "| 195 ms |", "| 207 ms |", "| 138 ms |", "| 135 ms |"})
    EXPECT_NE(run.out.find(cell), std::string::npos) << cell << "\n" << run.out;
}
