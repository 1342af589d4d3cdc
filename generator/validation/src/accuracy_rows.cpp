// SPDX-License-Identifier: Apache-2.0
// Rows of the accuracy bench (accuracy_bench.hpp): the worst errors over a row's cases, and their CSV.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "bench_text.hpp"
#include "ctab/validation/accuracy_bench.hpp"

namespace ctab::gen {

void AccuracyRow::add(const ContactSummary& candidate, const ContactSummary& reference_summary, bool ok,
                      const std::vector<double>& times_s, const std::optional<ContactFigures>& contact) {
  const AccuracyErrors e = accuracy_errors(candidate, reference_summary);
  ++cases;
  failed += ok ? 0 : 1;
  time_sum_s += *std::min_element(times_s.begin(), times_s.end());
  solve_times_s.insert(solve_times_s.end(), times_s.begin(), times_s.end());
  worst.area_rel = std::max(worst.area_rel, e.area_rel);
  worst.max_pressure_rel = std::max(worst.max_pressure_rel, e.max_pressure_rel);
  worst.p0_profile_rms_rel = std::max(worst.p0_profile_rms_rel, e.p0_profile_rms_rel);
  worst.contact_point_m = std::max(worst.contact_point_m, e.contact_point_m);
  if (!contact) return;
  ++contact_cases;
  contact_area = std::max(contact_area, std::fabs(candidate.area_m2 - contact->area_m2) / contact->area_m2);
  contact_pressure = std::max(contact_pressure, std::fabs(candidate.max_pressure_Pa - contact->max_pressure_Pa) /
                                                    contact->max_pressure_Pa);
  if (std::isfinite(contact->centre_of_pressure_m)) {
    const double d = std::fabs(candidate.centre_of_pressure_m - contact->centre_of_pressure_m);
    contact_point = std::isfinite(contact_point) ? std::max(contact_point, d) : d;
  }
}

namespace {

// "min,median,max" of single solves [s] (the median of an even count: the upper middle one); empty fields if none.
std::string spread_columns(std::vector<double> times_s) {
  if (times_s.empty()) return ",,";
  std::sort(times_s.begin(), times_s.end());
  return detail::csv_number(times_s.front()) + ',' + detail::csv_number(times_s[times_s.size() / 2]) + ',' +
         detail::csv_number(times_s.back());
}

}  // namespace

std::string accuracy_csv(const std::vector<AccuracyRow>& rows) {
  using detail::csv_number;
  std::ostringstream out;
  out << "scene,region,method,discretisation_m,reference,cases,failed_cases,time_per_case_s,area_error_rel,"
         "max_pressure_error_rel,p0_profile_rms_error_rel,contact_point_error_m,error_rel,contact_cases,"
         "vs_contact_area_error_rel,vs_contact_max_pressure_error_rel,vs_contact_point_error_m,tolerance,"
         "time_min_s,time_median_s,time_max_s\n";
  for (const AccuracyRow& r : rows) {
    const double worst = std::max({r.worst.area_rel, r.worst.max_pressure_rel, r.worst.p0_profile_rms_rel});
    const bool has_contact = r.contact_cases > 0;
    out << r.scene << ',' << r.region << ',' << r.method << ',' << csv_number(r.width_m) << ',' << r.reference << ','
        << r.cases << ',' << r.failed << ',' << csv_number(r.time_sum_s / r.cases) << ','
        << csv_number(r.worst.area_rel) << ',' << csv_number(r.worst.max_pressure_rel) << ','
        << csv_number(r.worst.p0_profile_rms_rel) << ',' << csv_number(r.worst.contact_point_m) << ','
        << csv_number(worst) << ',' << r.contact_cases << ',' << (has_contact ? csv_number(r.contact_area) : "") << ','
        << (has_contact ? csv_number(r.contact_pressure) : "") << ','
        << (has_contact ? csv_number(r.contact_point) : "") << ',' << (r.tolerance > 0.0 ? csv_number(r.tolerance) : "")
        << ',' << spread_columns(r.solve_times_s) << '\n';
  }
  return out.str();
}

}  // namespace ctab::gen
