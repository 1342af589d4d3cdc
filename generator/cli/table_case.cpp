#include "table_case.hpp"

#include <cmath>
#include <sstream>

#include "ctab/contact/error.hpp"
#include "ctab/contact/material.hpp"
#include "setup_options.hpp"

namespace ctab::cli {

namespace {

// Errors of a config file name the file, line and key; errors of command-line options name the option.
[[noreturn]] void fail(const gen::TableConfig& config, const char* key, const char* option,
                       const std::string& message) {
  if (config.source == kCommandLineSource) throw gen::InputError(option, 0, message);
  throw gen::InputError(config.source, config.key_line(key), std::string("'") + key + "': " + message);
}

gen::ProfileTable load_checked(const gen::TableConfig& config, const std::string& spec, gen::ProfileRole role,
                               const char* key, const char* option) {
  gen::ProfileReadOptions read;
  read.smoothing_length_m = config.smoothing_length_m;
  read.inclination = config.inclination;
  try {
    return gen::load_profile(spec, role, read);
  } catch (const gen::InputError& e) {
    fail(config, key, option, e.what());
  }
}

}  // namespace

CaseSetup::CaseSetup(const gen::TableConfig& config)
    : config_(config),
      wheel_(load_checked(config, config.wheel, gen::ProfileRole::Wheel, "profiles.wheel", "--wheel")),
      rail_(load_checked(config, config.rail, gen::ProfileRole::Rail, "profiles.rail", "--rail")),
      side_(std::make_unique<gen::SideGeometry>(wheel_, rail_, config.track)),
      E_star_Pa_(gen::effective_modulus(config.material, config.material)) {
  if (!(config.strip_width_m >= kMinStripWidth_m && config.strip_width_m <= kMaxStripWidth_m)) {
    std::ostringstream range;
    range << "expected a strip width in [" << kMinStripWidth_m << ", " << kMaxStripWidth_m << "] m, got "
          << config.strip_width_m;
    fail(config, "solver.strip_width_m", "--strip-width", range.str());
  }
  options_.method = config.method;
  options_.mim1d.strip_width_m = config.strip_width_m;
}

double case_roll(const CaseSetup& setup, double dy_m, bool& converged) {
  converged = true;
  if (setup.config().mode != gen::ContactMode::Wheelset) return 0.0;
  try {
    const gen::WheelsetPose pose = gen::rigid_wheelset_pose(setup.side(), setup.side(), dy_m);
    converged = pose.converged;
    return pose.roll_rad;
  } catch (...) {  // as in the generator: a failed roll iteration is the case's status, not an exception
    converged = false;
    return 0.0;
  }
}

bool wheel_over_rail(const CaseSetup& setup, Wheel wheel, double dy_m, double roll_rad) {
  const double sign = wheel == Wheel::Right ? 1.0 : -1.0;
  double s_begin = 0.0, s_end = 0.0;
  setup.side().overlap(sign * dy_m, sign * roll_rad, s_begin, s_end);
  if (!(s_end > s_begin)) return false;
  std::vector<gen::GapMinimum> minima;
  double first_contact_z = 0.0;
  setup.side().gap_minima(sign * dy_m, sign * roll_rad, minima, first_contact_z);
  return !minima.empty() && std::isfinite(first_contact_z);
}

std::string failure_hint(const CaseSetup& setup, Wheel wheel, const TableCase& result) {
  if (!result.roll_converged) return "the wheelset roll iteration did not converge";
  const double sign = wheel == Wheel::Right ? 1.0 : -1.0;
  std::vector<gen::GapMinimum> minima;
  double first_contact_z = 0.0;
  setup.side().gap_minima(sign * result.dy_m, sign * result.roll_rad, minima, first_contact_z);
  if (minima.empty() || !wheel_over_rail(setup, wheel, result.dy_m, result.roll_rad))
    return "the wheel is off its rail";
  constexpr double kNearEnd_m = 1e-3;
  const gen::GapMinimum& first = minima.front();
  const gen::ProfileTable& w = setup.side().wheel();
  const gen::ProfileTable& r = setup.side().rail();
  std::ostringstream hint;
  if (first.wheel_s_m - w.y_min() < kNearEnd_m || w.y_max() - first.wheel_s_m < kNearEnd_m)
    hint << "first contact at the end of the wheel profile (S = " << first.wheel_s_m * 1e3 << " mm)";
  else if (first.rail_y_m - r.y_min() < kNearEnd_m || r.y_max() - first.rail_y_m < kNearEnd_m)
    hint << "first contact at the end of the rail profile (y = " << first.rail_y_m * 1e3 << " mm)";
  else
    return {};
  hint << ": the shift is beyond what the profiles cover";
  return hint.str();
}

TableCase solve_table_case(const CaseSetup& setup, double dy_m, double load_value, bool right, bool left) {
  TableCase result;
  result.dy_m = dy_m;
  result.roll_rad = case_roll(setup, dy_m, result.roll_converged);
  const bool wanted[2] = {right, left};
  for (int w = 0; w < 2; ++w) {
    if (!wanted[w]) continue;
    const double sign = w == 0 ? 1.0 : -1.0;  // the left side in its mirrored frame: shift -dy, roll -phi
    gen::WheelContact& contact = result.wheel[w];
    contact = gen::solve_wheel_contact(setup.side(), sign * dy_m, sign * result.roll_rad, setup.effective_modulus_Pa(),
                                       setup.config().load_kind, load_value, setup.options());
    if (!result.roll_converged) contact.status = gen::SolveStatus::MaxIterations;
    contact.dy_m = dy_m;
    contact.roll_rad = result.roll_rad;
    result.solved[w] = true;
  }
  return result;
}

}  // namespace ctab::cli
