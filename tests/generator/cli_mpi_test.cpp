// SPDX-License-Identifier: Apache-2.0
// `mpirun -n 2 ctab generate` and `ctab batch` (built with CTAB_WITH_MPI) against a single-process run, byte for
// byte; a worker that fails reports its units as failed cases; a set-up error on rank 0 stops every rank (no hang).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_run.hpp"
#include "test_support.hpp"
#include "ctab/tables/table.hpp"

namespace {

namespace fs = std::filesystem;
using ctab::test::read_text;

std::string fresh_directory(const std::string& name) {
  const std::string directory = ::testing::TempDir() + "ctab_mpi_" + name;
  fs::remove_all(directory);
  fs::create_directories(directory);
  return directory + "/";
}

// Wheelset, mirrored, 41 rows: 21 half-axis rows, 3 work units of kRowsPerUnit = 8.
const char* const kConfig =
    "[axes]\nlateral_displacement_m = { start = -2e-3, stop = 2e-3, step = 0.1e-3 }\nvertical_load_N = 78.5e3\n";

// Runs a shell command line under `timeout` (a hang fails the test instead of stopping the suite); the exit code.
int run_shell(const std::string& environment, const std::string& command, const std::string& log) {
  const std::string line = "env SOURCE_DATE_EPOCH=1700000000 " + environment + " timeout 120 " + command + " >" + log +
                           ".out 2>" + log + ".err";
  const int status = std::system(line.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string mpirun(int ranks) {
  return std::string(CTAB_MPIEXEC) + " -n " + std::to_string(ranks) + " --oversubscribe --allow-run-as-root " +
         CTAB_EXECUTABLE;
}

std::string generate(const std::string& dir, const std::string& output) {
  return " generate " + dir + "small.toml --quiet --threads 1 -o " + dir + output;
}

}  // namespace

TEST(CliMpi, TwoRanksWriteTheSingleProcessFileByteForByte) {
  const std::string dir = fresh_directory("identical");
  std::ofstream(dir + "small.toml") << kConfig;
  ASSERT_EQ(run_shell("", CTAB_EXECUTABLE + generate(dir, "single.h5"), dir + "single"), 0)
      << read_text(dir + "single.err");
  for (const int ranks : {2, 3}) {
    const std::string name = "mpi" + std::to_string(ranks);
    ASSERT_EQ(run_shell("", mpirun(ranks) + generate(dir, name + ".h5"), dir + name), 0)
        << read_text(dir + name + ".err");
    EXPECT_EQ(read_text(dir + name + ".h5"), read_text(dir + "single.h5")) << ranks << " ranks";
  }
}

TEST(CliMpi, AFailingWorkerReportsItsUnitsAsFailedCases) {
  const std::string dir = fresh_directory("failing");
  std::ofstream(dir + "small.toml") << kConfig;
  // Rank 1 holds units 0 and 1 (kUnitsInFlight) and throws in both; rank 0 solves unit 2 itself.
  const int code = run_shell("CTAB_MPI_TEST_FAIL_RANK=1", mpirun(2) + generate(dir, "t.h5"), dir + "t");
  EXPECT_EQ(code, 4) << read_text(dir + "t.err");
  EXPECT_NE(read_text(dir + "t.err").find("solver-exception"), std::string::npos) << read_text(dir + "t.err");
  ctab::tables::Table table;
  const ctab::tables::TableResult read = ctab::tables::read_table(dir + "t.h5", table);
  ASSERT_TRUE(read.ok()) << read.message;
  std::size_t failed = 0;
  for (const auto status : table.status) failed += status == ctab::tables::CaseStatus::SolverException ? 1 : 0;
  // Units 0 and 1: half-axis rows 0..15 and their mirrors, 32 rows x 2 wheels; unit 2 (rows 16..24) converged.
  EXPECT_EQ(failed, 64u);
}

TEST(CliMpi, ASetUpErrorOnRankZeroStopsEveryRank) {
  const std::string dir = fresh_directory("setup");
  std::ofstream(dir + "small.toml") << kConfig;
  fs::create_directories(dir + "occupied.h5");  // an output that is a directory: rank 0 refuses it before solving
  const int code = run_shell("", mpirun(2) + generate(dir, "occupied.h5"), dir + "s");
  EXPECT_NE(code, 0);
  EXPECT_NE(code, 124) << "timed out";  // `timeout` ends a hung job with 124
  EXPECT_NE(read_text(dir + "s.err").find("occupied.h5"), std::string::npos) << read_text(dir + "s.err");
}

TEST(CliMpi, ThreePairBatchOnTwoRanksWritesTheSingleProcessTables) {
  CTAB_REQUIRE_SHARED();
  const std::string dir = fresh_directory("batch");
  fs::create_directories(dir + "wheels");
  fs::copy_file(std::string(CTAB_SHARED_DIR) + "/profiles/MBench_S1002_v3.prw", dir + "wheels/w1.prw");
  std::ofstream(dir + "wheels/bad.prw") << "not a profile\n";
  std::ofstream(dir + "small.toml") << "[solver]\nmode = \"wheel\"\n" << kConfig;  // 41 rows, 6 units
  std::ofstream(dir + "m.toml") << "config = \"small.toml\"\nwheels = [\"wheels/*.prw\", \"S1002\"]\n"
                                   "rails = [\"UIC60\"]\n";
  const std::string batch = " batch " + dir + "m.toml --quiet --threads 1 -o " + dir;
  ASSERT_EQ(run_shell("", CTAB_EXECUTABLE + batch + "one", dir + "one"), 4) << read_text(dir + "one.err");
  ASSERT_EQ(run_shell("", mpirun(2) + batch + "two", dir + "two"), 4) << read_text(dir + "two.err");
  for (const char* table : {"w1__UIC60.h5", "S1002__UIC60.h5"}) {
    ASSERT_TRUE(fs::exists(dir + "two/" + table)) << table;
    EXPECT_EQ(read_text(dir + "two/" + table), read_text(dir + "one/" + table)) << table;
  }
  EXPECT_FALSE(fs::exists(dir + "two/bad__UIC60.h5"));
  const std::string index = read_text(dir + "two/index.csv");
  EXPECT_NE(index.find("\"bad__UIC60.h5\",\"" + dir + "wheels/bad.prw\",\"UIC60\",input-error,"), std::string::npos)
      << index;
  // Again: both tables are complete, so rank 0 resumes them and no rank solves anything.
  ASSERT_EQ(run_shell("", mpirun(2) + batch + "two", dir + "again"), 4) << read_text(dir + "again.err");
  const std::string again = read_text(dir + "two/index.csv");
  EXPECT_NE(again.find("\"w1__UIC60.h5\",\"" + dir + "wheels/w1.prw\",\"UIC60\",ok,resumed,82,0,"), std::string::npos)
      << again;
  EXPECT_NE(again.find("\"S1002__UIC60.h5\",\"S1002\",\"UIC60\",ok,resumed,82,0,"), std::string::npos) << again;
}
