// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Exit codes of the ctab executable (docs/cli.md "Exit codes") and the error that maps to the I/O code.
#include "ctab/core/error.hpp"

namespace ctab::cli {

enum ExitCode : int {
  kExitSuccess = 0,
  kExitInternal = 1,    //!< an unexpected internal error (a bug)
  kExitUsage = 2,       //!< bad usage or input: options, config, profile, gap or table files, a corrupt table
  kExitIo = 3,          //!< I/O or resource failure: the output cannot be written, standard output fails, no memory
  kExitCaseFailed = 4,  //!< a solve, or some cases of a written table, did not succeed (statuses say why)
};

//! Output cannot be written, or memory runs out (exit code 3).
class IoError : public gen::Error {
 public:
  using gen::Error::Error;
};

}  // namespace ctab::cli
