// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Reading wheel and rail profiles: built-in names or point files, brought to the canonical form of
//! profile.hpp (SI; y towards the field side; z down; wheel: y = S from the tape circle, flange at y < 0).
//!
//! Formats (by extension):
//! - Simpack `.prw` / `.prr`: header and spline blocks; honours mirror.y, mirror.z, inversion, shift.y/z,
//!   bound.y/z, point.dist.min and units.len.f (user length units per metre); `rotate` must be 0.
//! - MiniProf `.whl` / `.ban`: `Key=Value` header up to the first empty line, `ColumnDef=X,Y[,...]`, comment
//!   lines starting with ! " % #; data rows starting with " are marked points (counted in XYPoints, not used).
//!   Units mm. `.whl`: X from the flange back, so S = X - 70 mm. `.ban`: mirrored in y by default (MiniProf's X
//!   runs the other way), z auto-detected.
//! - anything else: two columns `y z` (comma, semicolon or white space; one optional header line), units mm
//!   unless `length_unit_m` says otherwise.
//! Options may mirror y or z on top of the file's own settings; z (and a wheel's y) are auto-detected when
//! not given: a rail's ends lie below its top, a wheel's flange tip (largest z) at y < 0.
//! Point data are smoothed in arc length (smoothing_spline.hpp), by default noise-aware (choose_smoothing: the
//! cubic spline of 1 mm on clean data, the adaptive smoother of adaptive_smoothing.hpp with a length that grows
//! with the points' noise on noisy data; with the arcs prior for profiles drawn as circular arcs and straight lines),
//! or by the cubic spline of a given length. Rails are inclined by `inclination` (0 for a file already inclined) and re-origined at
//! the highest point of the head. A rail file whose head is already canted (rail_cant.hpp) by more than half the
//! inclination to be applied (at most 1/80) is an error: it would be inclined twice.
//! Errors (InputError) name the file, the line and what was expected: missing header block, non-numeric point,
//! fewer than 10 points, duplicate points, backward steps (loops), non-finite values, implausible total length
//! (units); MiniProf rows other than XYPoints declares or with other than ColumnDef's numbers; a last row cut
//! short (file ends without a newline inside a number written unlike the row before); Simpack profiles whose
//! size cannot be a wheel or rail (units.len.f, profile_plausibility.hpp). A UTF-8 byte-order mark is skipped;
//! text echoed in messages is cut at 60 characters (text_input.hpp).
#include <optional>
#include <string>
#include <vector>

#include "ctab/profiles/adaptive_smoothing.hpp"
#include "ctab/profiles/profile.hpp"

namespace ctab::gen {

enum class ProfileRole { Wheel, Rail };

//! How to smooth a point profile: `auto` (the length from the points' noise, smooth prior), `auto-arcs` (the same with
//! the arcs prior, adaptive_smoothing.hpp) or the cubic spline of a fixed length.
struct SmoothingSetting {
  bool automatic = true;                          //!< choose L from the points' noise (choose_smoothing)
  CurvaturePrior prior = CurvaturePrior::Smooth;  //!< the adaptive smoother's prior on noisy points when automatic
  double length_m = 1e-3;  //!< L of the cubic smoothing spline [m] when not automatic; 0 interpolates
  bool operator==(const SmoothingSetting&) const = default;
};

//! The words of a SmoothingSetting.
inline constexpr const char* kSmoothingAuto = "auto";
inline constexpr const char* kSmoothingAutoArcs = "auto-arcs";
//! "auto", "auto-arcs" or the length as "0.001 m" (provenance).
[[nodiscard]] std::string smoothing_text(const SmoothingSetting& setting);
//! The setting of "auto" or "auto-arcs"; empty for any other text (a length is parsed by the caller).
[[nodiscard]] std::optional<SmoothingSetting> automatic_smoothing(const std::string& text);

struct ProfileReadOptions {
  std::optional<bool> mirror_y;     //!< mirror y (on top of the file's setting); default per format/auto
  std::optional<bool> mirror_z;     //!< mirror z; default auto-detect
  double length_unit_m = 1e-3;      //!< unit of plain-text and MiniProf coordinates [m]
  SmoothingSetting smoothing;       //!< of point data
  double inclination = 1.0 / 40.0;  //!< rail inclination tan(angle) towards the track centre; 0: as given
};

//! Points of a profile file in canonical orientation, increasing y, SI.
struct ProfilePoints {
  std::vector<double> y_m, z_m;
  std::vector<std::size_t> line;  //!< source line of each point
};

[[nodiscard]] ProfilePoints read_profile_points(const std::string& path, ProfileRole role,
                                                const ProfileReadOptions& options);

//! Parses a rail inclination: a ratio such as "1/40" or a number in [0, 0.2). Throws InputError naming
//! `source`, `line` and `what` (the option or key) otherwise.
[[nodiscard]] double parse_inclination(const std::string& text, const std::string& source, std::size_t line,
                                       const std::string& what);

//! How a profile's points were smoothed (provenance): the length used and the noise estimated from the points
//! (point_noise.hpp), also when the length was given. Built-in profiles are analytic: point_data false.
struct ProfileSmoothing {
  bool point_data = false;     //!< the profile came from a file's points
  bool automatic = false;      //!< the length was chosen from the noise
  double length_m = 0.0;       //!< smoothing length L used [m] (on the running surfaces when automatic)
  double jump_length_m = 0.0;  //!< the shortest local length [m]: where the curvature jumps or changes fast the
                               //!< adaptive smoother's penalty gives way (smooth_point_profile); L otherwise
  double noise_sigma_m = 0.0;  //!< estimated noise normal to the profile [m]
  int arc_junctions = -1;      //!< junctions the arcs prior placed (auto-arcs on noisy points); -1 otherwise
};

//! A profile table from a built-in name (wheel: "S1002"; rail: "UIC60" or "60E1") or a file path.
[[nodiscard]] ProfileTable load_profile(const std::string& spec, ProfileRole role, const ProfileReadOptions& options);
//! The same, telling how the points were smoothed.
[[nodiscard]] ProfileTable load_profile(const std::string& spec, ProfileRole role, const ProfileReadOptions& options,
                                        ProfileSmoothing& smoothing);

}  // namespace ctab::gen
