// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Resolution of a discretised rung's result (docs/validation.md "Stability where methods fail"): with fewer than
//! kMinResolvedStrips strips (elements) across the smallest loaded patch the stability matrix measured MIM-1D up to
//! 38 % and bem2d up to 183 % off their references, so such a result carries SolveStatus::UnderResolved.
#include <vector>

#include "ctab/contact/contact_method.hpp"
#include "ctab/contact/normal_solution.hpp"
#include "ctab/contact/solve_status.hpp"

namespace ctab::gen {

//! Fewest strips across a loaded patch for an error bound [-].
inline constexpr double kMinResolvedStrips = 8.0;
//! Patches carrying less than this share of the total normal force do not count (as in the stability matrix) [-].
inline constexpr double kResolvedForceShare = 0.05;

//! Extent of one patch: lateral width (strips side by side), longest strip length 2a and force.
struct PatchExtent {
  double width_m = 0.0;   //!< lateral extent, y_max - y_min [m]
  double length_m = 0.0;  //!< largest 2 a_i [m]
  double force_N = 0.0;   //!< normal force of the patch [N]
};

//! The extent of a patch `width_m` wide carrying `force_N` on `strips` (any type with half_length_m).
template <class Strip>
[[nodiscard]] PatchExtent patch_extent(double width_m, double force_N, const std::vector<Strip>& strips) noexcept {
  PatchExtent extent{width_m, 0.0, force_N};
  for (const Strip& s : strips)
    extent.length_m = extent.length_m > 2.0 * s.half_length_m ? extent.length_m : 2.0 * s.half_length_m;
  return extent;
}

//! True for the rungs whose patch is made of strips or elements of the strip width: kp, analyn, mim1d, bem2d.
[[nodiscard]] bool discretises(ContactMethod method) noexcept;

//! Fewest strips across the patches that carry at least kResolvedForceShare of their summed force: width / strip
//! width, and for bem2d (square elements) also length / element size. +inf when no patch counts.
[[nodiscard]] double min_resolved_strips(const std::vector<PatchExtent>& patches, ContactMethod method,
                                         double strip_width_m) noexcept;
//! The extents of a strip problem's patches.
[[nodiscard]] std::vector<PatchExtent> patch_extents(const NormalSolution& solution);
//! Smallest of width and length over the patches that carry at least kResolvedForceShare of their summed force
//! (the stability matrix's resolution measure) [m]; 0 when no patch counts.
[[nodiscard]] double smallest_loaded_extent_m(const std::vector<PatchExtent>& patches) noexcept;

//! `status`, or UnderResolved where it is Converged, the rung discretises and fewer than kMinResolvedStrips strips
//! lie across its smallest counted patch.
[[nodiscard]] SolveStatus resolution_status(SolveStatus status, ContactMethod method,
                                            const std::vector<PatchExtent>& patches, double strip_width_m) noexcept;

}  // namespace ctab::gen
