// SPDX-License-Identifier: Apache-2.0
// ctab's output safety: what `generate -o` may replace, output-directory checks before the sweep, interrupts that
// leave no temporary file, and write errors on standard output (exit code 3).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using ctab::test::CtabRun;
using ctab::test::run_ctab;

// A fresh directory per test.
std::string fresh_directory(const std::string& name) {
  const std::string directory = ::testing::TempDir() + "ctab_output_" + name;
  fs::remove_all(directory);
  fs::create_directories(directory);
  return directory + "/";
}

const char* const kSmallConfig =
    "[solver]\nmode = \"wheel\"\n[axes]\n"
    "lateral_displacement_m = { start = -1e-3, stop = 1e-3, step = 1e-3 }\nvertical_load_N = 78.5e3\n";

bool is_hdf5(const std::string& path) {
  const std::string text = ctab::test::read_text(path);
  return text.rfind("\x89HDF\r\n\x1a\n", 0) == 0;
}

}  // namespace

TEST(CliOutput, ReplacesOnlyCtabFilesNeverAnInputOrAForeignFile) {
  const std::string dir = fresh_directory("refuse");
  const std::string config = ctab::test::write_temp("ctab_output_refuse/small.toml", kSmallConfig);
  const std::string text = ctab::test::write_temp("ctab_output_refuse/notes.txt", "my notes\n");
  fs::create_symlink(text, dir + "link.h5");
  ASSERT_EQ(mkfifo((dir + "fifo.h5").c_str(), 0644), 0);
  struct Case {
    std::string output, expected;
  };
  const std::string never = "; ctab never replaces it (not even with --force)";
  const Case cases[] = {{text, "exists and is not a ctab table" + never},
                        {config, "is an input of this command" + never},
                        {dir + "link.h5", "is a symbolic link" + never},
                        {dir + "fifo.h5", "is not a regular file (a FIFO, socket or device)" + never},
                        {"/dev/null", "is not a regular file (a FIFO, socket or device)" + never},
                        {dir, "is a directory"}};
  for (const Case& c : cases)
    for (const bool force : {false, true}) {
      std::vector<std::string> arguments = {"generate", config, "-o", c.output};
      if (force) arguments.push_back("--force");
      const CtabRun run = run_ctab(arguments);
      EXPECT_EQ(run.exit_code, 2) << c.output << "\n" << run.output();
      EXPECT_NE(run.err.find(c.output + ": " + c.expected), std::string::npos) << run.err;
      EXPECT_EQ(run.err.find(" cases"), std::string::npos) << "refused before the sweep: " << run.err;
    }
  struct stat null_status {};
  ASSERT_EQ(stat("/dev/null", &null_status), 0);
  EXPECT_TRUE(S_ISCHR(null_status.st_mode)) << "/dev/null is still a device";
  EXPECT_EQ(ctab::test::read_text(text), "my notes\n");
  EXPECT_EQ(ctab::test::read_text(config), kSmallConfig);
  // An existing table is replaced without --force.
  const CtabRun first = run_ctab({"generate", config, "-o", dir + "t.h5", "--quiet"});
  ASSERT_EQ(first.exit_code, 0) << first.output();
  EXPECT_EQ(run_ctab({"generate", config, "-o", dir + "t.h5", "--quiet"}).exit_code, 0);
  EXPECT_TRUE(is_hdf5(dir + "t.h5"));
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos) << "left behind: " << entry.path();
}

// A blob where a table goes (and a table where an export goes) needs --force; a foreign HDF5 file is never replaced.
TEST(CliOutput, TheOtherCtabKindNeedsForce) {
  const std::string dir = fresh_directory("kinds");
  const std::string config = ctab::test::write_temp("ctab_output_kinds/small.toml", kSmallConfig);
  ASSERT_EQ(run_ctab({"generate", config, "-o", dir + "t.h5", "--quiet"}).exit_code, 0);
  ASSERT_EQ(run_ctab({"export", dir + "t.h5", "-o", dir + "t.blob"}).exit_code, 0);
  ASSERT_EQ(run_ctab({"export", dir + "t.h5", "-o", dir + "t.h", "--format", "c-header"}).exit_code, 0);
  ASSERT_EQ(run_ctab({"generate", config, "-o", dir + "u.h5", "--quiet"}).exit_code, 0);
  // export replaces its own kinds (a blob, a header it wrote) without --force
  EXPECT_EQ(run_ctab({"export", dir + "t.h5", "-o", dir + "t.blob"}).exit_code, 0);
  EXPECT_EQ(run_ctab({"export", dir + "t.h5", "-o", dir + "t.h", "--format", "c-header"}).exit_code, 0);
  EXPECT_EQ(run_ctab({"export", dir + "t.h5", "-o", dir + "t.h"}).exit_code, 0) << "a header by a blob";
  const CtabRun blob_as_table = run_ctab({"generate", config, "-o", dir + "t.blob", "--quiet"});
  EXPECT_EQ(blob_as_table.exit_code, 2);
  EXPECT_NE(blob_as_table.err.find("is a ctab blob or exported header, not a table; not replaced (use --force"),
            std::string::npos)
      << blob_as_table.err;
  EXPECT_EQ(run_ctab({"generate", config, "-o", dir + "t.blob", "--quiet", "--force"}).exit_code, 0);
  EXPECT_TRUE(is_hdf5(dir + "t.blob"));
  const CtabRun table_as_blob = run_ctab({"export", dir + "t.h5", "-o", dir + "u.h5"});
  EXPECT_EQ(table_as_blob.exit_code, 2);
  EXPECT_NE(table_as_blob.err.find("is a ctab table, not a blob; not replaced (use --force"), std::string::npos)
      << table_as_blob.err;
  EXPECT_EQ(run_ctab({"export", dir + "t.h5", "-o", dir + "u.h5", "--force"}).exit_code, 0);
  // its own input: never, and the input stays as it was
  const std::string before = ctab::test::read_text(dir + "t.h5");
  for (const bool force : {false, true}) {
    std::vector<std::string> arguments = {"export", dir + "t.h5", "-o", dir + "t.h5"};
    if (force) arguments.push_back("--force");
    const CtabRun self = run_ctab(arguments);
    EXPECT_EQ(self.exit_code, 2) << self.output();
    EXPECT_NE(self.err.find("is an input of this command; ctab never replaces it"), std::string::npos) << self.err;
  }
  EXPECT_EQ(ctab::test::read_text(dir + "t.h5"), before);
  // merge: a shard is an input
  ASSERT_EQ(run_ctab({"generate", config, "-o", dir + "shard.h5", "--quiet"}).exit_code, 0);
  const CtabRun merge_self = run_ctab({"merge", dir + "shard.h5", "-o", dir + "shard.h5", "--force"});
  EXPECT_EQ(merge_self.exit_code, 2);
  EXPECT_NE(merge_self.err.find("is an input of this command"), std::string::npos) << merge_self.err;
}

