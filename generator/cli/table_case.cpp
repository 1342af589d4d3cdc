// SPDX-License-Identifier: Apache-2.0
#include "table_case.hpp"

#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include "setup_options.hpp"

namespace ctab::cli {

namespace {

// The side frame of a wheel: the left side is the mirror image of the right (shift -dy, roll -phi).
double side_sign(std::size_t wheel) { return wheel == 1 ? -1.0 : 1.0; }

}  // namespace

gen::SweepSetup make_case_setup(const gen::TableConfig& config) {
  try {
    return gen::make_sweep_setup(config);
  } catch (const gen::SweepSetupError& e) {
    static const std::map<std::string, std::string> kOption = {{"profiles.wheel", "--wheel"},
                                                               {"profiles.rail", "--rail"},
                                                               {"solver.strip_width_m", "--strip-width"}};
    const auto option = kOption.find(e.key());
    if (config.source != kCommandLineSource || option == kOption.end()) throw;
    throw gen::InputError(option->second, 0, e.reason());
  }
}

bool wheel_over_rail(const gen::SweepSetup& setup, std::size_t wheel, double dy_m, double roll_rad) {
  const double sign = side_sign(wheel);
  double s_begin = 0.0, s_end = 0.0;
  setup.side->overlap(sign * dy_m, sign * roll_rad, s_begin, s_end);
  if (!(s_end > s_begin)) return false;
  std::vector<gen::GapMinimum> minima;
  double first_contact_z = 0.0;
  setup.side->gap_minima(sign * dy_m, sign * roll_rad, minima, first_contact_z);
  return !minima.empty() && std::isfinite(first_contact_z);
}

std::string failure_hint(const gen::SweepSetup& setup, std::size_t wheel, const gen::CaseSolution& solution) {
  const std::string roll_failure =
      solution.roll.converged ? std::string()
                              : "the wheelset roll iteration did not converge" +
                                    (solution.roll.detail.empty() ? std::string() : " (" + solution.roll.detail + ")");
  // Geometry at the rigid roll, or level when the roll search failed: it usually says why it failed.
  const double sign = side_sign(wheel), roll = solution.roll.converged ? solution.roll.roll_rad : 0.0;
  std::vector<gen::GapMinimum> minima;
  double first_contact_z = 0.0;
  setup.side->gap_minima(sign * solution.dy_m, sign * roll, minima, first_contact_z);
  if (minima.empty() || !wheel_over_rail(setup, wheel, solution.dy_m, roll)) return "the wheel is off its rail";
  constexpr double kNearEnd_m = 1e-3;
  const gen::GapMinimum& first = minima.front();
  const gen::ProfileTable& w = setup.side->wheel();
  const gen::ProfileTable& r = setup.side->rail();
  std::ostringstream hint;
  if (first.wheel_s_m - w.y_min() < kNearEnd_m || w.y_max() - first.wheel_s_m < kNearEnd_m)
    hint << "first contact at the end of the wheel profile (S = " << first.wheel_s_m * 1e3 << " mm)";
  else if (first.rail_y_m - r.y_min() < kNearEnd_m || r.y_max() - first.rail_y_m < kNearEnd_m)
    hint << "first contact at the end of the rail profile (y = " << first.rail_y_m * 1e3 << " mm)";
  else return roll_failure;
  hint << ": the shift is beyond what the profiles cover";
  return roll_failure.empty() ? hint.str() : roll_failure + "; " + hint.str();
}

}  // namespace ctab::cli
