// SPDX-License-Identifier: Apache-2.0
#pragma once
// The Manchester benchmark profiles (../shared/profiles: S1002 wheel, UIC60 rail already inclined 1:40, so
// inclination 0) placed on the default track: the set-up of CONTACT's wheel-rail reference results.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "ctab/io/profile_io.hpp"
#include "ctab/validation/reference_csv.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"
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

//! CONTACT's planar rows lie on one line in the rail's y-z plane, through the rail point at the patch's reference y
//! and inclined at its reference angle; row i sits at s_i along it and its strip file gives y_rail_mm = ycp + s_i
//! cos(delta) (reference README). ctab's y_rail_m of a planar strip is instead the rail point below the strip, which
//! on a curved rail leaves that line by about s^2 sin(delta) / (2R): 0.03 mm at s = 1 mm on the 13 mm gauge corner at
//! 69 deg, half a row of a flank patch. Planar comparisons therefore project ctab's rail points onto CONTACT's line.
struct ContactRowLine {
  double y_m = 0.0, z_m = 0.0, angle_rad = 0.0;  // the reference rail point and angle (rail frame, z down)
  [[nodiscard]] double row_y_mm(double rail_y_m, const gen::ProfileTable& rail) const {
    const double s = (rail_y_m - y_m) * std::cos(angle_rad) + (rail.z_at(rail_y_m) - z_m) * std::sin(angle_rad);
    return (y_m + s * std::cos(angle_rad)) * 1e3;
  }
};

//! The row line of CONTACT's single patch at dy [mm] in a planar summary CSV (columns dy_mm, ycp_rail_mm,
//! contact_angle_rad).
inline ContactRowLine contact_row_line(const std::string& summary_file, double dy_mm, const gen::ProfileTable& rail) {
  const auto table = gen::read_csv(summary_file);
  const auto dys = table.numbers("dy_mm");
  const auto row = static_cast<std::size_t>(std::find(dys.begin(), dys.end(), dy_mm) - dys.begin());
  EXPECT_EQ(std::count(dys.begin(), dys.end(), dy_mm), 1) << summary_file << ": one patch at dy " << dy_mm << " mm";
  if (row >= dys.size()) return {};
  const double y_m = table.numbers("ycp_rail_mm")[row] * 1e-3;
  return {y_m, rail.z_at(y_m), table.numbers("contact_angle_rad")[row]};
}

//! p0 along the patch against a CONTACT strip file (columns y_rail_mm, p0_i_MPa), RMS over CONTACT's largest p0.
//! ctab's p0 at a row: linear between the centres of a patch's strips, and over the outer half of its edge strips
//! that strip's p0 (MIM-1D's strip carries its pressure across its whole width, as its area and force count it);
//! 0 outside every patch. Without the edge halves a row 10 um beyond the edge strip's centre read 0 (the flank at
//! dy 7.5 mm, where both models end their patch on the same row).
//! With `line` and `rail` (planar), ctab's strips are placed on CONTACT's row line (ContactRowLine); without, at
//! their y_rail_m (conformal: the surface points, as CONTACT's conformal rows).
inline double p0_profile_rms(const gen::WheelContact& contact, const std::string& strip_file,
                             const ContactRowLine* line = nullptr, const gen::ProfileTable* rail = nullptr) {
  const auto table = gen::read_csv(strip_file);
  const auto y = table.numbers("y_rail_mm"), p = table.numbers("p0_i_MPa");
  std::vector<double> ours(y.size(), 0.0);  // ctab's p0 at each row [MPa]
  for (const auto& patch : contact.patches) {
    std::vector<std::pair<double, double>> strips;  // (y_rail [mm], p0 [MPa])
    for (const auto& s : patch.strips)
      strips.emplace_back(line && rail ? line->row_y_mm(s.y_rail_m, *rail) : s.y_rail_m * 1e3, s.p0_Pa * 1e-6);
    if (strips.size() < 2) continue;
    std::sort(strips.begin(), strips.end());
    const double low_edge = strips[0].first - 0.5 * (strips[1].first - strips[0].first);
    const std::size_t n = strips.size();
    const double high_edge = strips[n - 1].first + 0.5 * (strips[n - 1].first - strips[n - 2].first);
    for (std::size_t i = 0; i < y.size(); ++i) {
      if (y[i] < low_edge || y[i] > high_edge) continue;
      if (y[i] <= strips.front().first) ours[i] = strips.front().second;
      else if (y[i] >= strips.back().first) ours[i] = strips.back().second;
      else
        for (std::size_t k = 1; k < n; ++k)
          if (y[i] <= strips[k].first) {
            const double t = (y[i] - strips[k - 1].first) / (strips[k].first - strips[k - 1].first);
            ours[i] = (1 - t) * strips[k - 1].second + t * strips[k].second;
            break;
          }
    }
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) sum += (ours[i] - p[i]) * (ours[i] - p[i]);
  return std::sqrt(sum / static_cast<double>(y.size())) / *std::max_element(p.begin(), p.end());
}

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
