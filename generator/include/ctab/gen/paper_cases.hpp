#pragma once
//! The theoretical cases of the MIM-1D paper (section 3.1), embedded so that they run without data files.
//! Both bodies steel (E = 208 GPa, nu = 0.3), approach 1 mm.
#include "ctab/gen/gap_profile.hpp"

namespace ctab::gen::paper {

inline constexpr double kApproach_m = 1.0e-3;        //!< prescribed approach of both cases [m]
inline constexpr double kSphereRadius_m = 0.040;     //!< Hertzian case: sphere on a flat [m]
inline constexpr double kRollingRadius_m = 0.400;    //!< non-Hertzian case: rolling radius [m]
inline constexpr double kRadiusNegative_m = 0.040;   //!< non-Hertzian case: lateral radius for y < 0 [m]
inline constexpr double kRadiusPositive_m = 0.500;   //!< non-Hertzian case: lateral radius for y >= 0 [m]

//! CONTACT (full BEM, 0.2 mm elements) on the non-Hertzian case at 1 mm approach (CONTACT rev. 2707 run for
//! this project; values as in the paper: "2645 kN").
inline constexpr double kNonHertzContactForce_N = 2645.5373e3;
inline constexpr double kNonHertzContactArea_m2 = 915.6e-6;
inline constexpr double kNonHertzContactMaxPressure_Pa = 6061.7e6;

//! Sphere R = 40 mm on a flat, sampled every 0.05 mm on |y| <= 12 mm (the contact half-width is 6.3 mm).
[[nodiscard]] inline GapProfile hertz_sphere_gap() { return sphere_on_flat_gap(kSphereRadius_m, 0.012, 0.05e-3); }
//! Two-radius body of revolution on a flat, sampled every 0.05 mm on -12 <= y <= 35 mm.
[[nodiscard]] inline GapProfile nonhertz_gap() {
  return two_radius_gap(kRollingRadius_m, kRadiusNegative_m, kRadiusPositive_m, -0.012, 0.035, 0.05e-3);
}

}  // namespace ctab::gen::paper
