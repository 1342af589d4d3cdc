#pragma once
//! Safety of `ctab generate -o OUTPUT`: what may be replaced, checked before the sweep, and no temporary file left
//! behind by an interrupt.
#include <string>

namespace ctab::cli {

//! Before any work: refuses (InputError, exit 2) an OUTPUT that is a symbolic link, a FIFO, a device, a directory,
//! the config file itself, or a regular file that is not an HDF5 file, unless `force`. (Any HDF5 file counts as a
//! ctab table here, whatever its schema version, so that old tables stay replaceable.) Fails (IoError, exit 3) when
//! OUTPUT's directory is missing or no file can be created in it (probed by creating and removing the temporary).
void check_output_path(const std::string& output, const std::string& config_path, bool force);

//! True if the file starts with the HDF5 signature (at offset 0 or at a user-block offset 512, 1024, 2048, ...).
[[nodiscard]] bool has_hdf5_signature(const std::string& path);

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
