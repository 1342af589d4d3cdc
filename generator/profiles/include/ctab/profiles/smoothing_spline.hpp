// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Weighted cubic smoothing spline of a point profile in summed-chord arc length (CONTACT's smoothing method 1,
//! Vollebregt et al., CM2022): y(s) and z(s) each minimise sum w_i |x_i - f(s_i)|^2 + lambda int f''^2 ds with
//! w_i = (s_{i+1} - s_{i-1})/2 and lambda = (L/(2 pi))^4, a low-pass filter that halves wavelengths of about L.
//! L = 0 interpolates (natural cubic spline). Solved in Reinsch's form (Green & Silverman 1994, 2.3):
//! (R + lambda Q^T W^-1 Q) gamma = Q^T x, f = x - lambda W^-1 Q gamma, gamma the knot second derivatives.
#include <memory>
#include <vector>

#include "ctab/profiles/adaptive_smoothing.hpp"
#include "ctab/profiles/profile.hpp"

namespace ctab::gen {

class SmoothingSplineCurve final : public ProfileCurve {
 public:
  //! Points (y, z) [m], ordered with increasing y; smoothing length L [m] (0: interpolate).
  SmoothingSplineCurve(const std::vector<double>& y, const std::vector<double>& z, double smoothing_length_m);
  [[nodiscard]] double t_begin() const override { return s_.front(); }
  [[nodiscard]] double t_end() const override { return s_.back(); }
  [[nodiscard]] CurvePoint at(double t) const override;

 private:
  std::vector<double> s_, fy_, fz_, gy_, gz_;  // knots, smoothed values, second derivatives
};

//! Default smoothing length of point profiles [m] (CONTACT's method 1 at L = 1 mm).
inline constexpr double kDefaultSmoothingLength_m = 1e-3;
//! Noise [m] below which the automatic choice keeps the default length exactly (clean and finely quantised data).
inline constexpr double kNoiseThreshold_m = 0.5e-6;
//! Curvature noise the automatic choice allows [1/m]: the standard deviation of the smoothed noise's curvature
//! (adaptive_smoothing.hpp) on the running surfaces. 5 um noise every 0.1 mm gives L = 10.6 mm.
inline constexpr double kCurvatureNoise_per_m = 0.1;
//! Longest length the automatic choice takes [m]: the bias on the clean shape grows beyond it (S1002's flank
//! contact just past the root-to-flank jump of the contact point, dy 7 mm, gains 2.6 % in area at 10.6 mm,
//! 3.4 % at 12 mm and 7.7 % at 14 mm on clean points), while 10 um noise at 11 mm stays within 6.4 % there.
inline constexpr double kMaxAutoSmoothingLength_m = 11e-3;

//! The noise-aware smoothing of a point profile and the noise it was chosen for.
struct SmoothingChoice {
  double length_m = kDefaultSmoothingLength_m;  //!< L [m]
  double noise_sigma_m = 0.0;                   //!< estimated noise normal to the profile [m] (point_noise.hpp)
  bool adaptive = false;  //!< smooth_adaptively (adaptive_smoothing.hpp) instead of the cubic spline of length L
  CurvaturePrior prior = CurvaturePrior::Smooth;  //!< the adaptive smoother's prior
};
//! `--smoothing auto`: the noise sigma estimated from the points (point_noise.hpp); the cubic spline of the default
//! 1 mm while sigma is below kNoiseThreshold_m (clean data smooth exactly as with L = 1 mm); otherwise the adaptive
//! smoother with the length whose curvature noise is kCurvatureNoise_per_m at the profile's mean point spacing,
//! clamped to [default, kMaxAutoSmoothingLength_m]. L grows as sigma^(2/5) h^(1/5): 2, 5, 10 um at 0.1 mm give
//! about 7.4, 10.6 and 11 (capped from 14) mm.
[[nodiscard]] SmoothingChoice choose_smoothing(const std::vector<double>& y, const std::vector<double>& z);

//! A point profile smoothed as chosen, the length used (kArcLengthFactor times choice.length_m between the arcs prior's
//! junctions) and the shortest local length the adaptive smoother used [m] (L for the cubic spline).
struct SmoothedPointCurve {
  std::shared_ptr<const ProfileCurve> curve;
  double length_m = 0.0;
  double shortest_length_m = 0.0;
  int arc_junctions = 0;  //!< junctions the arcs prior placed (0 otherwise)
};
//! The cubic smoothing spline of length choice.length_m, or for an adaptive choice the interpolating cubic spline
//! through the adaptively smoothed points.
[[nodiscard]] SmoothedPointCurve smooth_point_profile(const std::vector<double>& y, const std::vector<double>& z,
                                                      const SmoothingChoice& choice);

}  // namespace ctab::gen
