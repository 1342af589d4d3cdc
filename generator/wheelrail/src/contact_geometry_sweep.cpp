// SPDX-License-Identifier: Apache-2.0
#include "ctab/wheelrail/contact_geometry_sweep.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

namespace ctab::gen {

RigidContactRow rigid_contact(const SideGeometry& right, const SideGeometry& left, double dy_m, ContactMode mode) {
  RigidContactRow row;
  row.dy_m = dy_m;
  if (mode == ContactMode::Wheelset) {
    WheelsetPose pose = rigid_wheelset_pose(right, left, dy_m);
    row.roll_rad = pose.roll_rad;
    row.converged = pose.converged;
    row.detail = std::move(pose.detail);
  }
  std::vector<GapMinimum> minima;
  double z = 0.0;
  for (const bool right_side : {true, false}) {
    if (right_side) right.gap_minima(dy_m, row.roll_rad, minima, z);
    else left.gap_minima(-dy_m, -row.roll_rad, minima, z);
    if (!minima.empty()) {
      (right_side ? row.right : row.left) = minima.front();
    } else if (row.converged) {
      row.converged = false;
      row.detail = std::string(right_side ? "the right" : "the left") +
                   " wheel does not reach its rail at dy = " + std::to_string(dy_m) +
                   " m (lateral shift beyond the profiles)";
    }
  }
  row.rolling_radius_difference_m = row.right.rolling_radius_m - row.left.rolling_radius_m;
  return row;
}

std::vector<ContactJump> find_contact_jumps(const std::vector<RigidContactRow>& rows, double threshold_m) {
  std::vector<ContactJump> jumps;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    for (const bool right : {true, false}) {
      const double before = right ? rows[i - 1].right.wheel_s_m : rows[i - 1].left.wheel_s_m;
      const double after = right ? rows[i].right.wheel_s_m : rows[i].left.wheel_s_m;
      if (std::abs(after - before) > threshold_m)
        jumps.push_back({rows[i - 1].dy_m, rows[i].dy_m, before, after, right});
    }
  }
  return jumps;
}

double equivalent_conicity(const std::vector<double>& dy_m, const std::vector<double>& delta_r_m, double amplitude_m) {
  const std::size_t n = dy_m.size();
  if (n < 3 || dy_m.front() != 0.0 || dy_m.back() < amplitude_m) return std::numeric_limits<double>::quiet_NaN();
  // V(u) = int_0^u dr/2 by the trapezoidal rule on the grid.
  std::vector<double> potential(n, 0.0);
  for (std::size_t i = 1; i < n; ++i)
    potential[i] = potential[i - 1] + 0.25 * (delta_r_m[i] + delta_r_m[i - 1]) * (dy_m[i] - dy_m[i - 1]);
  auto V = [&](double u) {  // exact integral of the piecewise-linear dr/2
    const double step = dy_m[1] - dy_m[0];
    const auto k = std::min(static_cast<std::size_t>(u / step), n - 2);
    const double t = (u - dy_m[k]) / step;
    return potential[k] + 0.5 * step * (t * delta_r_m[k] + 0.5 * t * t * (delta_r_m[k + 1] - delta_r_m[k]));
  };
  const double top = V(amplitude_m);
  // Composite Gauss-Legendre (4 points on 64 panels) in theta on [0, pi/2].
  static constexpr double kNodes[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                       0.8611363115940526};
  static constexpr double kWeights[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                         0.3478548451374538};
  constexpr int kPanels = 64;
  const double width = std::numbers::pi / 2 / kPanels;
  double quarter = 0.0;
  for (int p = 0; p < kPanels; ++p)
    for (int g = 0; g < 4; ++g) {
      const double theta = width * (p + 0.5 * (1.0 + kNodes[g]));
      const double u = amplitude_m * std::sin(theta);
      const double energy = 2.0 * (top - V(u));
      if (!(energy > 0.0)) return std::numeric_limits<double>::quiet_NaN();
      quarter += 0.5 * width * kWeights[g] * amplitude_m * std::cos(theta) / std::sqrt(energy);
    }
  const double wavelength = 4.0 * quarter;
  return std::pow(2.0 * std::numbers::pi / wavelength, 2);
}

}  // namespace ctab::gen
