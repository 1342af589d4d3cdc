#pragma once
//! One case of a contact table, set up and solved exactly as the table generator does (same profiles, track,
//! roll, load kind and solver options), so that `ctab solve --config` can check any table entry by hand.
//! Sweep-independent: it uses the public profile, wheel-rail and I/O APIs only. (The generator should call it too.)
#include <memory>
#include <string>

#include "ctab/io/profile_io.hpp"
#include "ctab/sweep/table_config.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"

namespace ctab::cli {

//! The set-up of a config: profiles, one side geometry for both sides (the left side is the mirror image of the
//! right: shift -dy, roll -phi), E* and the solver options. Not movable (the geometry points into the profiles).
class CaseSetup {
 public:
  //! Loads the profiles; throws InputError naming the config source and key (or the option) on bad input.
  explicit CaseSetup(const gen::TableConfig& config);
  CaseSetup(const CaseSetup&) = delete;
  CaseSetup& operator=(const CaseSetup&) = delete;

  [[nodiscard]] const gen::TableConfig& config() const noexcept { return config_; }
  [[nodiscard]] const gen::SideGeometry& side() const noexcept { return *side_; }
  [[nodiscard]] double effective_modulus_Pa() const noexcept { return E_star_Pa_; }
  [[nodiscard]] const gen::WheelRailOptions& options() const noexcept { return options_; }
  //! Solver options beyond the config (the CLI's --curvature and --update).
  [[nodiscard]] gen::WheelRailOptions& options() noexcept { return options_; }

 private:
  gen::TableConfig config_;
  gen::ProfileTable wheel_, rail_;
  std::unique_ptr<gen::SideGeometry> side_;
  double E_star_Pa_ = 0.0;
  gen::WheelRailOptions options_;
};

enum class Wheel { Right, Left };

//! One table case: the roll of the wheelset (0 in single-wheel mode) and the contact of each solved wheel.
struct TableCase {
  double dy_m = 0.0;
  double roll_rad = 0.0;
  bool roll_converged = true;  //!< false: the wheels' statuses are max-iterations (as in the table)
  bool solved[2] = {false, false};
  gen::WheelContact wheel[2];  //!< [Wheel::Right], [Wheel::Left], in the track frame (dy, roll of the wheelset)
};

//! Roll angle of the config's mode at a lateral shift [rad]; `converged` false when the roll iteration failed.
[[nodiscard]] double case_roll(const CaseSetup& setup, double dy_m, bool& converged);

//! True when the wheel has a point above its rail at this shift and roll (otherwise it is off the rail).
[[nodiscard]] bool wheel_over_rail(const CaseSetup& setup, Wheel wheel, double dy_m, double roll_rad);

//! Why a solved wheel failed, when the geometry tells ("" otherwise): roll iteration failed, wheel off the rail,
//! first contact at the end of the wheel or rail profile (a shift beyond what the profiles cover).
[[nodiscard]] std::string failure_hint(const CaseSetup& setup, Wheel wheel, const TableCase& result);

//! Solves the wheels selected in `wheels` (both by default) at the shift dy and the load value (in the unit of
//! the config's load kind: N or m). Never throws; per-wheel outcomes are statuses.
[[nodiscard]] TableCase solve_table_case(const CaseSetup& setup, double dy_m, double load_value, bool right = true,
                                         bool left = true);

}  // namespace ctab::cli
