// SPDX-License-Identifier: Apache-2.0
// The FMU archive of a table (export.hpp): the wrapper found beside the executable, the description, the blob.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

#include "ctab/core/error.hpp"
#include "ctab/fmu/export.hpp"
#include "ctab/fmu/token.hpp"
#include "ctab/fmu/variables.hpp"
#include "model_description.hpp"
#include "zip_writer.hpp"

#ifndef CTAB_FMU_WRAPPER_RELATIVE_DIR
#error "CTAB_FMU_WRAPPER_RELATIVE_DIR: the wrapper's directory relative to the executable's (fmu/CMakeLists.txt)"
#endif

namespace ctab::fmu {

namespace {

std::vector<unsigned char> read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw gen::Error(path + ": cannot read the FMU wrapper");
  if (bytes.empty()) throw gen::Error(path + ": the FMU wrapper is empty or unreadable");
  return bytes;
}

}  // namespace

WrapperLocation find_wrapper() {
  namespace fs = std::filesystem;
  WrapperLocation where;
  if (const char* given = std::getenv("CTAB_FMU_WRAPPER"); given != nullptr && given[0] != '\0') {
    where.path = given;
  } else {
    std::error_code error;
    const fs::path exe = fs::read_symlink("/proc/self/exe", error);
    const fs::path dir = error ? fs::path(".") : exe.parent_path();
    where.path = (dir / CTAB_FMU_WRAPPER_RELATIVE_DIR / (std::string(kModelIdentifier) + ".so")).lexically_normal();
  }
  std::error_code error;
  where.found = fs::is_regular_file(where.path, error);
  return where;
}

bool is_exported_fmu(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string expected = ZipWriter::first_header_start("modelDescription.xml");
  std::string head(expected.size(), '\0');
  return in.read(head.data(), static_cast<std::streamsize>(head.size())) && head.compare(0, 14, expected, 0, 14) == 0 &&
         head.compare(26, std::string::npos, expected, 26, std::string::npos) == 0;
}

std::vector<unsigned char> build_fmu(const std::vector<unsigned char>& blob, const std::string& wrapper_path,
                                     const FmuSource& source) {
  ctab_table* raw = nullptr;
  const ctab_status status = ctab_table_open_memory(blob.data(), blob.size(), nullptr, &raw);
  const std::unique_ptr<ctab_table, void (*)(ctab_table*)> table(raw, ctab_table_close);
  if (status != CTAB_OK) throw gen::Error(std::string("FMU: the table blob does not load: ") + ctab_status_message(status));
  char token[kTokenSize];
  instantiation_token(blob.data(), blob.size(), token);
  const std::string xml = model_description(table.get(), {token, source.generation_tool, source.table_name});
  const std::vector<unsigned char> wrapper = read_all(wrapper_path);
  ZipWriter zip;
  zip.add("modelDescription.xml", xml.data(), xml.size());
  zip.add(std::string("binaries/x86_64-linux/") + kModelIdentifier + ".so", wrapper.data(), wrapper.size(), true);
  zip.add(std::string("resources/") + kTableResource, blob.data(), blob.size());
  return zip.finish();
}

}  // namespace ctab::fmu
