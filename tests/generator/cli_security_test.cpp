// SPDX-License-Identifier: Apache-2.0
// The CLI against hostile files and faults (docs/security.md): HDF5 inputs read in a child process whose crash or
// hang is exit 2 "corrupt table", a foreign HDF5 file never replaced, a full disk (an LD_PRELOAD shim) exit 3 with
// the old file intact, out of memory exit 3, invalid UTF-8 in `inspect --json`, `query` without --load on a load
// axis, one-row tables, and the load and modulus ranges shared by configs and options.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "ctab/tables/table.hpp"

namespace {

namespace fs = std::filesystem;
using ctab::test::CtabRun;
using ctab::test::read_text;
using ctab::test::run_ctab;

const char* const kLoadAxisConfig =
    "[solver]\nmode = \"wheel\"\n[axes]\n"
    "lateral_displacement_m = { start = -1e-3, stop = 1e-3, step = 1e-3 }\nvertical_load_N = [70e3, 80e3]\n";

// A fresh directory per test with a small load-axis table t.h5, its two shards and its blob.
struct Files {
  std::string dir, config, table, shard1, shard2, blob;
};

Files make_files(const std::string& name) {
  Files f;
  f.dir = ::testing::TempDir() + "ctab_security_" + name + "/";
  fs::remove_all(f.dir);
  fs::create_directories(f.dir);
  f.config = f.dir + "small.toml";
  std::ofstream(f.config) << kLoadAxisConfig;
  f.table = f.dir + "t.h5";
  f.shard1 = f.dir + "s1.h5";
  f.shard2 = f.dir + "s2.h5";
  f.blob = f.dir + "t.blob";
  EXPECT_EQ(run_ctab({"generate", f.config, "-o", f.table, "--quiet"}).exit_code, 0);
  EXPECT_EQ(run_ctab({"generate", f.config, "--shard", "1/2", "-o", f.shard1, "--quiet"}).exit_code, 0);
  EXPECT_EQ(run_ctab({"generate", f.config, "--shard", "2/2", "-o", f.shard2, "--quiet"}).exit_code, 0);
  EXPECT_EQ(run_ctab({"export", f.table, "-o", f.blob}).exit_code, 0);
  return f;
}

void expect_no_temporary(const std::string& dir) {
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << "left behind: " << entry.path();
}

}  // namespace

// CTAB_TEST_READ_FAULT (isolated_read.cpp) makes the reading child crash or hang as libhdf5 does on some corrupted
// files: every command that reads an HDF5 file the user gives survives it with exit 2, naming the file.
TEST(CliSecurity, CrashWhileReadingAnHdf5TableIsExit2CorruptTable) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reports the injected crash itself (exit 1) instead of dying by the signal";
#endif
  const Files f = make_files("crash");
  const std::vector<std::vector<std::string>> commands = {{"inspect", f.table},
                                                          {"inspect", f.table, "--json"},
                                                          {"query", f.table, "--dy", "0", "--load", "7e4"},
                                                          {"export", f.table, "-o", f.dir + "new.blob"},
                                                          {"merge", f.shard1, f.shard2, "-o", f.dir + "m.h5"},
                                                          {"bench", "lookup", f.table, "--queries", "10"}};
  for (const auto& arguments : commands) {
    const CtabRun run = run_ctab(arguments, {-1, {"CTAB_TEST_READ_FAULT=crash"}});
    EXPECT_EQ(run.exit_code, 2) << arguments[0] << "\n" << run.output();
    EXPECT_EQ(run.out, "") << arguments[0];
    const std::string named = arguments[0] == "merge" ? f.shard1 : f.table;
    EXPECT_NE(run.err.find("ctab: error: corrupt table: " + named + ": the reader crashed on it (signal 11"),
              std::string::npos)
        << run.err;
  }
  EXPECT_FALSE(fs::exists(f.dir + "new.blob"));
  EXPECT_FALSE(fs::exists(f.dir + "m.h5"));
  expect_no_temporary(f.dir);
}

