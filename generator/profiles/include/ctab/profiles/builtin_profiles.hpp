// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Built-in standard profiles generated from their definitions (no data files needed):
//! - S1002 wheel (EN 13715 / UIC 510-2), sections A-H with the coefficients of the function by H. Netter (DLR),
//!   as published in facts/profiles.md 1.2: S [mm] lateral from the tape circle (S < 0 towards the flange,
//!   flange back at S = -70), F(S) [mm] radius increase. Tabulated on -69.6 <= S <= 60 mm (the flange back is
//!   vertical at S = -70).
//! - 60E1 (UIC60) rail head (EN 13674-1): crown R300 to |y| = 10.228, R80 to 26.0265, R13 gauge corner tangent to
//!   a 1:20 flank, flank to 37.5 mm below the top; symmetric. Optionally inclined (1:20, 1:30, 1:40) towards the
//!   track centre and re-origined at the highest point of the inclined head (the Manchester convention).
#include <memory>
#include <string>

#include "ctab/profiles/profile.hpp"

namespace ctab::gen {

//! F(S) [mm] of S1002 at S [mm] with its first and second derivatives (exact, per section).
struct S1002Value {
  double f, df, d2f;
  char section;  //!< 'A'..'H'
};
[[nodiscard]] S1002Value s1002_mm(double s_mm) noexcept;

//! The S1002 wheel as a curve in SI (y = S, z = F).
[[nodiscard]] std::shared_ptr<const ProfileCurve> s1002_curve();
//! The 60E1 head, not inclined, origin at the crown top, SI.
[[nodiscard]] std::shared_ptr<const ProfileCurve> uic60_curve();
//! The 60E1 head inclined by atan(inclination) towards the track centre (gauge side down), origin at the
//! highest point of the inclined head. inclination 0 leaves it upright.
[[nodiscard]] std::shared_ptr<const ProfileCurve> uic60_inclined_curve(double inclination);

//! The built-in profile a name means, in any letter case: "S1002" the wheel, "UIC60" or "60E1" the rail; None: a
//! profile file.
enum class BuiltinProfile { None, S1002, Uic60 };
[[nodiscard]] BuiltinProfile builtin_profile(const std::string& name);
//! Whether `name` means a built-in profile (builtin_profile is not None).
[[nodiscard]] bool is_builtin_profile(const std::string& name);

//! Default lateral step of profile tables [m].
inline constexpr double kProfileTableStep_m = 0.01e-3;

}  // namespace ctab::gen
