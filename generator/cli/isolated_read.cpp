// SPDX-License-Identifier: Apache-2.0
#include "isolated_read.hpp"

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <stdexcept>

#include "ctab/core/error.hpp"
#include "error_exit.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define CTAB_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CTAB_ADDRESS_SANITIZER 1
#endif
#endif

namespace ctab::cli {

namespace {

// AddressSanitizer reserves terabytes of address space for its shadow memory: an address-space limit would fail
// every allocation, so a sanitizer build reads without one (the time limit stays).
#ifdef CTAB_ADDRESS_SANITIZER
constexpr bool kLimitAddressSpace = false;
#else
constexpr bool kLimitAddressSpace = true;
#endif

std::uint64_t environment_number(const char* name, std::uint64_t fallback, std::uint64_t max) {
  const char* text = std::getenv(name);
  if (text == nullptr || *text == '\0') return fallback;
  std::uint64_t value = 0;
  const char* end = text + std::strlen(text);
  const auto [at, error] = std::from_chars(text, end, value);
  if (error != std::errc() || at != end || value < 1 || value > max)
    throw gen::InputError(name, 0, std::string("expected a whole number in [1, ") + std::to_string(max) + "], got " +
                                       text);
  return value;
}

void write_all(int fd, const std::string& text) {
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent has gone: nothing to tell
    done += static_cast<std::size_t>(n);
  }
}

// Test hook (tests/generator/cli_isolation_test.cpp): CTAB_TEST_READ_FAULT=crash|hang makes the child crash or hang
// as libhdf5 does on some corrupted files, when it starts reading a file.
void injected_fault() {
  const char* fault = std::getenv("CTAB_TEST_READ_FAULT");
  if (fault == nullptr) return;
  if (std::strcmp(fault, "crash") == 0) ::raise(SIGSEGV);
  if (std::strcmp(fault, "hang") == 0)
    for (;;) ::pause();
}

// The address space this process already maps (inherited by the child: a batch's parent may hold gigabytes).
std::uint64_t mapped_bytes() {
  std::FILE* file = std::fopen("/proc/self/statm", "r");
  unsigned long long pages = 0;
  if (file != nullptr) {
    if (std::fscanf(file, "%llu", &pages) != 1) pages = 0;
    std::fclose(file);
  }
  return pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

[[noreturn]] void run_child(const std::function<int(IsolatedChild&)>& body, int reply_fd, const ReadLimits& limits) {
  rlimit core{0, 0};
  ::setrlimit(RLIMIT_CORE, &core);  // a crash on a hostile file leaves no core dump
  rlimit memory{};
  ::getrlimit(RLIMIT_AS, &memory);
  const std::uint64_t limit = mapped_bytes() + limits.memory_bytes;  // the read's own memory on top of the parent's
  if (memory.rlim_max == RLIM_INFINITY || memory.rlim_max > limit) memory.rlim_cur = limit;
  if (kLimitAddressSpace) ::setrlimit(RLIMIT_AS, &memory);  // the soft limit alone: trusted_from_here raises it
  ::alarm(limits.seconds);          // SIGALRM's default action ends the child
  IsolatedChild child(reply_fd);
  const int code = finish_standard_output(run_reporting_errors([&] { return body(child); }));
  std::fflush(stderr);
  ::_exit(code);  // no atexit handlers: libhdf5's clean-up is not safe after it failed on a hostile file
}

std::string signal_text(int number) {
  const char* name = ::strsignal(number);
  return "signal " + std::to_string(number) + (name ? std::string(", ") + name : std::string());
}

}  // namespace

ReadLimits read_limits() {
  ReadLimits limits;
  limits.seconds = static_cast<unsigned>(environment_number("CTAB_READ_TIME_LIMIT_S", limits.seconds, 86400));
  limits.memory_bytes = environment_number("CTAB_READ_MEMORY_LIMIT_GIB", limits.memory_bytes >> 30, 65536) << 30;
  return limits;
}

void IsolatedChild::reading(const std::string& path) {
  write_all(reply_fd_, "reading\t" + path + "\n");
  injected_fault();
}

void IsolatedChild::trusted_from_here() {
  write_all(reply_fd_, "trusted\n");
  ::alarm(0);
  rlimit memory{};
  ::getrlimit(RLIMIT_AS, &memory);
  memory.rlim_cur = memory.rlim_max;
  ::setrlimit(RLIMIT_AS, &memory);
}

void IsolatedChild::reply(const std::string& text) { write_all(reply_fd_, "reply\t" + text + "\n"); }

IsolatedResult run_isolated(const std::function<int(IsolatedChild&)>& body) {
  const ReadLimits limits = read_limits();
  int fds[2];
  if (::pipe(fds) != 0) throw gen::Error(std::string("cannot create a pipe: ") + std::strerror(errno));
  std::cout.flush();
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw gen::Error(std::string("cannot start a process to read the input: ") + std::strerror(errno));
  }
  if (pid == 0) {
    ::close(fds[0]);
    run_child(body, fds[1], limits);
  }
  ::close(fds[1]);
  std::string text;
  char buffer[4096];
  for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  IsolatedResult result;
  std::string path = "input";
  bool trusted = false;
  for (std::size_t at = 0, end; at < text.size(); at = end + 1) {
    end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(at, end - at);
    if (line.rfind("reading\t", 0) == 0) path = line.substr(8);
    else if (line.rfind("reply\t", 0) == 0) result.reply = line.substr(6);
    trusted = trusted || line == "trusted";
  }
  if (WIFEXITED(status)) {
    result.exit_code = WEXITSTATUS(status);
    return result;
  }
  const int number = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  if (trusted) throw std::runtime_error("the process working on " + path + " ended by " + signal_text(number));
  if (number == SIGALRM)
    throw gen::Error("corrupt table: " + path + ": reading it took longer than " + std::to_string(limits.seconds) +
                     " s (CTAB_READ_TIME_LIMIT_S); HDF5 tables must come from trusted sources (docs/security.md)");
  throw gen::Error("corrupt table: " + path + ": the reader crashed on it (" + signal_text(number) +
                   "); HDF5 tables must come from trusted sources, a blob is the format for others (docs/security.md)");
}

}  // namespace ctab::cli