TEST(CliSecurity, HangWhileReadingIsStoppedByTheTimeLimit) {
  const Files f = make_files("hang");
  const auto start = std::chrono::steady_clock::now();
  const CtabRun run = run_ctab({"inspect", f.table}, {-1, {"CTAB_TEST_READ_FAULT=hang", "CTAB_READ_TIME_LIMIT_S=1"}});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(run.exit_code, 2) << run.output();
  EXPECT_NE(run.err.find("corrupt table: " + f.table + ": reading it took longer than 1 s (CTAB_READ_TIME_LIMIT_S)"),
            std::string::npos)
      << run.err;
  EXPECT_LT(seconds, 20.0);
}

TEST(CliSecurity, ReadLimitsComeFromTheEnvironmentAndAreChecked) {
  const Files f = make_files("limits");
  const CtabRun small = run_ctab({"inspect", f.table}, {-1, {"CTAB_READ_MEMORY_LIMIT_GIB=1"}});
  EXPECT_EQ(small.exit_code, 0) << "a small table reads within 1 GiB\n" << small.output();
  const CtabRun bad = run_ctab({"inspect", f.table}, {-1, {"CTAB_READ_TIME_LIMIT_S=soon"}});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("CTAB_READ_TIME_LIMIT_S: expected a whole number in [1, 86400], got soon"), std::string::npos)
      << bad.err;
}

// batch resume reads the tables already in its directory: a corrupt one fails its own pair, not the batch.
TEST(CliSecurity, BatchResumeOfACorruptTableFailsItsPair) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reports the injected crash itself (exit 1) instead of dying by the signal";
#endif
  const Files f = make_files("batch");
  const std::string manifest = f.dir + "fleet.toml";
  std::ofstream(manifest) << "config = \"small.toml\"\nwheels = [\"S1002\"]\nrails = [\"UIC60\"]\npairing = \"all\"\n";
  ASSERT_EQ(run_ctab({"batch", manifest, "-o", f.dir + "fleet", "--quiet"}).exit_code, 0);
  const CtabRun run =
      run_ctab({"batch", manifest, "-o", f.dir + "fleet", "--quiet"}, {-1, {"CTAB_TEST_READ_FAULT=crash"}});
  EXPECT_EQ(run.exit_code, 4) << run.output();
  EXPECT_NE(run.err.find("corrupt table: " + f.dir + "fleet/S1002__UIC60.h5: the reader crashed"), std::string::npos)
      << run.err;
  EXPECT_NE(read_text(f.dir + "fleet/index.csv").find("input-error"), std::string::npos);
}