TEST(CliOutput, UnwritableOrMissingDirectoryFailsBeforeTheSweep) {
  const std::string config = ctab::test::write_temp("ctab_output_dirs.toml", kSmallConfig);
  std::string unwritable = "/sys/ctab_table.h5";  // sysfs: no new files, not even for root
  if (::geteuid() != 0) {
    const std::string dir = fresh_directory("readonly");
    ASSERT_EQ(chmod(dir.c_str(), 0555), 0);
    unwritable = dir + "t.h5";
  }
  for (const std::string& output : {::testing::TempDir() + "ctab_no_such_dir/t.h5", unwritable}) {
    const CtabRun run = run_ctab({"generate", config, "-o", output});  // not --quiet: the sweep would report
    EXPECT_EQ(run.exit_code, 3) << output << "\n" << run.output();
    EXPECT_NE(run.err.find("ctab: error: " + output + ": "), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find("cases"), std::string::npos) << "found before the sweep: " << run.err;
    EXPECT_EQ(run.err.find(".tmp-"), std::string::npos) << "names the user's file: " << run.err;
  }
}

// SIGINT and SIGTERM during the sweep: exit 128 + signal and remove OUTPUT.tmp-<pid> (here a stand-in created by
// the test: the real one exists only during the short write).
TEST(CliOutput, InterruptRemovesTheTemporaryFile) {
  const std::string config =
      ctab::test::write_temp("ctab_output_long.toml",
                             "[axes]\nlateral_displacement_m = { start = -12e-3, stop = 12e-3, step = 0.01e-3 }\n"
                             "vertical_load_N = [50e3, 78.5e3, 100e3]\n");
  for (const int signal_number : {SIGINT, SIGTERM}) {
    const std::string dir = fresh_directory("signal" + std::to_string(signal_number));
    const std::string output = dir + "t.h5", capture = dir + "capture";
    const pid_t pid = ctab::test::spawn_ctab({"generate", config, "-o", output, "--threads", "1"}, capture);
    ASSERT_GT(pid, 0);
    // The first progress line comes once the sweep runs (the handler is installed before it).
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (ctab::test::read_text(capture + ".err").find("cases") == std::string::npos &&
           std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const std::string temporary = output + ".tmp-" + std::to_string(pid);
    ctab::test::write_temp("ctab_output_signal" + std::to_string(signal_number) + "/t.h5.tmp-" + std::to_string(pid),
                           "partial");
    ASSERT_TRUE(fs::exists(temporary));
    ASSERT_EQ(kill(pid, signal_number), 0);
    const CtabRun run = ctab::test::wait_ctab(pid, capture);
    EXPECT_EQ(run.exit_code, 128 + signal_number) << run.output();
    EXPECT_FALSE(fs::exists(temporary));
    EXPECT_FALSE(fs::exists(output));
  }
}

// A full disk is exit 3 with a message; a closed pipe (`ctab geometry | head -n 1`) is the reader's choice: the
// command's own exit code, nothing on stderr.
TEST(CliOutput, StandardOutputWriteErrorsExitThree) {
  const int full = ::open("/dev/full", O_WRONLY);
  ASSERT_GE(full, 0);
  ctab::test::CtabSpawnOptions to_full;
  to_full.stdout_fd = full;
  for (const char* arguments : {"geometry", "--help", "config --print-default"}) {
    const CtabRun run = run_ctab(std::string(arguments), to_full);
    EXPECT_EQ(run.exit_code, 3) << arguments << "\n" << run.err;
    EXPECT_NE(run.err.find("ctab: error: cannot write to standard output"), std::string::npos) << run.err;
  }
  ::close(full);
  int pipe_ends[2];
  ASSERT_EQ(::pipe(pipe_ends), 0);
  ::close(pipe_ends[0]);  // nobody reads: writes fail with EPIPE (ctab ignores SIGPIPE)
  ctab::test::CtabSpawnOptions to_closed_pipe;
  to_closed_pipe.stdout_fd = pipe_ends[1];
  const CtabRun run = run_ctab("geometry --dy-min 0 --dy-max 1e-3", to_closed_pipe);
  ::close(pipe_ends[1]);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
}
