// SPDX-License-Identifier: Apache-2.0
// `ctab export`, `ctab query` and `ctab bench lookup` end to end on a generated default table: blob and HDF5
// answer alike, the C header holds the blob, bad input stops with exit code 2 and a message.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

struct CommandRun {
  int code;
  std::string output;
};

// CTest runs each test of this file as its own process, several at once: every path is this process's own.
fs::path process_dir() { return fs::path(::testing::TempDir()) / ("ctab_lookup_cli_" + std::to_string(::getpid())); }

CommandRun run(const std::string& arguments) {
  const fs::path out = process_dir() / "command_output.txt";
  const std::string command = std::string(CTAB_EXECUTABLE) + " " + arguments + " > " + out.string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(out);
  std::stringstream text;
  text << in.rdbuf();
  return {WEXITSTATUS(status), text.str()};
}

class LookupCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = process_dir();
    fs::create_directories(dir_);
    ASSERT_EQ(run("generate --quiet -o " + (dir_ / "t.h5").string()).code, 0);
  }
  static void TearDownTestSuite() {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  static fs::path dir_;
};
fs::path LookupCli::dir_;

TEST_F(LookupCli, ExportedBlobAnswersLikeTheHdf5Table) {
  const std::string h5 = (dir_ / "t.h5").string(), blob = (dir_ / "t.blob").string();
  ASSERT_EQ(run("export " + h5 + " -o " + blob).code, 0);
  for (const char* dy : {"-7.31e-3", "0.05e-3", "6.27e-3"}) {
    const CommandRun a = run("query " + h5 + " --dy " + dy + " --wheel left --json --strips");
    const CommandRun b = run("query " + blob + " --dy " + dy + " --wheel left --json --strips");
    ASSERT_EQ(a.code, 0) << a.output;
    EXPECT_EQ(a.output, b.output);
    EXPECT_NE(a.output.find("\"normal_force_N\""), std::string::npos);
  }
  const CommandRun clamped = run("query " + blob + " --dy 0.5");
  EXPECT_EQ(clamped.code, 0);
  EXPECT_NE(clamped.output.find("clamped"), std::string::npos);
}

TEST_F(LookupCli, SinglePrecisionAndCHeaderExports) {
  const std::string h5 = (dir_ / "t.h5").string();
  ASSERT_EQ(run("export " + h5 + " --single-precision -o " + (dir_ / "f.blob").string()).code, 0);
  ASSERT_EQ(run("export " + h5 + " -o " + (dir_ / "d.blob").string()).code, 0);
  EXPECT_LT(fs::file_size(dir_ / "f.blob"), fs::file_size(dir_ / "d.blob") * 6 / 10);
  ASSERT_EQ(run("export " + h5 + " --format c-header --name my_table -o " + (dir_ / "t.h").string()).code, 0);
  std::ifstream in(dir_ / "t.h");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("static my_table_ALIGN const unsigned char my_table["), std::string::npos);
  EXPECT_NE(text.str().find("my_table_size = " + std::to_string(fs::file_size(dir_ / "d.blob")) + "u;"),
            std::string::npos);
  EXPECT_EQ(run("export " + h5 + " --format c-header --name 9bad -o x.h").code, 2) << "CLI11 validation error";
}

TEST_F(LookupCli, BadInputStopsWithAMessage) {
  const CommandRun missing = run("query " + (dir_ / "missing.blob").string() + " --dy 0");
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.output.find("cannot open"), std::string::npos);
  const CommandRun wrong_axis = run("query " + (dir_ / "t.h5").string() + " --dy 0 --approach 1e-4");
  EXPECT_EQ(wrong_axis.code, 2);
  EXPECT_NE(wrong_axis.output.find("use --load"), std::string::npos);
  std::ofstream((dir_ / "junk.blob").string()) << "not a table";
  const CommandRun junk = run("export " + (dir_ / "junk.blob").string() + " -o " + (dir_ / "out.blob").string());
  EXPECT_EQ(junk.code, 2);
  EXPECT_FALSE(fs::exists(dir_ / "out.blob")) << "no output on failure";
}

TEST_F(LookupCli, BenchLookupPrintsItsFigures) {
  const CommandRun bench = run("bench lookup " + (dir_ / "t.h5").string() + " --queries 2000 --repetitions 1");
  ASSERT_EQ(bench.code, 0) << bench.output;
  EXPECT_NE(bench.output.find("p99.99"), std::string::npos);
  EXPECT_NE(bench.output.find("memory"), std::string::npos);
  EXPECT_NE(bench.output.find("single vs double"), std::string::npos);
}

}  // namespace