// An HDF5 file without ctab's schema_version attribute is foreign: never replaced, --force or not.
TEST(CliSecurity, AForeignHdf5FileIsNeverReplaced) {
  const Files f = make_files("foreign");
  const std::string foreign = f.dir + "foreign.h5";
  const hid_t file = H5Fcreate(foreign.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  H5Fclose(file);
  const std::string before = read_text(foreign);
  for (const bool force : {false, true}) {
    std::vector<std::string> arguments = {"generate", f.config, "-o", foreign, "--quiet"};
    if (force) arguments.push_back("--force");
    const CtabRun run = run_ctab(arguments);
    EXPECT_EQ(run.exit_code, 2) << run.output();
    EXPECT_NE(run.err.find(foreign + ": exists and is not a ctab table; ctab never replaces it"), std::string::npos)
        << run.err;
  }
  EXPECT_EQ(read_text(foreign), before);
}

// A full file system (enospc_shim.c: writes fail after N bytes): exit 3, no crash, the old file byte for byte, no
// temporary left behind, for every command that writes a table, a blob or an index.
TEST(CliSecurity, FullDiskIsExit3AndKeepsTheOldFile) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "the ENOSPC shim cannot be preloaded before the AddressSanitizer runtime";
#endif
  const Files f = make_files("full");
  const std::string manifest = f.dir + "fleet.toml";
  std::ofstream(manifest) << "config = \"small.toml\"\nwheels = [\"S1002\"]\nrails = [\"UIC60\"]\npairing = \"all\"\n";
  ASSERT_EQ(run_ctab({"batch", manifest, "-o", f.dir + "fleet", "--quiet"}).exit_code, 0);
  std::ofstream(f.config, std::ios::app) << "[output]\nstrip_samples = 9\n";  // another table: batch regenerates
  const std::string old_table = read_text(f.table), old_blob = read_text(f.blob);
  const std::string old_pair = read_text(f.dir + "fleet/S1002__UIC60.h5");
  const std::string old_index = read_text(f.dir + "fleet/index.csv");
  const std::vector<std::vector<std::string>> commands = {{"generate", f.config, "-o", f.table, "--quiet"},
                                                          {"merge", f.shard1, f.shard2, "-o", f.table, "--quiet"},
                                                          {"batch", manifest, "-o", f.dir + "fleet", "--quiet"},
                                                          {"export", f.shard1, "-o", f.blob},
                                                          {"export", f.shard1, "-o", f.blob, "--format", "c-header"}};
  for (const char* after : {"0", "3000", "20000"})
    for (const auto& arguments : commands) {
      const CtabRun run =
          run_ctab(arguments,
                   {-1, {std::string("LD_PRELOAD=") + CTAB_ENOSPC_SHIM, std::string("CTAB_ENOSPC_AFTER=") + after}});
      EXPECT_EQ(run.exit_code, 3) << arguments[0] << " after " << after << " bytes\n" << run.output();
      EXPECT_NE(run.err.find("ctab: error: "), std::string::npos) << run.err;
      EXPECT_EQ(run.err.find("internal error"), std::string::npos) << run.err;
    }
  EXPECT_EQ(read_text(f.table), old_table);
  EXPECT_EQ(read_text(f.blob), old_blob);
  EXPECT_EQ(read_text(f.dir + "fleet/S1002__UIC60.h5"), old_pair);
  EXPECT_EQ(read_text(f.dir + "fleet/index.csv"), old_index);
  expect_no_temporary(f.dir);
}

// Out of memory (an address-space limit on the whole process) is a clear message and exit 3, not "internal error".
TEST(CliSecurity, OutOfMemoryIsExit3) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer needs terabytes of address space";
#endif
  const Files f = make_files("memory");
  const std::string config =
      f.dir + "big.toml";  // about 1.3 GiB of table (under the 2 GiB limit), allocated before the sweep
  std::ofstream(config) << "[solver]\nmode = \"wheel\"\n[axes]\n"
                           "lateral_displacement_m = { start = -12e-3, stop = 12e-3, step = 1.2e-7 }\n"
                           "vertical_load_N = 78.5e3\n[output]\nstrip_samples = 64\n";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const rlimit limit{1000ull << 20, 1000ull << 20};
    setrlimit(RLIMIT_AS, &limit);
    const std::string output = f.dir + "big.h5";
    execl(CTAB_EXECUTABLE, CTAB_EXECUTABLE, "generate", config.c_str(), "-o", output.c_str(), "--quiet",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 3);
}

TEST(CliSecurity, InspectJsonReplacesInvalidUtf8) {
  const Files f = make_files("utf8");
  ctab::tables::Table table;
  ASSERT_TRUE(ctab::tables::read_table(f.table, table).ok());
  table.text_attributes["wheel_profile"] = "caf\xe9 \xff";
  const std::string path = f.dir + "latin1.h5";
  ASSERT_TRUE(ctab::tables::write_table(table, path).ok());
  const CtabRun run = run_ctab({"inspect", path, "--json"});
  EXPECT_EQ(run.exit_code, 0) << run.output();
  const nlohmann::json parsed = nlohmann::json::parse(run.out);
  EXPECT_EQ(parsed["provenance"]["wheel_profile"], "caf\xEF\xBF\xBD \xEF\xBF\xBD");
}

TEST(CliSecurity, QueryOnALoadAxisNeedsTheLoad) {
  const Files f = make_files("load");
  for (const std::string& file : {f.table, f.blob}) {
    const CtabRun run = run_ctab({"query", file, "--dy", "0"});
    EXPECT_EQ(run.exit_code, 2) << run.output();
    EXPECT_NE(run.err.find(file + ": the table has a load axis: give --load"), std::string::npos) << run.err;
    EXPECT_EQ(run_ctab({"query", file, "--dy", "0", "--load", "75e3"}).exit_code, 0);
  }
}

