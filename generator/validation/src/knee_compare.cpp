// SPDX-License-Identifier: Apache-2.0
// Per-patch errors of the knee sweep and the indicators' summary (knee_sweep.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

#include "ctab/validation/knee_sweep.hpp"

namespace ctab::gen {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double relative(double value, double reference) {
  return reference > 0.0 ? std::abs(value - reference) / reference : kInf;
}

KneeErrors patch_errors(const ContactPatch& c, const ContactPatch& r, double wheel_fz_N) {
  KneeErrors e;
  e.area_rel = relative(c.area_m2, r.area_m2);
  e.max_pressure_rel = relative(c.max_pressure_Pa, r.max_pressure_Pa);
  e.direction_rad = std::abs(c.contact_angle_rad - r.contact_angle_rad);
  e.lateral_of_fz = wheel_fz_N > 0.0 ? std::abs(c.force_lateral_N - r.force_lateral_N) / wheel_fz_N : kInf;
  e.contact_point_m = std::abs(c.y_cop_rail_m - r.y_cop_rail_m);
  return e;
}

}  // namespace

bool KneeErrors::exceeds(const KneeTargets& t) const noexcept {
  return !(area_rel <= t.area_rel && max_pressure_rel <= t.max_pressure_rel && direction_rad <= t.direction_rad &&
           lateral_of_fz <= t.lateral_of_fz && contact_point_m <= t.contact_point_m);
}

std::vector<KneeRow> compare_patches(const WheelContact& candidate, const WheelContact& reference) {
  std::vector<KneeRow> rows;
  for (std::size_t k = 0; k < reference.patches.size(); ++k) {
    const ContactPatch& r = reference.patches[k];
    KneeRow row;
    row.patch = k;
    row.zone = r.zone;
    row.load_share = reference.normal_force_N > 0.0 ? r.normal_force_N / reference.normal_force_N : 0.0;
    row.candidate_status = candidate.status;
    row.reference_status = reference.status;
    const ContactPatch* nearest = nullptr;
    for (const ContactPatch& c : candidate.patches)
      if (!nearest || std::abs(c.y_cop_rail_m - r.y_cop_rail_m) < std::abs(nearest->y_cop_rail_m - r.y_cop_rail_m))
        nearest = &c;
    if (nearest) {
      row.shape = patch_shape(*nearest);
      row.errors = patch_errors(*nearest, r, reference.vertical_force_N);
    } else {
      row.errors = {kInf, kInf, kInf, kInf, kInf};
    }
    rows.push_back(row);
  }
  return rows;
}

std::string knee_csv(const std::vector<KneeRow>& rows) {
  std::string out =
      "dy_m,vertical_load_N,patch,zone,load_share,candidate_status,reference_status,angle_spread_rad,"
      "max_turn_per_strip_rad,aspect_ratio,strips,area_rel,max_pressure_rel,direction_rad,lateral_of_fz,"
      "contact_point_m,chosen_method,chosen_width_m,candidate_time_s,reference_time_s\n";
  char line[512];
  for (const KneeRow& r : rows) {
    std::snprintf(line, sizeof line, "%.6g,%.6g,%zu,%s,%.6g,%s,%s,%.6g,%.6g,%.6g,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%s,%.6g,%.4g,%.4g\n",
                  r.dy_m, r.vertical_load_N, r.patch, r.zone.c_str(), r.load_share, status_name(r.candidate_status),
                  status_name(r.reference_status), r.shape.angle_spread_rad, r.shape.max_turn_per_strip_rad,
                  r.shape.aspect_ratio, r.shape.strips, r.errors.area_rel, r.errors.max_pressure_rel,
                  r.errors.direction_rad, r.errors.lateral_of_fz, r.errors.contact_point_m,
                  method_name(r.choice.method), r.choice.strip_width_m, r.candidate_time_s, r.reference_time_s);
    out += line;
  }
  return out;
}

namespace {

struct Indicator {
  const char* name;
  std::function<double(const PatchShape&)> value;  // larger = the strip model more at risk
};

// One summary line: the threshold flagging every failing patch and the share it flags; the false-negative rate at
// the threshold flagging 10 % of the patches.
std::string indicator_line(const Indicator& indicator, const std::vector<const KneeRow*>& rows,
                           const KneeTargets& targets) {
  std::vector<double> all, failing;
  for (const KneeRow* r : rows) {
    const double v = indicator.value(r->shape);
    all.push_back(v);
    if (r->errors.exceeds(targets)) failing.push_back(v);
  }
  std::sort(all.begin(), all.end());
  const double catch_all = failing.empty() ? kInf : *std::min_element(failing.begin(), failing.end());
  const auto flagged_at = [&](double t) {
    return static_cast<double>(all.end() - std::lower_bound(all.begin(), all.end(), t)) / static_cast<double>(all.size());
  };
  const double top10 = all[static_cast<std::size_t>(0.9 * static_cast<double>(all.size() - 1))];
  const double missed = static_cast<double>(std::count_if(failing.begin(), failing.end(), [&](double v) { return v < top10; }));
  char line[300];
  std::snprintf(line, sizeof line,
                "%-24s failing %zu of %zu; flags all failing at >= %.4g (flags %.1f %%); at the top-10 %% threshold "
                "%.4g misses %.1f %% of the failing\n",
                indicator.name, failing.size(), all.size(), catch_all, 100.0 * (failing.empty() ? 0.0 : flagged_at(catch_all)),
                top10, failing.empty() ? 0.0 : 100.0 * missed / static_cast<double>(failing.size()));
  return line;
}

}  // namespace

std::string knee_indicator_summary(const std::vector<KneeRow>& rows, const KneeTargets& targets,
                                   double min_load_share) {
  std::vector<const KneeRow*> kept;
  for (const KneeRow& r : rows)
    if (r.load_share >= min_load_share && is_success(r.reference_status) && r.shape.strips > 0) kept.push_back(&r);
  if (kept.empty()) return "no patch carries the stated share of the load\n";
  const Indicator indicators[] = {
      {"angle_spread_rad", [](const PatchShape& s) { return s.angle_spread_rad; }},
      {"max_turn_per_strip_rad", [](const PatchShape& s) { return s.max_turn_per_strip_rad; }},
      {"aspect_ratio", [](const PatchShape& s) { return s.aspect_ratio; }},
      {"1/strips", [](const PatchShape& s) { return 1.0 / s.strips; }},
  };
  std::string out;
  for (const Indicator& i : indicators) out += indicator_line(i, kept, targets);
  return out;
}

}  // namespace ctab::gen
