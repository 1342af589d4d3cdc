// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The CLI's trust boundary for HDF5 inputs (docs/security.md): libhdf5 itself may crash or hang on a corrupted
//! file, so every command that reads an HDF5 file the user gives runs that part in a forked child process with a
//! wall-time and an address-space limit. A crash or a timeout of the child is exit 2, "corrupt table: PATH: ...".
#include <cstdint>
#include <functional>
#include <string>

namespace ctab::cli {

//! The child's limits while it reads untrusted input.
struct ReadLimits {
  unsigned seconds = 60;                    //!< wall time (CTAB_READ_TIME_LIMIT_S)
  std::uint64_t memory_bytes = 8ull << 30;  //!< address space beyond the parent's (CTAB_READ_MEMORY_LIMIT_GIB)
};

//! The defaults above, or the environment's CTAB_READ_TIME_LIMIT_S (1..86400) and CTAB_READ_MEMORY_LIMIT_GIB
//! (1..65536); a value out of range or unparsable is an InputError.
[[nodiscard]] ReadLimits read_limits();

//! What the body of run_isolated uses inside the child.
class IsolatedChild {
 public:
  explicit IsolatedChild(int reply_fd) noexcept : reply_fd_(reply_fd) {}
  //! Names the file whose reading starts (a crash or timeout from here on names it).
  void reading(const std::string& path);
  //! The untrusted input is parsed and checked: lifts the time and memory limits for the rest of the body.
  void trusted_from_here();
  //! One line of text for the parent (IsolatedResult::reply); no newlines.
  void reply(const std::string& text);

 private:
  int reply_fd_;
};

struct IsolatedResult {
  int exit_code = 0;  //!< the body's exit code (error_exit.hpp maps its exceptions)
  std::string reply;  //!< what the body passed to IsolatedChild::reply
};

//! Runs `body` in a forked child under read_limits() and waits for it. Standard output and error are shared (the
//! parent's are flushed first). A child ended by a signal or by the time limit throws gen::Error "corrupt table:
//! PATH: ..." naming the file given to IsolatedChild::reading last; after trusted_from_here, a signal is an internal
//! error (std::runtime_error).
[[nodiscard]] IsolatedResult run_isolated(const std::function<int(IsolatedChild&)>& body);

}  // namespace ctab::cli
