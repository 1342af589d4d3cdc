// SPDX-License-Identifier: Apache-2.0
#pragma once
// Shared helpers for the tests: reference data paths (CONTACT's result files are read by ctab::gen::read_csv,
// ctab/validation/reference_csv.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace ctab::test {

//! True when ../shared (CTAB_SHARED_DIR: reference data, profiles) is there.
inline bool shared_dir_present() { return std::filesystem::is_directory(CTAB_SHARED_DIR); }

//! Skips the current test (or, in SetUpTestSuite, the whole suite) when ../shared is absent: a clone without
//! the reference data still runs everything else. Such test executables carry the CTest label `shared`.
#define CTAB_REQUIRE_SHARED()                                                                      \
  do {                                                                                             \
    if (!::ctab::test::shared_dir_present()) GTEST_SKIP() << "no shared data at " CTAB_SHARED_DIR; \
  } while (false)

//! Path of a file under ../shared (reference data; tests only).
inline std::string shared_path(const std::string& relative) { return std::string(CTAB_SHARED_DIR) + "/" + relative; }
inline std::string source_path(const std::string& relative) { return std::string(CTAB_SOURCE_DIR) + "/" + relative; }

}  // namespace ctab::test
