// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The knee sweep (`ctab bench knee`, docs/design/knee-indicator.md): a single wheel on its rail over a dense range of
//! lateral shifts and several vertical loads, solved by a candidate (MIM-1D at a strip width, or the least model)
//! and by bem2d at a fine element size; per bem2d patch the candidate's errors (area, max pressure, force direction,
//! lateral force over F_z, contact point) next to the candidate patch's shape (patch_shape.hpp), the indicators
//! that may predict them. Cases run in parallel (OpenMP); progress goes to stderr.
#include <string>
#include <vector>

#include "ctab/sweep/table_config.hpp"
#include "ctab/wheelrail/least_model.hpp"
#include "ctab/wheelrail/patch_shape.hpp"

namespace ctab::gen {

//! The per-patch targets of the least model against converged bem2d.
struct KneeTargets {
  double area_rel = 0.03;           //!< |A - A_ref| / A_ref [-]
  double max_pressure_rel = 0.05;   //!< |pmax - pmax_ref| / pmax_ref [-]
  double direction_rad = 0.3 * 3.141592653589793 / 180.0;  //!< force direction [rad]
  double lateral_of_fz = 0.02;      //!< |F_y - F_y,ref| / F_z of the wheel [-]
  double contact_point_m = 0.3e-3;  //!< |y_cop - y_cop,ref| on the rail [m]
};

//! Errors of one candidate patch against its bem2d patch (infinite where the candidate has no patch there).
struct KneeErrors {
  double area_rel = 0.0, max_pressure_rel = 0.0, direction_rad = 0.0, lateral_of_fz = 0.0, contact_point_m = 0.0;
  //! True when any error exceeds its target.
  [[nodiscard]] bool exceeds(const KneeTargets& targets) const noexcept;
};

struct KneeSweepOptions {
  TableConfig profiles;  //!< wheel, rail, inclination and surface (mode, loading and method are the sweep's)
  std::vector<double> shifts_m;
  std::vector<double> vertical_loads_N{50e3, 78.5e3, 110e3};
  ContactMethod candidate_method = ContactMethod::Mim1d;
  double candidate_width_m = 0.05e-3;  //!< strip width of the candidate [m] (unused by the least model)
  double candidate_tolerance = 0.0;    //!< > 0: the candidate is the least model at this tolerance [-]
  double reference_width_m = 0.1e-3;   //!< bem2d row width of the reference [m]
  double reference_length_m = 0.0;     //!< its element length along the rolling direction [m]; 0: squares
};

//! One bem2d patch of one case and the candidate's patch nearest to it (centre of pressure on the rail).
struct KneeRow {
  double dy_m = 0.0, vertical_load_N = 0.0;
  std::size_t patch = 0;  //!< index among the reference's patches
  std::string zone;       //!< the reference patch's zone
  double load_share = 0.0;  //!< the reference patch's share of the wheel's normal force [-]
  SolveStatus candidate_status = SolveStatus::InvalidInput, reference_status = SolveStatus::InvalidInput;
  PatchShape shape;  //!< of the candidate's patch
  KneeErrors errors;
  AutoChoice choice;  //!< the candidate's (the least model's choice; for a fixed rung its method and width)
  double candidate_time_s = 0.0, reference_time_s = 0.0;
};

//! Runs the sweep; rows ordered by load, shift and patch.
[[nodiscard]] std::vector<KneeRow> run_knee_sweep(const KneeSweepOptions& options);

//! Candidate errors of one case: each reference patch against the candidate patch nearest to it.
[[nodiscard]] std::vector<KneeRow> compare_patches(const WheelContact& candidate, const WheelContact& reference);

//! CSV of the rows (header first; SI units).
[[nodiscard]] std::string knee_csv(const std::vector<KneeRow>& rows);

//! How well each indicator predicts a patch failing `targets` among rows of at least `min_load_share`: text, one
//! line per indicator (the threshold that flags every failing patch and the share of patches it flags, and the
//! false-negative rate at the threshold that flags 10 % of the patches).
[[nodiscard]] std::string knee_indicator_summary(const std::vector<KneeRow>& rows, const KneeTargets& targets,
                                                 double min_load_share);

}  // namespace ctab::gen
