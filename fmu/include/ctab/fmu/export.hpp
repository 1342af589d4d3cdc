// SPDX-License-Identifier: Apache-2.0
#pragma once
//! `ctab export --format fmu`: a table blob packed as an FMI 3.0 Co-Simulation FMU for x86-64 Linux around the
//! prebuilt wrapper shared object installed with ctab (docs/fmu.md).
#include <string>
#include <vector>

namespace ctab::fmu {

//! Where the wrapper was looked for, and whether it is there.
struct WrapperLocation {
  std::string path;
  bool found = false;
};

//! The wrapper shared object: $CTAB_FMU_WRAPPER where set, else the one installed beside this executable
//! (<bindir>/../lib/ctab/fmu/ctab_contact_table.so, the same layout in the build tree).
[[nodiscard]] WrapperLocation find_wrapper();

//! True when `path` starts like an FMU this exporter writes (its first entry modelDescription.xml with the fixed
//! time stamp), so that `ctab export` may replace it.
[[nodiscard]] bool is_exported_fmu(const std::string& path);

struct FmuSource {
  std::string generation_tool;  //!< "ctab 0.2.0"
  std::string table_name;       //!< the exported file's name, for the model's description
};

//! The FMU archive: modelDescription.xml for the blob's table, binaries/x86_64-linux/<id>.so (read from
//! `wrapper_path`), resources/table.ctab (the blob). Throws gen::Error where the blob does not load or the
//! wrapper cannot be read.
[[nodiscard]] std::vector<unsigned char> build_fmu(const std::vector<unsigned char>& blob,
                                                   const std::string& wrapper_path, const FmuSource& source);

}  // namespace ctab::fmu
