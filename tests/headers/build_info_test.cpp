// SPDX-License-Identifier: Apache-2.0
// The configured header ctab/build_info.hpp (generator/cli/build_info.hpp.in) and `ctab --version`'s text.
#include <gtest/gtest.h>

#include <string>

#include "version.hpp"

TEST(BuildInfo, VersionCompilerAndFlagsAreThoseOfThisBuild) {
  EXPECT_STREQ(CTAB_VERSION, CTAB_EXPECTED_VERSION);
  EXPECT_STRNE(CTAB_GIT_COMMIT, "");
  const std::string compiler = CTAB_COMPILER;
  EXPECT_EQ(compiler.rfind(std::string(CTAB_EXPECTED_COMPILER_ID) + " ", 0), 0u) << compiler;
  EXPECT_GT(compiler.size(), std::string(CTAB_EXPECTED_COMPILER_ID).size() + 1) << "no compiler version";
#ifdef NDEBUG
  // Release and RelWithDebInfo builds optimise; the flags must say how.
  EXPECT_NE(std::string(CTAB_BUILD_FLAGS).find("-O"), std::string::npos) << CTAB_BUILD_FLAGS;
#endif
}

TEST(BuildInfo, VersionTextNamesAllOfThem) {
  const std::string text = ctab::cli::version_text();
  EXPECT_EQ(text.rfind(std::string("ctab ") + CTAB_VERSION + " (" + CTAB_GIT_COMMIT + ")", 0), 0u) << text;
  EXPECT_NE(text.find(CTAB_COMPILER), std::string::npos) << text;
  EXPECT_NE(text.find(CTAB_BUILD_FLAGS), std::string::npos) << text;
}
