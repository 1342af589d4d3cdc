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
  [[nodiscard]] double t_begin() const override { return s_.front(); }
  [[nodiscard]] double t_end() const override { return s_.back(); }
  [[nodiscard]] CurvePoint at(double t) const override;

 private:
  std::vector<double> s_, fy_, fz_, gy_, gz_;  // knots, smoothed values, second derivatives
};

}  // namespace ctab::gen
