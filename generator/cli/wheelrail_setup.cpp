#include "wheelrail_setup.hpp"

#include <cmath>

#include "ctab/contact/error.hpp"

namespace ctab::cli {

void add_wheelrail_options(CLI::App& app, WheelRailCliOptions& o) {
  app.add_option("--wheel", o.wheel, "wheel profile: S1002 (built in) or a file (.prw, .whl, 2-column y z in mm)");
  app.add_option("--rail", o.rail, "rail profile: UIC60 (built-in 60E1) or a file (.prr, .ban, 2-column y z in mm)");
  app.add_option("--inclination", o.inclination, "rail inclination: 1/40 (default), 1/30, 1/20 or 0 (already inclined)");
  app.add_option("--smoothing", o.smoothing_m, "smoothing length of point profiles [m] (default 1e-3; 0 interpolates)");
  app.add_option("--gauge", o.track.gauge_m, "track gauge [m] (default 1.435)");
  app.add_option("--flange-back-distance", o.track.flange_back_distance_m, "wheelset flange-back distance [m] (default 1.360)");
  app.add_option("--nominal-radius", o.track.nominal_radius_m, "nominal rolling radius [m] (default 0.460)");
}

WheelRailSetup build_wheelrail_setup(const WheelRailCliOptions& o) {
  for (const double* v : {&o.track.gauge_m, &o.track.flange_back_distance_m, &o.track.nominal_radius_m})
    if (!(std::isfinite(*v) && *v > 0.0)) throw gen::InputError("track", 0, "gauge, flange-back distance and radius must be positive");
  if (!(std::isfinite(o.smoothing_m) && o.smoothing_m >= 0.0)) throw gen::InputError("--smoothing", 0, "expected a length >= 0 in metres");
  gen::ProfileReadOptions read;
  read.smoothing_length_m = o.smoothing_m;
  read.inclination = gen::parse_inclination(o.inclination, "--inclination", 0, "");
  WheelRailSetup setup;
  setup.wheel = gen::load_profile(o.wheel, gen::ProfileRole::Wheel, read);
  setup.rail = gen::load_profile(o.rail, gen::ProfileRole::Rail, read);
  setup.right = std::make_unique<gen::SideGeometry>(setup.wheel, setup.rail, o.track);
  setup.left = std::make_unique<gen::SideGeometry>(setup.wheel, setup.rail, o.track);
  return setup;
}

}  // namespace ctab::cli
