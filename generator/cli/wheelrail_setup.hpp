#pragma once
// Command-line options shared by the wheel-rail subcommands (profiles, inclination, track) and the set-up they build.
#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "ctab/io/profile_io.hpp"
#include "ctab/wheelrail/wheelrail_geometry.hpp"

namespace ctab::cli {

struct WheelRailCliOptions {
  std::string wheel = "S1002";
  std::string rail = "UIC60";
  std::string inclination = "1/40";
  double smoothing_m = 1e-3;
  gen::TrackSetup track;
};

//! The profiles and both sides' geometry (left = mirror image of the right).
struct WheelRailSetup {
  gen::ProfileTable wheel, rail;
  std::unique_ptr<gen::SideGeometry> right, left;
};

void add_wheelrail_options(CLI::App& app, WheelRailCliOptions& options);
[[nodiscard]] WheelRailSetup build_wheelrail_setup(const WheelRailCliOptions& options);

}  // namespace ctab::cli
