// SPDX-License-Identifier: Apache-2.0
#pragma once
//! How a command's exceptions become exit codes (exit_codes.hpp) and messages on stderr: shared by the main process
//! and the child processes that read HDF5 inputs (isolated_read.hpp).
#include <functional>

namespace ctab::cli {

//! Runs `body`; an exception stops it and becomes a message on stderr and its exit code: IoError, filesystem errors
//! and out of memory 3, gen::Error (ParseError, InputError) 2, anything else 1 (an internal error).
[[nodiscard]] int run_reporting_errors(const std::function<int()>& body);

//! Flushes standard output; a full disk or another write error there turns `code` into 3 (a usage error keeps 2)
//! with a message on stderr. A closed pipe (the reader stopped, as `head` does) keeps `code`, quietly.
[[nodiscard]] int finish_standard_output(int code);

}  // namespace ctab::cli
