// SPDX-License-Identifier: Apache-2.0
#pragma once
// Runs the built ctab executable (CTAB_EXECUTABLE) without a shell: arguments as given, stdout and stderr captured
// separately, the exit code (or the signal that ended it), optional stdout descriptor and environment.
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

extern char** environ;

namespace ctab::test {

struct CtabRun {
  int exit_code = -1;  //!< -1 when ended by a signal
  std::string out, err;
  [[nodiscard]] std::string output() const { return out + err; }
};

struct CtabSpawnOptions {
  int stdout_fd = -1;                    //!< a descriptor for stdout instead of a capture file
  std::vector<std::string> environment;  //!< NAME=VALUE added to the environment
};

inline std::string read_text(const std::string& path) {
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

//! Starts ctab with stdout and stderr going to files next to `capture` (capture.out, capture.err).
inline pid_t spawn_ctab(const std::vector<std::string>& arguments, const std::string& capture,
                        const CtabSpawnOptions& options = {}) {
  std::vector<std::string> args = {CTAB_EXECUTABLE};
  args.insert(args.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_text;
  for (char** e = environ; *e; ++e) env_text.emplace_back(*e);
  env_text.insert(env_text.end(), options.environment.begin(), options.environment.end());
  std::vector<char*> envp;
  for (auto& e : env_text) envp.push_back(e.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (options.stdout_fd >= 0) posix_spawn_file_actions_adddup2(&actions, options.stdout_fd, STDOUT_FILENO);
  else
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, (capture + ".out").c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, (capture + ".err").c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  pid_t pid = -1;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data()) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

//! Waits for a spawned ctab and collects its result.
inline CtabRun wait_ctab(pid_t pid, const std::string& capture) {
  CtabRun run;
  int status = 0;
  if (pid <= 0 || waitpid(pid, &status, 0) != pid) return run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = read_text(capture + ".out");
  run.err = read_text(capture + ".err");
  return run;
}

inline CtabRun run_ctab(const std::vector<std::string>& arguments, const CtabSpawnOptions& options = {}) {
  const std::string capture = ::testing::TempDir() + "ctab_run_" + std::to_string(::getpid());
  return wait_ctab(spawn_ctab(arguments, capture, options), capture);
}

//! The same with the arguments split at spaces (for paths without spaces).
inline CtabRun run_ctab(const std::string& arguments, const CtabSpawnOptions& options = {}) {
  std::vector<std::string> split;
  std::istringstream words(arguments);
  for (std::string word; words >> word;) split.push_back(word);
  return run_ctab(split, options);
}

inline std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace ctab::test
