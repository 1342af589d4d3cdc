// SPDX-License-Identifier: Apache-2.0
#include "ctab/profiles/sampled_points.hpp"

#include <cmath>

namespace ctab::gen {

SampledPoints sample_points(const ProfileTable& table, double step_m, PointSpacing spacing,
                            const std::function<double(double)>& change) {
  SampledPoints points;
  for (double y = table.y_min(); y <= table.y_max();) {
    const ProfilePoint p = table.at(y);
    points.y_m.push_back(y);
    points.z_m.push_back(p.z + change(y));
    y += spacing == PointSpacing::Lateral ? step_m : step_m / std::sqrt(1.0 + p.dz * p.dz);
  }
  return points;
}

}  // namespace ctab::gen
