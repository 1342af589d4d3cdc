// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Measurement noise of a point profile, estimated from the points alone (difference-based variance estimation:
//! Rice 1984; Gasser, Sroka & Jennen-Steinmetz 1986; Hall, Kay & Titterington 1990).
//!
//! Each run of four consecutive points p_i..p_{i+3} gives the third divided difference in summed-chord arc length
//! s, sum_j c_j p_j with c_j = 1 / prod_{k != j} (s_j - s_k), scaled by 1/|c| so that independent noise of
//! standard deviation sigma gives a pseudo-residual of standard deviation sigma. It annihilates every quadratic in
//! s, so a smooth profile (circular arcs, splines) contributes only through its curvature's derivative: at 0.1 mm
//! spacing a 10 mm arc contributes nothing, and a curvature jump spoils the one to three runs that straddle it.
//! The component normal to the chord p_i p_{i+3} is kept (noise along the profile is absorbed by the arc length),
//! and sigma is its median absolute value / 0.6745 (Gaussian consistency; robust to the junction runs), over the
//! runs whose chord is flatter than 45 degrees (tread, rail head, flange root: where the contact sees the noise;
//! on a steep flank noise in z hardly moves the surface) when there are at least 20 of them, else over all runs.
#include <vector>

namespace ctab::gen {

//! Standard deviation [m] of the noise normal to the profile of points (y, z) [m] ordered along it (at least 4
//! points, distinct consecutive points). 0 for exact (e.g. sampled analytic) data.
[[nodiscard]] double estimate_point_noise_m(const std::vector<double>& y, const std::vector<double>& z);

}  // namespace ctab::gen
