#pragma once
// The Manchester benchmark profiles (../shared/profiles: S1002 wheel, UIC60 rail already inclined 1:40, so
// inclination 0) placed on the default track: the set-up of CONTACT's wheel-rail reference results.
#include <gtest/gtest.h>

#include "ctab/io/profile_io.hpp"
#include "ctab/wheelrail/wheelrail_geometry.hpp"
#include "test_support.hpp"

namespace ctab::test {

struct ManchesterSide {
  gen::ProfileTable wheel, rail;
  gen::SideGeometry side;  // refers to wheel and rail: the object is never copied or moved

  ManchesterSide()
      : wheel(load("profiles/MBench_S1002_v3.prw", gen::ProfileRole::Wheel)),
        rail(load("profiles/MBench_UIC60_v3.prr", gen::ProfileRole::Rail)), side(wheel, rail, gen::TrackSetup{}) {}
  ManchesterSide(const ManchesterSide&) = delete;
  ManchesterSide& operator=(const ManchesterSide&) = delete;

 private:
  static gen::ProfileTable load(const char* file, gen::ProfileRole role) {
    gen::ProfileReadOptions options;
    options.inclination = 0.0;
    return gen::load_profile(shared_path(file), role, options);
  }
};

//! A parameterised suite on the Manchester side, loaded once per suite (skipped without ../shared).
template <class Param>
class ManchesterSuite : public ::testing::TestWithParam<Param> {
 protected:
  static void SetUpTestSuite() {
    CTAB_REQUIRE_SHARED();
    manchester_ = new ManchesterSide;
    side_ = &manchester_->side;
  }
  static void TearDownTestSuite() {
    delete manchester_;
    manchester_ = nullptr;
    side_ = nullptr;
  }
  inline static ManchesterSide* manchester_ = nullptr;
  inline static const gen::SideGeometry* side_ = nullptr;
};

}  // namespace ctab::test
