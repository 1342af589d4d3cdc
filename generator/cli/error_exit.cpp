// SPDX-License-Identifier: Apache-2.0
#include "error_exit.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <new>

#include <poll.h>
#include <unistd.h>

#include "ctab/core/error.hpp"
#include "exit_codes.hpp"

namespace ctab::cli {

int run_reporting_errors(const std::function<int()>& body) {
  try {
    return body();
  } catch (const IoError& e) {
    std::cerr << "ctab: error: " << e.what() << '\n';
    return kExitIo;
  } catch (const gen::Error& e) {
    std::cerr << "ctab: error: " << e.what() << '\n';
    return kExitUsage;
  } catch (const std::filesystem::filesystem_error& e) {
    std::cerr << "ctab: error: " << e.what() << '\n';
    return kExitIo;
  } catch (const std::bad_alloc&) {
    std::cerr << "ctab: error: out of memory\n";
    return kExitIo;
  } catch (const std::exception& e) {
    std::cerr << "ctab: internal error: " << e.what() << '\n';
    return kExitInternal;
  }
}

namespace {

// True when standard output is a pipe or socket whose reading end has closed (`ctab geometry | head -n 1`).
bool reader_closed() {
  pollfd out{STDOUT_FILENO, POLLOUT, 0};
  return ::poll(&out, 1, 0) == 1 && (out.revents & POLLERR) != 0;
}

}  // namespace

// SIGPIPE is ignored (main: a child's pipe must not kill ctab), so a closed pipe is a write error here. A reader
// that stopped reading standard output (head) is no failure: the command's own code, nothing on stderr.
int finish_standard_output(int code) {
  std::cout.flush();
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  if (flushed && !std::ferror(stdout) && std::cout.good()) return code;
  if (error == EPIPE || reader_closed()) return code;
  std::fprintf(stderr, "ctab: error: cannot write to standard output%s%s\n", error ? ": " : "",
               error ? std::strerror(error) : "");
  return code == kExitUsage ? code : kExitIo;
}

}  // namespace ctab::cli
