// SPDX-License-Identifier: Apache-2.0
#pragma once
// Version, commit, compiler and flags of this build (ctab/build_info.hpp, configured by CMake); "unknown" when
// built otherwise.
#include <string>

#if __has_include("ctab/build_info.hpp")
#include "ctab/build_info.hpp"
#endif
#ifndef CTAB_VERSION
#define CTAB_VERSION "unknown"
#endif
#ifndef CTAB_GIT_COMMIT
#define CTAB_GIT_COMMIT "unknown"
#endif
#ifndef CTAB_COMPILER
#define CTAB_COMPILER "unknown"
#endif
#ifndef CTAB_BUILD_FLAGS
#define CTAB_BUILD_FLAGS "unknown"
#endif

namespace ctab::cli {

//! What `ctab --version` prints: "ctab 0.2.0 (commit)" and a line with the compiler and its flags.
inline std::string version_text() {
  return std::string("ctab ") + CTAB_VERSION + " (" + CTAB_GIT_COMMIT + ")\ncompiler: " + CTAB_COMPILER +
         "\nflags: " + CTAB_BUILD_FLAGS;
}

}  // namespace ctab::cli
