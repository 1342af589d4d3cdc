// SPDX-License-Identifier: Apache-2.0
#pragma once
// The FASTSIM march shared by the strip and ellipse methods: strips of a patch in structure-of-arrays form,
// marched from the leading edge (x = +a) to the trailing edge, all strips at once (the inner loop vectorises).
#include <cstdint>

#include "ctab/lookup/creep.hpp"

namespace ctab::lookup::detail {

//! Strips to march: centre s, half-length a, peak of the parabolic traction bound's pressure q0 (the bound is
//! mu q0 (1 - x^2 / a^2)), the factor on the strip's inverse flexibilities 1/L1, 1/L2 (1: Kalker's), width ds (the
//! same for all).
struct MarchStrips {
  double s[kMaxCreepStrips];
  double a[kMaxCreepStrips];
  double q0[kMaxCreepStrips];
  double stiffness[kMaxCreepStrips];
  std::uint32_t n = 0;
  double ds = 0.0;
};

//! Simplified-theory flexibilities [m/Pa] (Kalker 1982): L1 = 8a / (3 C11 G), L2 = 8a / (3 C22 G),
//! L3 = pi a sqrt(a/b) / (4 C23 G).
struct Flexibility {
  double l1 = 0.0, l2 = 0.0, l3 = 0.0;
};
[[nodiscard]] Flexibility flexibility(double a_m, double b_m, double shear_modulus_Pa,
                                      const KalkerCoefficients& c) noexcept;

//! Sets each strip's stiffness so that its march follows the force of Carter's elastic strip (2-D) of the same
//! initial slope: FASTSIM on a strip with the parabolic bound is too soft in partial slip.
void carter_stiffness(MarchStrips& strips, const Flexibility& flex, const ctab_creep_input& input) noexcept;

//! Forces, moment about s = 0 and slip fraction of the march (fx, fs, mz, slip_fraction of `out`); with `field`,
//! each strip's forces per unit width and slip fraction.
void march(const MarchStrips& strips, const Flexibility& flex, const ctab_creep_input& input, std::int32_t cells,
           ctab_creep_patch& out, StripForces* field) noexcept;

}  // namespace ctab::lookup::detail
