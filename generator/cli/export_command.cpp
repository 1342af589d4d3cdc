// `ctab export FILE --format blob|c-header -o OUT [--single-precision] [--name IDENT]`: a table (HDF5 or blob) as
// a lookup blob or as a C header of constant arrays, for targets without HDF5 or a file system.
#include <cstdio>
#include <memory>
#include <string>

#include "commands.hpp"
#include "ctab/core/error.hpp"
#include "ctab/lookup/blob.hpp"
#include "ctab/lookup/hdf5_table.hpp"
#include "ctab/lookup/table.hpp"

namespace ctab::cli {

namespace {

struct ExportOptions {
  std::string input, output, format = "blob", name = "ctab_table_blob";
  bool single_precision = false;
};

//! Writes `bytes` to `path` through a temporary file renamed on success (no partial output under `path`).
void write_atomically(const std::string& path, const void* bytes, std::size_t size) {
  const std::string temporary = path + ".tmp-export";
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (file == nullptr) throw gen::Error(path + ": cannot open for writing");
  const bool written = std::fwrite(bytes, 1, size, file) == size;
  const bool closed = std::fclose(file) == 0;
  if (!written || !closed || std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw gen::Error(path + ": write failed");
  }
}

int run_export(const ExportOptions& o) {
  lookup::TableData data;
  bool single = false;
  lookup::LoadResult result = lookup::read_any(o.input, data, single);
  if (!result.ok()) throw gen::Error(result.message);
  lookup::Table check;  // the same checks a target's load makes
  result = check.load(data, {});
  if (!result.ok()) throw gen::Error(o.input + ": " + result.message);
  const std::vector<unsigned char> blob = lookup::write_blob(data, o.single_precision || single);
  if (o.format == "blob") {
    write_atomically(o.output, blob.data(), blob.size());
  } else {
    const std::string header = lookup::blob_c_header(blob, o.name);
    write_atomically(o.output, header.data(), header.size());
  }
  std::printf("%s: %s, %zu bytes of blob (%s precision), %zu x %zu cases, %zu slots\n", o.output.c_str(),
              o.format.c_str(), blob.size(), o.single_precision || single ? "single" : "double", data.n_dy(),
              data.n_second(), data.n_slots);
  return 0;
}

}  // namespace

Command add_export_command(CLI::App& parent) {
  auto o = std::make_shared<ExportOptions>();
  CLI::App* app =
      parent.add_subcommand("export", "Write a table as a lookup blob or a C header (targets without HDF5)");
  app->add_option("file", o->input, "table (.h5 or blob)")->required();
  app->add_option("--format", o->format, "blob (default) or c-header")->check(CLI::IsMember({"blob", "c-header"}));
  app->add_option("-o,--output", o->output, "output file")->required();
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
