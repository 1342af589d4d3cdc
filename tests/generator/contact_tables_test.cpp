// SPDX-License-Identifier: Apache-2.0
// The strip-kernel and Hertz-coefficient tables are compiled in (generated at build time by contact_tables_gen);
// they must be bit for bit what the run-time computation gives.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "ctab/contact/hertz.hpp"
#include "ctab/contact/strip_kernel.hpp"

namespace {

using namespace ctab::gen;

TEST(ContactTables, StripKernelTableEqualsTheRunTimeComputation) {
  const std::vector<StripKernel::Interval> runtime = StripKernel::build_intervals();
  ASSERT_EQ(runtime.size(), StripKernel::kIntervalCount);
  const StripKernel::Interval* compiled = StripKernel::instance().intervals();
  std::size_t differing = 0;
  for (std::size_t i = 0; i < runtime.size(); ++i)
    if (std::memcmp(&runtime[i], &compiled[i], sizeof(StripKernel::Interval)) != 0) ++differing;
  EXPECT_EQ(differing, 0u);
}

TEST(ContactTables, HertzTableEqualsTheRunTimeComputation) {
  const std::vector<HertzTableNode> runtime = build_hertz_table();
  ASSERT_EQ(runtime.size(), kHertzTableNodes);
  const HertzTableNode* compiled = hertz_table();
  std::size_t differing = 0;
  for (std::size_t k = 0; k < runtime.size(); ++k)
    if (runtime[k].value != compiled[k].value || runtime[k].slope != compiled[k].slope) ++differing;
  EXPECT_EQ(differing, 0u);
  // And the lookup uses it: at a node the tabulated coefficients are the node's values.
  HertzCoefficients c;
  ASSERT_TRUE(hertz_coefficients_tabulated(1.0, 1.0, c));  // x = ln(B/A) = 0, node 768
  EXPECT_EQ(c.m, compiled[768].value[0]);
  EXPECT_EQ(c.n, compiled[768].value[1]);
  EXPECT_EQ(c.r, compiled[768].value[2]);
}

}  // namespace
