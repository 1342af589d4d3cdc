#pragma once
//! Configuration of a contact-table run (TOML). Every key is checked: unknown keys, wrong types, empty axes and
//! non-positive steps give an InputError naming the source, the line and the key. The embedded default
//! (kDefaultTableConfig, also examples/configs/default.toml) is S1002 on UIC60 1:40 with the Manchester set-up,
//! wheelset mode, dy from -12 to +12 mm in 0.1 mm steps, vertical wheel load 78.5 kN, MIM-1D at 0.2 mm strips.
#include <string>
#include <vector>

#include "ctab/wheelrail/contact_geometry_sweep.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/wheelrail/wheelrail_options.hpp"

namespace ctab::gen {

extern const char* const kDefaultTableConfig;

struct TableConfig {
  std::string source = "default";          //!< file name, for messages and provenance
  std::string text;                        //!< the full config text (provenance)
  std::string wheel = "S1002";             //!< built-in name or profile file
  std::string rail = "UIC60";
  std::string inclination_text = "1/40";
  double inclination = 1.0 / 40.0;         //!< rail inclination tan(angle); 0: the rail file is already inclined
  double smoothing_length_m = 1e-3;        //!< smoothing of point profiles [m]
  TrackSetup track;
  ElasticMaterial material = kSteel;       //!< both bodies
  ContactMode mode = ContactMode::Wheelset;
  NormalMethod method = NormalMethod::Mim1d;
  double strip_width_m = 0.2e-3;
  std::vector<double> lateral_displacement_m;  //!< uniform axis [m]
  LoadKind load_kind = LoadKind::VerticalForce;
  std::vector<double> load_values;         //!< second axis, or one fixed value [N or m]
  bool second_axis = false;                //!< true when the load or approach is an axis of the table
  std::size_t strip_samples = 32;          //!< points of the resampled strip profiles per patch
  std::size_t patch_slots = 3;             //!< patch slots per wheel in the table ([output] patch_slots, 1..16)
  std::size_t key_line(const std::string& key) const;  //!< source line of a key (0 if unknown)
  std::vector<std::pair<std::string, std::size_t>> key_lines;
};

//! Parses and validates a config text; `source` names it in errors. Throws InputError.
[[nodiscard]] TableConfig parse_table_config(const std::string& text, const std::string& source);
//! Reads a config file. Throws InputError.
[[nodiscard]] TableConfig read_table_config(const std::string& path);

//! Name of the second axis in the table ("vertical_load_N", "normal_load_N" or "approach_m").
[[nodiscard]] const char* load_axis_name(LoadKind kind) noexcept;

}  // namespace ctab::gen