// A one-row table cannot be queried: generate and config refuse its config naming the file, line and key; solve
// --config still solves its one case.
TEST(CliSecurity, AOneRowAxisIsRefusedForATable) {
  const Files f = make_files("one_row");
  const std::string config = f.dir + "one_row.toml";
  std::ofstream(config) << "[solver]\nmode = \"wheel\"\n[axes]\n"
                           "lateral_displacement_m = { start = 0, stop = 1e-3, step = 2e-3 }\n"
                           "vertical_load_N = 78.5e3\n";
  const std::string expected = config +
                               ":4: 'axes.lateral_displacement_m': gives one lateral shift; a table needs at least 2 "
                               "(stop >= start + step)";
  for (const std::vector<std::string>& arguments :
       {std::vector<std::string>{"generate", config, "-o", f.dir + "one.h5", "--quiet"},
        std::vector<std::string>{"config", config}}) {
    const CtabRun run = run_ctab(arguments);
    EXPECT_EQ(run.exit_code, 2) << run.output();
    EXPECT_NE(run.err.find(expected), std::string::npos) << run.err;
  }
  EXPECT_EQ(run_ctab({"solve", "--config", config, "--dy", "0"}).exit_code, 0);
}

// One range per quantity: a config and an option refuse the same values with the same words.
TEST(CliSecurity, ConfigAndOptionsShareTheLoadAndModulusRanges) {
  const Files f = make_files("ranges");
  struct Case {
    std::string config_line, option, value, expected;
  };
  const Case cases[] = {{"[axes]\nvertical_load_N = 1e12\n", "--vertical-load", "1e12",
                         "expected a load in (0, 1e8] N"},
                        {"[axes]\napproach_m = 0.5\n", "--approach", "0.5", "expected an approach in (0, 0.01] m"},
                        {"[material]\nyoungs_modulus_Pa = 1e-21\n", "--youngs-modulus", "1e-21",
                         "expected a Young's modulus in (1e6, 1e13] Pa"}};
  for (const Case& c : cases) {
    const std::string config = f.dir + "range.toml";
    std::ofstream(config) << "[axes]\nlateral_displacement_m = { start = -1e-3, stop = 1e-3, step = 1e-3 }\n" +
                                 (c.config_line.rfind("[axes]", 0) == 0 ? c.config_line.substr(7)
                                                                        : "vertical_load_N = 78.5e3\n" + c.config_line);
    const CtabRun from_config = run_ctab({"config", config});
    EXPECT_EQ(from_config.exit_code, 2) << c.config_line;
    EXPECT_NE(from_config.err.find(c.expected), std::string::npos) << from_config.err;
    std::vector<std::string> arguments = {"solve", "--dy", "0", c.option, c.value};
    if (c.option == "--youngs-modulus") arguments.insert(arguments.end(), {"--vertical-load", "78.5e3"});
    const CtabRun from_option = run_ctab(arguments);
    EXPECT_EQ(from_option.exit_code, 2) << c.option;
    EXPECT_NE(from_option.err.find(c.option + ": " + c.expected), std::string::npos) << from_option.err;
  }
}

// A negative separation in a gap file is refused with the file and line.
TEST(CliSecurity, ANegativeGapIsRefused) {
  const Files f = make_files("gap");
  const std::string gap = f.dir + "gap.csv";
  std::ofstream(gap) << "y_m,h_m,A_per_m,B_per_m\n-1e-3,1e-6,2,1\n0,-1,2,1\n1e-3,1e-6,2,1\n";
  const CtabRun run = run_ctab({"solve", "--gap", gap, "--load", "1e3"});
  EXPECT_EQ(run.exit_code, 2) << run.output();
  EXPECT_NE(run.err.find(gap + ":3: field 'h_m': a separation must not be negative"), std::string::npos) << run.err;
}
