// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The cant of a rail head measured from its profile points, to catch a rail file that is already inclined
//! being inclined again (a silent, large error: the Manchester UIC60 file inclined twice gives an equivalent
//! conicity of 0.009 instead of 0.18).
//!
//! Estimator (canonical frame of profile.hpp: y towards the field side, z down):
//! 1. The head's centre line: the gauge and field faces are found at the gauge measuring depth d = 14 mm below
//!    the highest point (EN 13848-1), or at the depth of the shallower profile end when that is less (at least
//!    5 mm); the head's axis meets them at y_c = (y_gauge + y_field)/2.
//! 2. The running band: the least-squares line z = a + b y over y_c +- 10 mm (the R300 crown of 60E1 spans
//!    +-10.2 mm), the points interpolated linearly on 201 equally spaced stations.
//! 3. The cant is -b (positive: gauge side low, i.e. inclined towards the track centre). A head symmetric about
//!    an axis tilted by theta has -b = tan(theta) to first order (the even part of the head adds no slope to a
//!    fit centred on the axis). The axis leans by theta between the crown and depth d, so the window is
//!    re-centred on the crown's axis point y_c - d tan(theta) and the fit repeated (twice).
//! Upright 60E1 gives 0, 60E1 at 1:40 gives 0.0250 and 1:20 gives 0.0500 (profiles_test).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace ctab::gen {

struct HeadCant {
  double cant = 0.0;        //!< tan of the head's tilt, positive with the gauge side (y < 0) low [-]
  double centre_y_m = 0.0;  //!< centre of the fitted running band [m]
  double depth_m = 0.0;     //!< depth below the top at which the head's faces were found [m]
};

namespace detail {

//! z of the polyline (y, z) at y (y increasing; clamped at the ends).
inline double polyline_z(const std::vector<double>& y, const std::vector<double>& z, double at) {
  const auto upper = std::upper_bound(y.begin(), y.end(), at);
  if (upper == y.begin()) return z.front();
  if (upper == y.end()) return z.back();
  const auto k = static_cast<std::size_t>(upper - y.begin());
  const double s = (at - y[k - 1]) / (y[k] - y[k - 1]);
  return z[k - 1] + s * (z[k] - z[k - 1]);
}

//! y where the polyline first reaches depth `level` walking from index `from` by `step` (+1 or -1).
inline std::optional<double> face_at_depth(const std::vector<double>& y, const std::vector<double>& z, std::size_t from,
                                           int step, double level) {
  for (std::size_t i = from; step > 0 ? i + 1 < y.size() : i > 0; i = step > 0 ? i + 1 : i - 1) {
    const std::size_t next = step > 0 ? i + 1 : i - 1;
    if (z[next] >= level) return y[i] + (level - z[i]) / (z[next] - z[i]) * (y[next] - y[i]);
  }
  return std::nullopt;
}

//! Slope b of the least-squares line over [centre - half_width, centre + half_width].
inline double band_slope(const std::vector<double>& y, const std::vector<double>& z, double centre, double half_width) {
  constexpr int kStations = 201;
  double sum_u2 = 0.0, sum_uz = 0.0, sum_z = 0.0;
  for (int k = 0; k < kStations; ++k) {
    const double u = half_width * (2.0 * k / (kStations - 1) - 1.0);
    sum_z += polyline_z(y, z, centre + u);
  }
  const double mean_z = sum_z / kStations;
  for (int k = 0; k < kStations; ++k) {
    const double u = half_width * (2.0 * k / (kStations - 1) - 1.0);
    sum_u2 += u * u;
    sum_uz += u * (polyline_z(y, z, centre + u) - mean_z);
  }
  return sum_uz / sum_u2;
}

}  // namespace detail

inline constexpr double kCantFaceDepth_m = 14e-3;      //!< depth of the head's faces (gauge measuring depth)
inline constexpr double kCantMinFaceDepth_m = 5e-3;    //!< shallower profiles are not measured
inline constexpr double kCantBandHalfWidth_m = 10e-3;  //!< half width of the fitted running band

//! The head's cant from profile points (y increasing, z down, SI); nullopt when the profile does not reach
//! 5 mm below its top on both sides or the band does not fit inside it.
[[nodiscard]] inline std::optional<HeadCant> measure_head_cant(const std::vector<double>& y_m,
                                                               const std::vector<double>& z_m) {
  if (y_m.size() < 3 || y_m.size() != z_m.size()) return std::nullopt;
  const auto top = static_cast<std::size_t>(std::min_element(z_m.begin(), z_m.end()) - z_m.begin());
  const double top_z = z_m[top];
  const double depth = std::min({kCantFaceDepth_m, z_m.front() - top_z, z_m.back() - top_z});
  if (!(depth >= kCantMinFaceDepth_m)) return std::nullopt;
  const auto gauge = detail::face_at_depth(y_m, z_m, top, -1, top_z + depth);
  const auto field = detail::face_at_depth(y_m, z_m, top, +1, top_z + depth);
  if (!gauge || !field) return std::nullopt;
  const double axis_at_depth = 0.5 * (*gauge + *field);
  HeadCant result{0.0, axis_at_depth, depth};
  for (int pass = 0; pass < 3; ++pass) {
    const double centre = axis_at_depth - depth * result.cant;  // the axis at the crown
    if (centre - kCantBandHalfWidth_m < y_m.front() || centre + kCantBandHalfWidth_m > y_m.back()) return std::nullopt;
    result = {-detail::band_slope(y_m, z_m, centre, kCantBandHalfWidth_m), centre, depth};
  }
  return result;
}

}  // namespace ctab::gen
