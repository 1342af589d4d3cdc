// SPDX-License-Identifier: Apache-2.0
// `ctab export FILE --format blob|c-header|fmu -o OUT [--single-precision] [--name IDENT]`: a table (HDF5 or blob)
// as a lookup blob, as a C header of constant arrays (targets without HDF5 or a file system), or as an FMI 3.0
// Co-Simulation FMU (docs/fmu.md).
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <filesystem>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ctab/core/error.hpp"
#include "ctab/fmu/export.hpp"
#include "ctab/lookup/blob.hpp"
#include "ctab/lookup/hdf5_table.hpp"
#include "ctab/lookup/table.hpp"
#include "exit_codes.hpp"
#include "isolated_read.hpp"
#include "load_errors.hpp"
#include "output_guard.hpp"
#include "version.hpp"

namespace ctab::cli {

namespace {

struct ExportOptions {
  std::string input, output, format = "blob", name = "ctab_table_blob";
  std::string wrapper;  // --format fmu: the wrapper shared object found beside this executable
  bool single_precision = false, force = false;
};

//! Writes `bytes` to `path` through a temporary file renamed on success (no partial output under `path`); a failure
//! (a full disk) is an IoError and leaves `path` as it was.
void write_atomically(const std::string& path, const void* bytes, std::size_t size) {
  const std::string temporary = temporary_table_path(path);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw IoError(path + ": cannot open for writing: " + std::strerror(errno));
  int error = 0;
  for (std::size_t done = 0; done < size && error == 0;) {
    const ssize_t n = ::write(fd, static_cast<const char*>(bytes) + done, size - done);
    if (n > 0) done += static_cast<std::size_t>(n);
    else if (n == 0) error = EIO;
    else if (errno != EINTR) error = errno;
  }
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error == 0 && std::rename(temporary.c_str(), path.c_str()) != 0) error = errno;
  if (error != 0) {
    std::remove(temporary.c_str());
    throw IoError(path + ": cannot write: " + std::strerror(error));
  }
}

// In a child process (isolated_read.hpp): the input may be an HDF5 table from anywhere.
int export_table(const ExportOptions& o, IsolatedChild& child) {
  lookup::TableData data;
  bool single = false;
  child.reading(o.input);
  throw_if_failed(lookup::read_any(o.input, data, single));
  lookup::Table check;  // the same checks a target's load makes
  lookup::LoadResult result = check.load(data, {});
  if (!result.ok()) result.message = o.input + ": " + result.message;
  throw_if_failed(result);
  child.trusted_from_here();
  std::vector<unsigned char> blob;  // refused where single precision cannot hold a value
  lookup::LoadResult written = lookup::write_blob(data, o.single_precision || single, blob);
  if (!written.ok()) written.message = o.input + ": " + written.message;
  throw_if_failed(written);
  const InterruptCleanup cleanup(o.output);
  if (o.format == "blob") {
    write_atomically(o.output, blob.data(), blob.size());
  } else if (o.format == "fmu") {
    const fmu::FmuSource source{std::string("ctab ") + CTAB_VERSION,
                                std::filesystem::path(o.input).filename().string()};
    const std::vector<unsigned char> archive = fmu::build_fmu(blob, o.wrapper, source);
    write_atomically(o.output, archive.data(), archive.size());
    std::printf("%s: FMI 3.0 Co-Simulation FMU, %zu bytes\n", o.output.c_str(), archive.size());
  } else {
    const std::string header = lookup::blob_c_header(blob, o.name);
    write_atomically(o.output, header.data(), header.size());
  }
  std::printf("%s: %s, %zu bytes of blob (%s precision), %zu x %zu cases, %zu slots\n", o.output.c_str(),
              o.format.c_str(), blob.size(), o.single_precision || single ? "single" : "double", data.n_dy(),
              data.n_second(), data.n_slots);
  return 0;
}

int run_export(ExportOptions o) {
  check_output_path(o.output, {o.input}, OutputKind::Export, o.force);
  if (o.format == "fmu") {
    const fmu::WrapperLocation wrapper = fmu::find_wrapper();
    if (!wrapper.found)
      throw IoError("ctab export --format fmu: the FMU wrapper " + wrapper.path +
                    " is missing (it is built and installed with ctab in <prefix>/lib/ctab/fmu; set CTAB_FMU_WRAPPER "
                    "to its path)");
    o.wrapper = wrapper.path;
  }
  return run_isolated([&](IsolatedChild& child) { return export_table(o, child); }).exit_code;
}

}  // namespace

Command add_export_command(CLI::App& parent) {
  auto o = std::make_shared<ExportOptions>();
  CLI::App* app =
      parent.add_subcommand("export", "Write a table as a lookup blob, a C header or an FMI 3.0 FMU");
  app->add_option("file", o->input, "table (.h5 or blob)")->required();
  app->add_option("--format", o->format, "blob (default), c-header or fmu (FMI 3.0 Co-Simulation, x86-64 Linux)")
      ->check(CLI::IsMember({"blob", "c-header", "fmu"}));
  app->add_option("-o,--output", o->output,
                  "output file; replaced only on success, and only if it is a blob, header or FMU export wrote")
      ->required();
  app->add_flag("--force", o->force, "replace OUTPUT even if it is a ctab table (never anything else)");
  app->add_flag("--single-precision", o->single_precision, "store values as float (half the size)");
  app->add_option("--name", o->name, "C identifier of the array (c-header; default ctab_table_blob)")
      ->check([](const std::string& s) {
        bool ok = !s.empty() && !(s[0] >= '0' && s[0] <= '9');
        for (const char c : s)
          ok = ok && (c == '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'));
        return ok ? std::string() : std::string("not a C identifier: ") + s;
      });
  return {app, [o] { return run_export(*o); }};
}

}  // namespace ctab::cli
