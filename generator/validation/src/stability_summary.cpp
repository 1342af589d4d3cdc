// SPDX-License-Identifier: Apache-2.0
// The stability matrix's summary table and verdict (stability_matrix.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "ctab/validation/stability_matrix.hpp"

namespace ctab::gen {

namespace {

//! One line of the summary: a scene and a method over its cases.
struct SummaryLine {
  int cases = 0, converged = 0, no_contact = 0, under_resolved = 0, failed = 0, claimed = 0, broken = 0, non_finite = 0;
  double worst_error = 0.0, worst_time_s = 0.0;
  std::map<std::string, int> failures;  // status name -> count
};

void add_row(SummaryLine& l, const StabilityRow& r) {
  ++l.cases;
  l.converged += r.status == SolveStatus::Converged;
  l.no_contact += r.status == SolveStatus::NoContact;
  l.under_resolved += r.status == SolveStatus::UnderResolved;
  if (!is_success(r.status)) {
    ++l.failed;
    ++l.failures[status_name(r.status)];
  }
  l.non_finite += r.finite ? 0 : 1;
  const double e = r.error_rel();
  if (std::isfinite(e)) l.worst_error = std::max(l.worst_error, e);
  l.worst_time_s = std::max(l.worst_time_s, r.time_s);
  if (stability_claim_applies(r)) {
    ++l.claimed;
    l.broken += e > stability_error_bound(r) ? 1 : 0;
  }
}

template <class... Args>
std::string formatted(const char* format, Args... args) {
  char text[512];
  std::snprintf(text, sizeof text, format, args...);
  return text;
}

}  // namespace

std::string stability_summary(const std::vector<StabilityRow>& rows) {
  std::map<std::pair<std::string, std::string>, SummaryLine> lines;
  std::vector<std::pair<std::string, std::string>> order;
  for (const StabilityRow& r : rows) {
    const auto key = std::make_pair(r.scene, r.method);
    if (!lines.count(key)) order.push_back(key);
    add_row(lines[key], r);
  }
  std::string text =
      formatted("%-22s %-7s %5s %5s %5s %5s %6s %7s %6s %9s %9s  %s\n", "scene", "method", "cases", "conv", "noc",
                "under", "failed", "claimed", "broken", "worst err", "worst s", "failures");
  for (const auto& key : order) {
    const SummaryLine& l = lines[key];
    std::string failures;
    for (const auto& [name, count] : l.failures) failures += name + " x" + std::to_string(count) + " ";
    if (l.non_finite) failures += "NON-FINITE x" + std::to_string(l.non_finite);
    text += formatted("%-22s %-7s %5d %5d %5d %5d %6d %7d %6d %8.1f%% %9.2e  ", key.first.c_str(), key.second.c_str(),
                      l.cases, l.converged, l.no_contact, l.under_resolved, l.failed, l.claimed, l.broken,
                      100.0 * l.worst_error, l.worst_time_s);
    text += failures + "\n";
  }
  return text;
}

bool stability_claims_broken(const std::vector<StabilityRow>& rows) {
  return std::any_of(rows.begin(), rows.end(), [](const StabilityRow& r) {
    return !r.finite || (stability_claim_applies(r) && r.error_rel() > stability_error_bound(r));
  });
}

}  // namespace ctab::gen
