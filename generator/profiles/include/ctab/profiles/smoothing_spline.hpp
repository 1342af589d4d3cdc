#pragma once
//! Weighted cubic smoothing spline of a point profile in summed-chord arc length (CONTACT's smoothing method 1,
//! Vollebregt et al., CM2022): y(s) and z(s) each minimise sum w_i |x_i - f(s_i)|^2 + lambda int f''^2 ds with
//! w_i = (s_{i+1} - s_{i-1})/2 and lambda = (L/(2 pi))^4, a low-pass filter that halves wavelengths of about L.
//! L = 0 interpolates (natural cubic spline). Solved in Reinsch's form (Green & Silverman 1994, 2.3):
//! (R + lambda Q^T W^-1 Q) gamma = Q^T x, f = x - lambda W^-1 Q gamma, gamma the knot second derivatives.
#include <vector>

#include "ctab/profiles/profile.hpp"

namespace ctab::gen {

class SmoothingSplineCurve final : public ProfileCurve {
 public:
  //! Points (y, z) [m], ordered with increasing y; smoothing length L [m] (0: interpolate).
  SmoothingSplineCurve(const std::vector<double>& y, const std::vector<double>& z, double smoothing_length_m);
  //! The same with a smoothing length per point [m]: residual weights w_i / lambda_i against a unit penalty, i.e.
  //! (R + Q^T Lambda W^-1 Q) gamma = Q^T x, f = x - Lambda W^-1 Q gamma, a low-pass whose cut-off follows L_i.
  SmoothingSplineCurve(const std::vector<double>& y, const std::vector<double>& z,
                       const std::vector<double>& smoothing_lengths_m);
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
//! Largest length the automatic choice takes [m] (the config's limit is 0.1 m).
inline constexpr double kMaxAutoSmoothingLength_m = 50e-3;
//! Curvature noise the automatic choice allows [1/m] (standard deviation of the smoothed noise's second
//! derivative): on the running surfaces (kCurvatureNoise_per_m) and near jumps of the curvature, where a long L
//! would flatten the real profile (kJumpCurvatureNoise_per_m). Calibrated on S1002 and 60E1 with 2, 5 and 10 um
//! noise every 0.1 mm (tests/generator/profile_noise_test.cpp): 5 um gives L = 8.8 mm and 3.0 mm near jumps. The
//! near-jump value is set by the bias on the clean shape: S1002's flank contact just past the root-to-flank jump
//! of the contact point (dy 7 mm, wheel y -38.8 mm, 70 deg) gains 5.6-6.0 % in area with 3.5 mm (2 /m)
//! and 3.3 % with 3.0 mm (3 /m) on clean points; the noise adds less than 0.5 % there.
inline constexpr double kCurvatureNoise_per_m = 0.2;
inline constexpr double kJumpCurvatureNoise_per_m = 3.0;
//! A curvature jump: the pilot curvature's second difference over +-kJumpReach x L exceeds this [1/m] (S1002's
//! flange root and 60E1's R300/R80/R13 junctions are 8 to 65 1/m; the noise left at L is about 0.5 1/m).
inline constexpr double kCurvatureJump_per_m = 4.0;
inline constexpr double kJumpReach = 0.4;

//! Standard deviation [1/m] of the second derivative that the smoothing spline of length L [m] leaves of white
//! noise of standard deviation sigma [m] on points spaced h [m]: the spline is the low-pass filter
//! 1 / (1 + lambda omega^4) (Reinsch 1967; Silverman 1984's equivalent kernel), so
//! Var f'' = sigma^2 h / (2 pi) int omega^4 / (1 + lambda omega^4)^2 d omega = sigma^2 h lambda^(-5/4) sqrt(2)/16.
[[nodiscard]] double curvature_noise_per_m(double noise_sigma_m, double point_spacing_m, double smoothing_length_m);
//! The inverse: the smoothing length [m] that leaves curvature noise `curvature_noise_per_m` [1/m].
[[nodiscard]] double length_for_curvature_noise_m(double noise_sigma_m, double point_spacing_m,
                                                  double curvature_noise_per_m);

//! The noise-aware smoothing of a point profile and the noise it was chosen for.
struct SmoothingChoice {
  double length_m = kDefaultSmoothingLength_m;       //!< L on the running surfaces [m]
  double jump_length_m = kDefaultSmoothingLength_m;  //!< L near jumps of the curvature [m] (<= length_m)
  double noise_sigma_m = 0.0;                        //!< estimated noise normal to the profile [m] (point_noise.hpp)
};
//! `--smoothing auto`: the noise sigma estimated from the points (point_noise.hpp); both lengths the default 1 mm
//! while sigma is below kNoiseThreshold_m (clean data smooth exactly as with L = 1 mm); otherwise the lengths whose
//! curvature noise is kCurvatureNoise_per_m and kJumpCurvatureNoise_per_m at the profile's mean point spacing,
//! clamped to [default, kMaxAutoSmoothingLength_m]. L grows as sigma^(2/5) h^(1/5): 2, 5, 10 um at 0.1 mm give
//! about 6.1, 8.8, 11.6 mm (2.1, 3.0, 3.9 mm near jumps).
[[nodiscard]] SmoothingChoice choose_smoothing(const std::vector<double>& y, const std::vector<double>& z);

//! The smoothing length at each point: choice.length_m, but choice.jump_length_m within kJumpReach x L of a jump
//! of the curvature (found on a pilot fit with choice.length_m), growing back by at most 1 m per m of arc length
//! (so the long smoothing never reaches across a jump). All equal when the two lengths are.
[[nodiscard]] std::vector<double> smoothing_lengths(const std::vector<double>& y, const std::vector<double>& z,
                                                    const SmoothingChoice& choice);

}  // namespace ctab::gen
