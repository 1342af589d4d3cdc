// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Creep forces on a contact patch from its normal solution (docs/creep.md): Kalker's simplified theory (FASTSIM)
//! marched along x on the patch's strips or on its equivalent ellipse, and Kalker's linear theory. Real-time rules
//! of the queries: noexcept, no allocation, no lock, time bounded by the strip count and the cells per strip.
#include <cstdint>

#include "ctab/lookup/ctab_lookup.h"

namespace ctab::lookup {

class Table;

inline constexpr std::uint32_t kMaxCreepStrips = 256;  //!< most strips one creep call takes
inline constexpr std::int32_t kDefaultCreepCells = 16;
inline constexpr std::int32_t kMinCreepCells = 4, kMaxCreepCells = 64;
inline constexpr double kDefaultYoungsModulus_Pa = 208e9, kDefaultPoissonRatio = 0.3;

//! Kalker's linear-theory coefficients of an ellipse.
struct KalkerCoefficients {
  double c11 = 0.0, c22 = 0.0, c23 = 0.0, c33 = 0.0;
};
//! Kalker 1990 Table E.3 at semi-axes a (rolling direction), b and Poisson's ratio nu in [0, 0.5]: linear in the
//! ratio of the shorter to the longer axis on its branch (a < b or a >= b), quadratic in nu on the reciprocals.
//! Ratios beyond 10 use the ratio-10 row.
[[nodiscard]] KalkerCoefficients kalker_coefficients(double a_m, double b_m, double poisson_ratio) noexcept;

//! One patch as strips: n samples evenly spaced in s (n in 2..kMaxCreepStrips).
struct StripPatch {
  const double* s_m = nullptr;
  const double* half_length_m = nullptr;
  const double* peak_pressure_Pa = nullptr;
  std::uint32_t n = 0;
  double normal_force_N = 0.0;  //!< > 0: the pressure is rescaled to this force; 0: as given
  double plane_angle_rad = 0.0;
};

//! True when the creepages, friction, material, method and cell count of `input` are usable.
[[nodiscard]] bool valid_creep_input(const ctab_creep_input& input) noexcept;

//! Per strip of a patch (the strip method): forces per unit width [N/m] and slip fraction, at the patch's samples.
struct StripForces {
  double fx_per_m[kMaxCreepStrips];
  double fs_per_m[kMaxCreepStrips];
  double slip_fraction[kMaxCreepStrips];
};

//! Creep forces of one patch. Invalid input: CTAB_INVALID_INPUT and `out` zeroed (present 0). With `field` and the
//! strip method, each strip's forces too (other methods leave it untouched).
ctab_status creep_patch(const StripPatch& patch, const ctab_creep_input& input, ctab_creep_patch& out,
                        StripForces* field = nullptr) noexcept;

//! Creep forces of every slot of one wheel at a prelooked point of `table`.
ctab_status creep_query(const Table& table, const ctab_location& where, std::int32_t wheel,
                        const ctab_creep_input& input, ctab_creep_result& out) noexcept;

//! Creep forces of one slot with its own creepages (tread and flange of one wheel roll differently).
ctab_status creep_slot(const Table& table, const ctab_location& where, std::int32_t wheel, std::int32_t slot,
                       const ctab_creep_input& input, ctab_creep_patch& out) noexcept;

}  // namespace ctab::lookup
