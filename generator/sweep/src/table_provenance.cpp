// SPDX-License-Identifier: Apache-2.0
// Provenance attributes of a generated table (table_provenance.hpp).
#include "table_provenance.hpp"

#include <cstdlib>
#include <ctime>
#include <string>

#include "ctab/io/profile_io.hpp"
#include "ctab/io/sha256.hpp"

namespace ctab::gen::detail {

namespace {

std::string utc_now() {
  std::time_t now = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) now = static_cast<std::time_t>(std::atoll(epoch));
  char text[32];
  std::tm utc{};
  gmtime_r(&now, &utc);
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

// "<body>_smoothing_m", "<body>_smoothing_near_jumps_m", "<body>_noise_sigma_m" and with the arcs prior
// "<body>_arc_junctions" of a point profile (nothing for a built-in one).
void add_smoothing_provenance(tables::Table& table, const std::string& body, const ProfileSmoothing& smoothing) {
  if (!smoothing.point_data) return;
  table.number_attributes[body + "_smoothing_m"] = smoothing.length_m;
  table.number_attributes[body + "_smoothing_near_jumps_m"] = smoothing.jump_length_m;
  table.number_attributes[body + "_noise_sigma_m"] = smoothing.noise_sigma_m;
  if (smoothing.arc_junctions >= 0) table.number_attributes[body + "_arc_junctions"] = smoothing.arc_junctions;
}

}  // namespace

void add_provenance(tables::Table& table, const TableConfig& config, const SweepSetup& setup, const SweepPlan& plan,
                    const GeneratorInfo& info) {
  auto& text = table.text_attributes;
  text["generator"] = "ctab";
  text["generator_version"] = info.version;
  text["git_commit"] = info.git_commit;
  text["compiler"] = info.compiler;
  text["build_flags"] = info.build_flags;
  text["config"] = config.text;
  text["config_source"] = config.source;
  text["created_utc"] = utc_now();
  text["wheel_profile"] = config.wheel;
  text["rail_profile"] = config.rail;
  text["wheel_profile_sha256"] =
      sha256_hex(setup.wheel->z_samples().data(), setup.wheel->z_samples().size() * sizeof(double));
  text["rail_profile_sha256"] =
      sha256_hex(setup.rail->z_samples().data(), setup.rail->z_samples().size() * sizeof(double));
  text["rail_inclination"] = config.inclination_text;
  text["smoothing"] =
      config.wheel_smoothing == config.rail_smoothing
          ? smoothing_text(config.wheel_smoothing)
          : "wheel " + smoothing_text(config.wheel_smoothing) + ", rail " + smoothing_text(config.rail_smoothing);
  text["mode"] = config.mode == ContactMode::Wheelset ? "wheelset" : "wheel";
  text["method"] = config.least_model ? "auto" : method_name(config.method);  // per case: /wheels/method
  text["surface"] = std::string(surface_name(config.surface));
  text["reference_point"] = std::string(reference_point_name(config.reference));
  text["reference_angle"] = std::string(reference_angle_name(config.reference));
  text["mirrored"] = plan.mirrored ? "true" : "false";  // a boolean in the file (tables/README.md)
  text["units"] = "SI: m, N, Pa, rad";
  auto& number = table.number_attributes;
  number["youngs_modulus_Pa"] = config.material.youngs_modulus_Pa;
  number["poisson_ratio"] = config.material.poisson_ratio;
  number["strip_width_m"] = config.strip_width_m;  // per case: /wheels/strip_width_m
  if (config.least_model) number["tolerance"] = config.tolerance;
  number["gauge_m"] = config.track.gauge_m;
  number["nominal_radius_m"] = config.track.nominal_radius_m;
  add_smoothing_provenance(table, "wheel", setup.wheel_smoothing);
  add_smoothing_provenance(table, "rail", setup.rail_smoothing);
  table.integer_attributes["threads"] = plan.threads;
  table.integer_attributes[tables::kCompressionLevelAttribute] = static_cast<std::int64_t>(config.compression_level);
}

}  // namespace ctab::gen::detail
