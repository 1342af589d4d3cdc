#include "error_exit.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <new>

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

// SIGPIPE is ignored (main), so a closed pipe is a write error here.
int finish_standard_output(int code) {
  std::cout.flush();
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  if (flushed && !std::ferror(stdout) && std::cout.good()) return code;
  std::fprintf(stderr, "ctab: error: cannot write to standard output%s%s\n", error ? ": " : "",
               error ? std::strerror(error) : "");
  return code == kExitUsage ? code : kExitIo;
}

}  // namespace ctab::cli
