// SPDX-License-Identifier: Apache-2.0
#include "verify_errors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ctab::cli {

const char* quantity_name(Quantity q) noexcept {
  switch (q) {
    case Quantity::Force: return "force";
    case Quantity::Area: return "area";
    case Quantity::ContactPoint: return "contact_point";
    case Quantity::Lateral: return "lateral_force";
  }
  return "unknown";
}

std::array<double, kQuantities> table_tolerances(const tables::Table& table) {
  constexpr std::array<const char*, kQuantities> kNames{"tolerance_force_rel", "tolerance_area_rel",
                                                        "tolerance_contact_point_m", "tolerance_lateral_force_rel"};
  std::array<double, kQuantities> tolerance{0.005, 0.005, 1e-5, 0.005};
  for (std::size_t q = 0; q < kQuantities; ++q) {
    const auto found = table.number_attributes.find(kNames[q]);
    if (found != table.number_attributes.end() && std::isfinite(found->second) && found->second > 0.0)
      tolerance[q] = found->second;
  }
  return tolerance;
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double relative(double value, double reference) {
  return reference != 0.0 ? std::abs(value - reference) / std::abs(reference) : (value != 0.0 ? 1.0 : 0.0);
}

void raise(double& worst, double value) { worst = std::isnan(worst) ? value : std::max(worst, value); }

}  // namespace

PointErrors compare_point(const ctab_result& lookup, const gen::WheelContact& direct) {
  PointErrors out;
  out.error.fill(kNaN);
  const std::size_t n_direct = direct.patches.size(), n_slots = static_cast<std::size_t>(lookup.n_slots);
  // Every (direct patch, present slot) pair by distance; nearest first (ties by patch, then slot).
  struct Pair {
    double distance;
    std::size_t patch, slot;
  };
  std::vector<Pair> pairs;
  for (std::size_t p = 0; p < n_direct; ++p)
    for (std::size_t s = 0; s < n_slots; ++s)
      if (lookup.patch[s].present)
        pairs.push_back({std::abs(lookup.patch[s].q[CTAB_Y_RAIL_M] - direct.patches[p].y_rail_m), p, s});
  std::stable_sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.distance < b.distance; });
  std::vector<bool> patch_taken(n_direct, false), slot_taken(n_slots, false);
  for (const Pair& pair : pairs) {
    if (patch_taken[pair.patch] || slot_taken[pair.slot]) continue;
    patch_taken[pair.patch] = slot_taken[pair.slot] = true;
    const gen::ContactPatch& d = direct.patches[pair.patch];
    const double* q = lookup.patch[pair.slot].q;
    raise(out.error[static_cast<std::size_t>(Quantity::Force)], relative(q[CTAB_NORMAL_FORCE_N], d.normal_force_N));
    raise(out.error[static_cast<std::size_t>(Quantity::Area)], relative(q[CTAB_AREA_M2], d.area_m2));
    raise(out.error[static_cast<std::size_t>(Quantity::ContactPoint)], pair.distance);
  }
  for (std::size_t p = 0; p < n_direct; ++p) out.unmatched += !patch_taken[p];
  for (std::size_t s = 0; s < n_slots; ++s) out.unmatched += lookup.patch[s].present && !slot_taken[s];
  if (out.unmatched > 0) {
    raise(out.error[static_cast<std::size_t>(Quantity::Force)], 1.0);
    raise(out.error[static_cast<std::size_t>(Quantity::Area)], 1.0);
  }
  double lateral_lookup = 0.0, lateral_direct = 0.0, load = 0.0;
  for (std::size_t s = 0; s < n_slots; ++s)
    if (lookup.patch[s].present) lateral_lookup += lookup.patch[s].q[CTAB_FORCE_LATERAL_N];
  for (const gen::ContactPatch& d : direct.patches) {
    lateral_direct += d.force_lateral_N;
    load += d.force_vertical_N;
  }
  if (load > 0.0)
    out.error[static_cast<std::size_t>(Quantity::Lateral)] = std::abs(lateral_lookup - lateral_direct) / load;
  return out;
}

ErrorStats error_stats(const std::vector<double>& errors, const std::vector<std::size_t>& points) {
  ErrorStats stats;
  std::vector<double> sorted;
  for (std::size_t k = 0; k < errors.size(); ++k) {
    if (std::isnan(errors[k])) continue;
    if (sorted.empty() || errors[k] > stats.max) {
      stats.max = errors[k];
      stats.worst = points[k];
    }
    sorted.push_back(errors[k]);
  }
  stats.count = sorted.size();
  if (sorted.empty()) return stats;
  std::sort(sorted.begin(), sorted.end());
  const auto rank = [&](double share) {
    const auto r = static_cast<std::size_t>(std::ceil(share * static_cast<double>(sorted.size())));
    return sorted[std::clamp<std::size_t>(r, 1, sorted.size()) - 1];
  };
  stats.median = rank(0.5);
  stats.p95 = rank(0.95);
  return stats;
}

}  // namespace ctab::cli
