#include "output_guard.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "ctab/core/error.hpp"
#include "exit_codes.hpp"

namespace ctab::cli {

namespace {

namespace fs = std::filesystem;

constexpr std::array<char, 8> kHdf5Signature = {'\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n'};

[[noreturn]] void refuse(const std::string& output, const std::string& what) {
  throw gen::InputError(output, 0, what + "; not replaced (use --force to replace it anyway)");
}

// The directory must exist and take a new file: probe with the temporary name itself, then remove it.
void check_directory(const std::string& output) {
  fs::path directory = fs::path(output).parent_path();
  if (directory.empty()) directory = ".";
  std::error_code error;
  if (!fs::is_directory(directory, error))
    throw IoError(output + ": the output directory " + directory.string() + " does not exist");
  const std::string probe = temporary_table_path(output);
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw IoError(output + ": cannot create a file in " + directory.string() + ": " + std::strerror(errno));
  ::close(fd);
  ::unlink(probe.c_str());
}

// Prepared before the handler is installed; the handler only reads it.
char g_temporary_path[4096];
struct sigaction g_previous_int, g_previous_term;

extern "C" void remove_temporary_and_exit(int signal_number) {
  ::unlink(g_temporary_path);
  ::_exit(128 + signal_number);
}

}  // namespace

std::string temporary_table_path(const std::string& output) { return output + ".tmp-" + std::to_string(::getpid()); }

bool has_hdf5_signature(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::array<char, 8> head{};
  for (std::streamoff offset = 0; file; offset = offset == 0 ? 512 : 2 * offset) {
    file.seekg(offset);
    if (!file.read(head.data(), head.size())) return false;
    if (head == kHdf5Signature) return true;
  }
  return false;
}

void check_output_path(const std::string& output, const std::string& config_path, bool force) {
  std::error_code error;
  const fs::file_status status = fs::symlink_status(output, error);
  if (fs::exists(status)) {
    if (fs::is_directory(status)) throw gen::InputError(output, 0, "is a directory; give a file name for the table");
    if (!force) {
      if (fs::is_symlink(status)) refuse(output, "is a symbolic link");
      if (!fs::is_regular_file(status)) refuse(output, "is not a regular file (a FIFO, socket or device)");
      if (!config_path.empty() && fs::equivalent(output, config_path, error))
        refuse(output, "is the config file itself");
      if (!has_hdf5_signature(output)) refuse(output, "exists and is not an HDF5 contact table");
    }
  }
  check_directory(output);
}

InterruptCleanup::InterruptCleanup(const std::string& output) {
  const std::string path = temporary_table_path(output);
  if (path.size() >= sizeof g_temporary_path) throw gen::InputError(output, 0, "output path too long");
  std::memcpy(g_temporary_path, path.c_str(), path.size() + 1);
  struct sigaction action {};
  action.sa_handler = remove_temporary_and_exit;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &g_previous_int);
  sigaction(SIGTERM, &action, &g_previous_term);
}

InterruptCleanup::~InterruptCleanup() {
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
}

}  // namespace ctab::cli
