// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Configuration of a contact-table run (TOML). Every key is checked: unknown keys, wrong types, values outside
//! their range, a missing load, bad axes (make_uniform_axis, axis_range.hpp) and tables too large for memory
//! give an InputError `file:line: 'key': what was expected`. The embedded default
//! (kDefaultTableConfig, also examples/configs/default.toml) is S1002 on UIC60 1:40 with the Manchester set-up,
//! wheelset mode, dy from -12 to +12 mm in 0.1 mm steps, vertical wheel load 78.5 kN, MIM-1D at 0.2 mm strips.
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ctab/wheelrail/contact_geometry_sweep.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/io/profile_io.hpp"
#include "ctab/tables/table.hpp"
#include "ctab/wheelrail/wheelrail_geometry.hpp"
#include "ctab/wheelrail/wheelrail_options.hpp"

namespace ctab::gen {

extern const char* const kDefaultTableConfig;

//! Strip width range [m]. Below 10 um a wheel-rail patch window needs more strips than kMaxStripsPerPatch
//! (strip_grid.hpp) and one case takes seconds; above 5 mm a patch (10-20 mm wide) has too few strips.
inline constexpr double kMinStripWidth_m = 10e-6;
inline constexpr double kMaxStripWidth_m = 5e-3;
//! Largest smoothing length of point profiles [m] (chosen: 100x the default 1 mm catches "1" meant as mm).
inline constexpr double kMaxSmoothingLength_m = 0.1;
//! Most patch slots per wheel and case in the table ([output] patch_slots).
inline constexpr std::size_t kMaxPatchSlots = 16;
//! Most cases (lateral shifts x loads) per table. Chosen: at about 1 ms per wheel solve this is an hour on 1 core.
inline constexpr std::size_t kMaxTableCases = 2'000'000;
//! Largest table in memory [bytes] (table_memory_bytes): the one limit of every table reader and writer.
inline constexpr double kMaxTableBytes = tables::kMaxTableBytes;

//! A physically sensible range of one quantity that both a config and the CLI's options take (docs/cli.md
//! "Ranges"): one check per quantity, whichever way the value comes in.
struct QuantityRange {
  double low, high;         //!< low excluded, high included
  const char* expectation;  //!< for messages: what a value must be
  [[nodiscard]] constexpr bool contains(double value) const noexcept { return value > low && value <= high; }
};
//! A wheel's vertical or normal load [N]: 1e8 N is a thousand times the heaviest axle load in service.
inline constexpr QuantityRange kLoadRange_N{0.0, 1e8, "a load in (0, 1e8] N"};
//! A prescribed approach [m]: far beyond any elastic approach; larger values are typing errors.
inline constexpr QuantityRange kApproachRange_m{0.0, 10e-3, "an approach in (0, 0.01] m"};
//! Young's modulus [Pa]: from soft rubber (1e6) to beyond diamond (1.2e12).
inline constexpr QuantityRange kYoungsModulusRange_Pa{1e6, 1e13, "a Young's modulus in (1e6, 1e13] Pa"};

//! [axes] tolerance: the interpolation error the adaptive dy axis is refined to (docs/method.md "Error-controlled
//! axes"), per quantity, and the finest step smooth refinement may take. Present: lateral_displacement_m is the
//! coarse axis the generator starts from.
struct AxisTolerance {
  double force_rel = 0.005;          //!< patch normal force, relative (floor: kSmallPatchShare of the wheel's) [-]
  double area_rel = 0.005;           //!< patch area, relative (same floor) [-]
  double contact_point_m = 1e-5;     //!< contact point on wheel and rail, absolute [m]
  double lateral_force_rel = 0.005;  //!< total lateral force as a fraction of the wheel's normal load [-]
  //! Finest step of smooth refinement [m] (jumps are bracketed to tables::kJumpCellWidth_m regardless). Chosen:
  //! 10 um. Below it the error no longer falls with the step: the solver's own scatter (strips entering and leaving
  //! a patch, about 0.5 % in area where two patches share the load) dominates; on the default table 1 um costs 1.5x
  //! the solves (875 against 599) for cells whose error is that scatter.
  double min_step_m = 1e-5;
};
//! Allowed ranges of the tolerance keys (messages name them).
inline constexpr double kMaxRelativeTolerance = 0.5;
inline constexpr double kMaxContactPointTolerance_m = 1e-3;
inline constexpr double kMinAxisStep_m = 1e-7;  //!< as tables::kMinDyStep
inline constexpr double kMaxMinAxisStep_m = 1e-3;

struct TableConfig {
  std::string source = "default";  //!< file name, for messages and provenance
  std::string text;                //!< the full config text (provenance)
  std::string wheel = "S1002";     //!< built-in name or profile file
  std::string rail = "UIC60";
  std::string inclination_text = "1/40";
  double inclination = 1.0 / 40.0;  //!< rail inclination tan(angle); 0: the rail file is already inclined
  //! [profiles] smoothing_m for both, wheel_smoothing_m / rail_smoothing_m for one: "auto", "auto-arcs" or a length
  SmoothingSetting wheel_smoothing, rail_smoothing;
  TrackSetup track;
  ElasticMaterial material = kSteel;  //!< both bodies
  ContactMode mode = ContactMode::Wheelset;
  NormalMethod method = NormalMethod::Mim1d;
  double strip_width_m = 0.2e-3;
  //! [solver] method = "auto": the least model (least_model.hpp) picks the strip width per case; `method` is then
  //! Mim1d and strip_width_m unused. [solver] tolerance: its error tolerance (0 < T < 1, default 0.02) [-].
  bool least_model = false;
  double tolerance = 0.02;
  //! [solver] reference_point ("deepest", the default, or "interpenetration-centre", CONTACT's rule) and
  //! reference_angle ("interpenetration-mean", CONTACT's and the default, or "tangent"; CONTACT's point takes only
  //! CONTACT's angle): where a patch's contact plane lies and how it is inclined (WheelRailOptions::reference).
  ReferenceRule reference = ReferenceRule::DeepestContactsAngle;
  //! [solver] surface: "conformal" (the default) or "planar" (WheelRailOptions::surface).
  ContactSurface surface = ContactSurface::Conformal;
  //! [solver] warm_start: each MIM-1D solve starts from its neighbour in dy, in fixed chains of rows
  //! (table_generator.hpp, warm_start_previous_rows); entries then agree with cold starts within the solver
  //! tolerance instead of bit for bit, and stay bit-identical across threads, shards and MPI ranks.
  bool warm_start = false;
  //! dy axis [m]: uniform ({start, stop, step}), with the nodes of [axes] lateral_refinement_m's zones merged in
  std::vector<double> lateral_displacement_m;
  //! [axes] tolerance: the dy axis is decided by the generator from lateral_displacement_m (the coarse axis)
  std::optional<AxisTolerance> axis_tolerance;
  LoadKind load_kind = LoadKind::VerticalForce;
  std::vector<double> load_values;  //!< second axis, or one fixed value [N or m]
  bool second_axis = false;         //!< true when the load or approach is an axis of the table
  std::size_t strip_samples = 32;   //!< points of the resampled strip profiles per patch
  std::size_t patch_slots = 3;      //!< patch slots per wheel and case in the table ([output], 1..16)
  //! HDF5 deflate level of the table ([output] compression, 0 = none .. 9), written as the root attribute
  //! compression_level (tables::kCompressionLevelAttribute).
  std::size_t compression_level = static_cast<std::size_t>(tables::kDefaultCompressionLevel);
  std::size_t key_line(const std::string& key) const;  //!< source line of a key (0 if unknown)
  std::vector<std::pair<std::string, std::size_t>> key_lines;
};

//! Parses and validates a config text; `source` names it in errors. Throws InputError.
[[nodiscard]] TableConfig parse_table_config(const std::string& text, const std::string& source);
//! Reads a config file. Throws InputError.
[[nodiscard]] TableConfig read_table_config(const std::string& path);
//! A config that makes a table (generate, batch, config) needs at least 2 lateral shifts: the lookup interpolates
//! between two, and refuses a one-row table. (`solve --config` solves one case of any config.) Throws InputError
//! naming the file, line and key.
void require_table_axes(const TableConfig& config);

//! Memory of the table's datasets [bytes]: cases x 2 wheels x patch_slots x (20 scalars + 2 strip_samples) x 8.
[[nodiscard]] double table_memory_bytes(const TableConfig& config) noexcept;

//! Places the profiles on the config's track (SideGeometry); an error (e.g. a rail that does not reach the gauge
//! height) names the config file and the line of track.gauge_height_m (or of profiles.rail). Throws InputError.
[[nodiscard]] SideGeometry place_profiles(const TableConfig& config, const ProfileTable& wheel,
                                          const ProfileTable& rail);

//! Name of the second axis in the table ("vertical_load_N", "normal_load_N" or "approach_m").
[[nodiscard]] const char* load_axis_name(LoadKind kind) noexcept;

}  // namespace ctab::gen
