// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Safety of `-o OUTPUT` (generate, merge, batch, export): what may be replaced, checked before any work, and no
//! temporary file left behind by an interrupt.
#include <string>
#include <string_view>
#include <vector>

namespace ctab::cli {

//! How the C header `ctab export --format c-header` writes starts (lookup::blob_c_header): the mark of a header that
//! export may replace.
inline constexpr std::string_view kExportHeaderStart = "/* ctab contact table blob (";

//! What a command writes to `-o`.
enum class OutputKind {
  Table,   //!< an HDF5 contact table (generate, merge, batch)
  Export,  //!< a lookup blob or the C header `ctab export` writes
};

//! Before any work: may OUTPUT be replaced by a file of `kind`? A missing OUTPUT may; an existing one only if it is a
//! regular file (not a symbolic link, device, FIFO, socket or directory), none of `inputs` (fs::equivalent), and a
//! ctab file: of the same kind (replaced), or of the other kind with `force`. Anything else is refused, --force or not
//! (InputError, exit 2). Fails (IoError, exit 3) when OUTPUT's directory is missing or no file can be created in it
//! (probed by creating and removing the temporary).
void check_output_path(const std::string& output, const std::vector<std::string>& inputs, OutputKind kind,
                       bool force);

//! The temporary file of tables::write_table for OUTPUT in this process: OUTPUT + ".tmp-" + pid.
[[nodiscard]] std::string temporary_table_path(const std::string& output);

//! While alive, SIGINT and SIGTERM remove the temporary table file and exit with 128 + signal (an async-signal-safe
//! handler: a path prepared in a static buffer, unlink, _exit). SIGKILL cannot be caught and may leave the file;
//! readers ignore stale `.tmp-*` files and the next successful run replaces OUTPUT.
class InterruptCleanup {
 public:
  explicit InterruptCleanup(const std::string& output);
  ~InterruptCleanup();
  InterruptCleanup(const InterruptCleanup&) = delete;
  InterruptCleanup& operator=(const InterruptCleanup&) = delete;
};

}  // namespace ctab::cli
