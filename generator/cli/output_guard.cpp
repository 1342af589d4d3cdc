// SPDX-License-Identifier: Apache-2.0
#include "output_guard.hpp"

#include "ctab/fmu/export.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>

#include <hdf5.h>

#include "ctab/core/error.hpp"
#include "ctab/lookup/blob.hpp"
#include "exit_codes.hpp"
#include "isolated_read.hpp"

namespace ctab::cli {

namespace {

namespace fs = std::filesystem;

constexpr std::array<char, 8> kHdf5Signature = {'\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n'};

// What an existing regular file is, as far as `-o` is concerned.
enum class FileKind { Table, Blob, Header, Foreign };

[[noreturn]] void refuse(const std::string& output, const std::string& what) {
  throw gen::InputError(output, 0, what + "; ctab never replaces it (not even with --force)");
}

bool starts_with(const std::string& path, std::string_view prefix) {
  std::ifstream file(path, std::ios::binary);
  std::string head(prefix.size(), '\0');
  return file.read(head.data(), static_cast<std::streamsize>(head.size())) && head == prefix;
}

// The HDF5 signature at offset 0 or at a user-block offset 512, 1024, 2048, ...
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

// An HDF5 file with ctab's schema_version attribute on its root (any version, so that old tables stay replaceable);
// opened in a child process (isolated_read.hpp): the file may be anything.
bool is_ctab_table(const std::string& path) {
  if (!has_hdf5_signature(path)) return false;
  const IsolatedResult result = run_isolated([&](IsolatedChild& child) {
    child.reading(path);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const bool table = file >= 0 && H5Aexists(file, "schema_version") > 0;
    if (file >= 0) H5Fclose(file);
    return table ? 0 : 1;
  });
  return result.exit_code == 0;
}

FileKind file_kind(const std::string& path) {
  if (starts_with(path, std::string_view(lookup::kBlobMagic, sizeof lookup::kBlobMagic))) return FileKind::Blob;
  if (starts_with(path, kExportHeaderStart)) return FileKind::Header;
  if (fmu::is_exported_fmu(path)) return FileKind::Header;  // an FMU `ctab export` wrote: as replaceable
  return is_ctab_table(path) ? FileKind::Table : FileKind::Foreign;
}

void check_existing_output(const std::string& output, const fs::file_status& status,
                           const std::vector<std::string>& inputs, OutputKind kind, bool force) {
  if (fs::is_directory(status)) throw gen::InputError(output, 0, "is a directory; give a file name");
  if (fs::is_symlink(status)) refuse(output, "is a symbolic link");
  if (!fs::is_regular_file(status)) refuse(output, "is not a regular file (a FIFO, socket or device)");
  std::error_code error;
  for (const std::string& input : inputs)
    if (!input.empty() && fs::equivalent(output, input, error)) refuse(output, "is an input of this command");
  const FileKind existing = file_kind(output);
  if (existing == FileKind::Foreign)
    refuse(output, kind == OutputKind::Table ? "exists and is not a ctab table" : "exists and is not a ctab blob");
  const bool same = (existing == FileKind::Table) == (kind == OutputKind::Table);
  if (!same && !force)
    throw gen::InputError(output, 0,
                          existing == FileKind::Table
                              ? "is a ctab table, not a blob; not replaced (use --force to replace it)"
                              : "is a ctab blob or exported header, not a table; not replaced (use --force to replace it)");
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


void check_output_path(const std::string& output, const std::vector<std::string>& inputs, OutputKind kind,
                       bool force) {
  std::error_code error;
  const fs::file_status status = fs::symlink_status(output, error);
  if (fs::exists(status)) check_existing_output(output, status, inputs, kind, force);
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
