// SPDX-License-Identifier: Apache-2.0
// The tangential ladder against CONTACT's steady-rolling creep forces (tests may read ../shared): ctab's creep call
// fed ctab's own normal solution of the same case (ctab/validation/creep_validation.hpp). Bounds: the issue's
// measured worst plus a margin (the targets, 0.03 mu N tread, 0.05 flange, 0.05 combined, Mz 15 %, are not
// all met: docs/creep.md lists both; a change of method or discretisation must not make these worse).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "ctab/lookup/ctab_lookup.h"
#include "ctab/validation/creep_validation.hpp"

namespace ctab::gen {
namespace {

const std::string kShared = CTAB_SHARED_DIR;

class CreepContact : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const auto cases = read_creep_reference(kShared + "/reference/contact/wheelrail/tangential/creep_zfix.csv");
    rows_ = new std::vector<CreepRow>(run_creep_validation(cases, kShared + "/profiles"));
    std::printf("%s", creep_summary(*rows_).c_str());
  }
  static void TearDownTestSuite() { delete rows_; }
  static std::vector<CreepRow>* rows_;
};
std::vector<CreepRow>* CreepContact::rows_ = nullptr;

std::string name(const CreepRow& r) {
  char text[120];
  std::snprintf(text, sizeof text, "%s dy %.1f mm %s method %d", r.reference.conformal ? "conformal" : "planar",
                r.reference.dy_m * 1e3, r.reference.name.c_str(), r.method);
  return text;
}

// Planar cases, the strip method: force errors and the spin moment.
TEST_F(CreepContact, PlanarStripsWithinBounds) {
  for (const CreepRow& r : *rows_) {
    if (r.reference.conformal || r.method != CTAB_CREEP_STRIPS) continue;
    const std::string& c = r.reference.name;
    // Measured worst (planar, 32 strip samples, 16 cells): tread xi 0.076, eta 0.039, phi 0.068, comb 0.058;
    // flange xi 0.027, eta 0.028, phi 0.078, comb 0.007.
    const double bound = c.rfind("xi", 0) == 0 ? 0.085 : c.rfind("eta", 0) == 0 ? 0.045 : c == "comb" ? 0.065 : 0.09;
    EXPECT_LT(r.error_muN, bound) << name(r) << ": error " << r.error_muN << " mu N";
    if (c.rfind("phi", 0) == 0) {
      EXPECT_LT(r.mz_error, 0.2) << name(r) << ": Mz error " << r.mz_error;
    }
  }
}

// Planar cases, the strips on Carter's curve (the CLI's default; the targets: 0.03 mu N tread, 0.05 flange
// and combined, Mz 15 %): force errors and the spin moment, per region.
TEST_F(CreepContact, PlanarCarterWithinBounds) {
  for (const CreepRow& r : *rows_) {
    if (r.reference.conformal || r.method != CTAB_CREEP_STRIPS_CARTER) continue;
    const std::string& c = r.reference.name;
    const bool tread = r.region() == "tread", xi = c.rfind("xi", 0) == 0, eta = c.rfind("eta", 0) == 0;
    // Measured worst (planar, 32 strip samples, 16 cells): tread xi 0.031, eta 0.021, phi 0.068, comb 0.010,
    // Mz 13.5 %; flange xi 0.021, eta 0.0065, phi 0.078, comb 0.013, Mz 18.8 %.
    const double bound = tread ? (xi ? 0.035 : eta ? 0.025 : c == "comb" ? 0.015 : 0.075)
                               : (xi ? 0.025 : eta ? 0.01 : c == "comb" ? 0.018 : 0.085);
    EXPECT_LT(r.error_muN, bound) << name(r) << ": error " << r.error_muN << " mu N";
    if (c.rfind("phi", 0) == 0) {
      EXPECT_LT(r.mz_error, tread ? 0.145 : 0.2) << name(r) << ": Mz error " << r.mz_error;
    }
  }
}

// Every method and surface: finite, bounded by mu N, and the small-creepage sign right.
TEST_F(CreepContact, EveryCaseIsPhysical) {
  for (const CreepRow& r : *rows_) {
    if (r.method == CTAB_CREEP_LINEAR) continue;
    const double muN = 0.3 * r.reference.normal_force_N;
    EXPECT_LT(std::hypot(r.fx_N, r.fs_N), 1.01 * muN) << name(r);
    if (r.reference.name.rfind("xi", 0) == 0) {
      EXPECT_LT(r.fx_N, 0.0) << name(r);
    }
    EXPECT_LT(r.time_s, 1e-3) << name(r);
  }
}

}  // namespace
}  // namespace ctab::gen
