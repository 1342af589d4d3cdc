// SPDX-License-Identifier: Apache-2.0
#include "creep_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ctab/core/error.hpp"
#include "setup_options.hpp"

namespace ctab::cli {

namespace {

int method_value(const std::string& name) {
  if (name == "carter") return CTAB_CREEP_STRIPS_CARTER;
  return name == "ellipse" ? CTAB_CREEP_FASTSIM_ELLIPSE : name == "linear" ? CTAB_CREEP_LINEAR : CTAB_CREEP_STRIPS;
}

}  // namespace

ctab_creep_input CreepOptions::input(const gen::ElasticMaterial& material) const {
  return {creepage.at(0), creepage.at(1), creepage.at(2), friction, material.youngs_modulus_Pa,
          material.poisson_ratio, method_value(method), 0};
}

void add_creep_options(CLI::App& app, CreepOptions& options) {
  app.add_option("--creepage", options.creepage,
                 "creep forces at creepages XI,ETA,PHI (longitudinal, lateral [-], spin [1/m]; CONTACT's signs, at the "
                 "patch's s origin; docs/creep.md)")
      ->delimiter(',')
      ->expected(3)
      ->check(finite_range(-1e3, 1e3, ""));
  app.add_option("--friction", options.friction, "Coulomb friction coefficient for --creepage")
      ->check(finite_positive("", 10.0));
  app.add_option("--creep-method", options.method,
                 "carter (default: strips on Carter's curve), strips (FASTSIM on the strips), ellipse (FASTSIM) or "
                 "linear (Kalker)")
      ->check(CLI::IsMember({"strips", "carter", "ellipse", "linear"}));
}

void check_creep_options(const CreepOptions& options) {
  if (options.wanted() != (options.friction > 0.0))
    throw gen::InputError("--creepage", 0, "give --creepage XI,ETA,PHI and --friction MU together");
}

nlohmann::json creep_json(const ctab_creep_patch& p) {
  return {{"fx_N", p.fx_N},
          {"fs_N", p.fs_N},
          {"mz_Nm", p.mz_Nm},
          {"force_lateral_N", p.force_lateral_N},
          {"force_vertical_N", p.force_vertical_N},
          {"normal_force_N", p.normal_force_N},
          {"slip_fraction", p.slip_fraction},
          {"status", ctab_status_message(p.status)}};
}

nlohmann::json solved_patch_creep(const gen::ContactPatch& patch, const ctab_creep_input& input) {
  const std::size_t n = std::min<std::size_t>(patch.strips.size(), lookup::kMaxCreepStrips);
  if (n < 2) return {{"status", "too few strips"}};
  // Evenly spaced samples over the strip centres, linear between them (the strips' own when they are even).
  std::vector<double> s(n), a(n), p0(n);
  const double first = patch.strips.front().s_m, last = patch.strips.back().s_m;
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    s[i] = first + (last - first) * static_cast<double>(i) / static_cast<double>(n - 1);
    while (k + 2 < patch.strips.size() && patch.strips[k + 1].s_m < s[i]) ++k;
    const gen::PatchStrip &lo = patch.strips[k], &hi = patch.strips[k + 1];
    const double t = hi.s_m > lo.s_m ? std::clamp((s[i] - lo.s_m) / (hi.s_m - lo.s_m), 0.0, 1.0) : 0.0;
    a[i] = (1 - t) * lo.half_length_m + t * hi.half_length_m;
    p0[i] = (1 - t) * lo.p0_Pa + t * hi.p0_Pa;
  }
  const lookup::StripPatch strips{s.data(), a.data(), p0.data(), static_cast<std::uint32_t>(n), patch.normal_force_N,
                                  patch.plane_angle_rad};
  ctab_creep_patch out;
  lookup::StripForces field;
  (void)lookup::creep_patch(strips, input, out, &field);
  nlohmann::json json = creep_json(out);
  if ((input.method == CTAB_CREEP_STRIPS || input.method == CTAB_CREEP_STRIPS_CARTER) && out.status >= 0)
    json["strips"] = {{"s_m", s},
                      {"fx_per_m", std::vector<double>(field.fx_per_m, field.fx_per_m + n)},
                      {"fs_per_m", std::vector<double>(field.fs_per_m, field.fs_per_m + n)},
                      {"slip_fraction", std::vector<double>(field.slip_fraction, field.slip_fraction + n)}};
  return json;
}

void print_creep(const char* indent, const nlohmann::json& c) {
  if (!c.contains("fx_N")) return;
  std::printf("%screep: Fx %.1f N, Fs %.1f N (side frame: lateral %.1f N, vertical %.1f N), Mz %.3f N m, slip %.1f %%"
              " (%s)\n",
              indent, c["fx_N"].get<double>(), c["fs_N"].get<double>(), c["force_lateral_N"].get<double>(),
              c["force_vertical_N"].get<double>(), c["mz_Nm"].get<double>(), 100.0 * c["slip_fraction"].get<double>(),
              c["status"].get<std::string>().c_str());
}

}  // namespace ctab::cli
