// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Optimal partitioning of a sampled signal into quadratic pieces (Jackson et al. 2005, "An algorithm for optimal
//! partitioning of data on an interval"): the boundaries that minimise sum over pieces of (the least-squares residual
//! of a quadratic in t fitted to the piece + a penalty per piece), by dynamic programming over the pieces, each piece's
//! residual updated point by point with Givens rotations, the starts that can no longer win pruned (PELT; Killick,
//! Fearnhead & Eckley 2012: about linear in n where pieces are long). The adaptive smoother's arcs prior
//! (adaptive_smoothing.hpp) finds a profile's junctions with it: a circular arc is a quadratic normal offset.
#include <cstddef>
#include <vector>

namespace ctab::gen {

//! The first index of every piece after the first (increasing) of the partition of values g_i at t_i (increasing)
//! into pieces of at least `min_points` points, each costing its quadratic fit's residual sum of squares plus
//! `penalty` (in g's unit squared). t and g of equal size, min_points >= 3.
[[nodiscard]] std::vector<std::size_t> quadratic_segmentation(const std::vector<double>& t,
                                                              const std::vector<double>& g, double penalty,
                                                              std::size_t min_points);

//! The first point after a jump in g's second derivative: g_i at t_i over [begin, end) fitted by c0 + c1 u + c2 u^2 +
//! c3 max(u - u_j, 0)^2 (value and slope continuous at u_j, the middle between the point and the one before), the
//! least residual over the points with at least `margin` (>= 2) points on either side (each in O(end - begin), by the
//! jump's column projected off the quadratic's).
[[nodiscard]] std::size_t refine_curvature_jump(const std::vector<double>& t, const std::vector<double>& g,
                                                std::size_t begin, std::size_t end, std::size_t margin);

}  // namespace ctab::gen
