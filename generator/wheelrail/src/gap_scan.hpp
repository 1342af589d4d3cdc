// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The coarse gap scan of one side (internal to ctab::wheelrail): the overlap of wheel and rail, a uniform S grid
//! over it (step at most SideGeometry::kScanStep_m), the local minima of the vertical gap on the grid, and their
//! golden-section refinement. SideGeometry::gap_minima / first_contact_height scan the whole grid;
//! FirstContactTracker scans windows of the same grid (the same points, so the same minima).
#include <cstddef>
#include <vector>

#include "ctab/wheelrail/wheelrail_geometry.hpp"

namespace ctab::gen::gap_scan {

//! A grid point that is a local minimum of the gap (interior, or at an end of the overlap).
struct CoarseMinimum {
  double s = 0.0;    //!< S on the wheel profile [m]
  double gap = 0.0;  //!< gap there, z_ws = 0 [m]
};

//! The wheel and the roll's cosine and sine at one shift: what every gap evaluation of a scan shares.
struct Pose {
  double dy_m = 0.0, roll_rad = 0.0, cos_roll = 1.0, sin_roll = 0.0;
  Pose(double dy, double roll);
};

//! The uniform S grid over the overlap: point k at s_begin + step k, k < count (count 0: no overlap).
struct Grid {
  double s_begin = 0.0, s_end = 0.0, step = 0.0;
  std::size_t count = 0;
  [[nodiscard]] double s(std::size_t k) const noexcept { return s_begin + step * static_cast<double>(k); }
};

[[nodiscard]] Grid make_grid(const SideGeometry& side, const Pose& pose);

//! Rail coordinate below the wheel point at S (SideGeometry::wheel_point's rail_y_m, from the cubic z_at) [m].
[[nodiscard]] double rail_y(const SideGeometry& side, const Pose& pose, double s);

//! Appends the coarse minima among grid points first..last (inclusive) to `out`: interior minima need both
//! neighbours inside the range, end minima are those of the whole grid (k = 0 or count - 1). `values` (if not
//! null) receives the gap at every scanned point, in order.
void scan(const SideGeometry& side, const Pose& pose, const Grid& grid, std::size_t first, std::size_t last,
          std::vector<CoarseMinimum>& out, std::vector<double>* values = nullptr);

//! Golden-section refinement of a coarse minimum on [s - step, s + step] within the overlap; returns S.
[[nodiscard]] double refine(const SideGeometry& side, const Pose& pose, const Grid& grid, double centre);

//! The two lowest coarse minima refined (they can swap order on refinement on a near-conformal tread).
struct RefinedPair {
  std::size_t count = 0;                         //!< how many were refined (0, 1 or 2)
  double first = 0.0;                            //!< refined gap of the lowest coarse minimum [m]
  double second = 0.0;                           //!< the same for the second lowest [m] (+inf when count < 2)
  [[nodiscard]] double lowest() const noexcept;  //!< the first contact height, the lower of the two (NaN: none)
};
//! Refines the two lowest of `coarse` (reordering it).
[[nodiscard]] RefinedPair refine_two_lowest(const SideGeometry& side, const Pose& pose, const Grid& grid,
                                            std::vector<CoarseMinimum>& coarse);

}  // namespace ctab::gen::gap_scan
